// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceTeapotSource
 * @brief   Newell (Utah) teapot tessellated from its 32 bicubic Bezier patches.
 *
 * vtkIceTeapotSource evaluates the classic public-domain teapot patches
 * (rim, body, handle, spout, lid and bottom) on a Resolution x Resolution
 * grid each and outputs triangles. Points shared along patch seams are
 * merged, triangles collapsed at the lid and bottom poles are dropped and
 * every patch is wound so that its triangles face outward. Smooth point
 * normals are stored in the "Normals" array.
 *
 * The teapot is rotated so that +Y is up (the spout points to +X), centred
 * at the origin and scaled so that its largest bounding box extent is 2.
 * The default Resolution of 15 gives 14 280 triangles.
 */

#ifndef vtkIceTeapotSource_h
#define vtkIceTeapotSource_h

#include "FiltersIceModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FILTERSICE_EXPORT vtkIceTeapotSource : public vtkPolyDataAlgorithm
{
public:
  static vtkIceTeapotSource* New();
  vtkTypeMacro(vtkIceTeapotSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of subdivisions along each edge of every Bezier patch.
   * Default is 15; clamped to [1, 256].
   */
  vtkSetClampMacro(Resolution, int, 1, 256);
  vtkGetMacro(Resolution, int);
  ///@}

protected:
  vtkIceTeapotSource();
  ~vtkIceTeapotSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution;

private:
  vtkIceTeapotSource(const vtkIceTeapotSource&) = delete;
  void operator=(const vtkIceTeapotSource&) = delete;
};

#endif
