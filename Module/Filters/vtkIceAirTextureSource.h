// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceAirTextureSource
 * @brief   Procedural air-bubble images for the milky look of ice.
 *
 * Enclosed air makes ice milky (paper section 3.1). vtkIceMapper places textured planes inside
 * the ice; this source makes their texture: an RGBA atlas of 2 x 2 tiles, each a different mix of
 * bubble sizes and spatial frequencies (fine dense bubbles, small ones, a few large ones, and
 * clusters), over a faint cloudy haze. Bubbles are white, most opaque at their rim, with a small
 * highlight; alpha is 0 between bubbles except for the haze. Same Seed, same image.
 */
#ifndef vtkIceAirTextureSource_h
#define vtkIceAirTextureSource_h

#include "FiltersIceModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class FILTERSICE_EXPORT vtkIceAirTextureSource : public vtkImageAlgorithm
{
public:
  static vtkIceAirTextureSource* New();
  vtkTypeMacro(vtkIceAirTextureSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Width and height of the atlas in pixels (each tile is half). Default 512.
   */
  vtkSetClampMacro(Size, int, 16, 8192);
  vtkGetMacro(Size, int);
  ///@}

  ///@{
  /**
   * Seed of the bubble placement. Default 1.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

protected:
  vtkIceAirTextureSource();
  ~vtkIceAirTextureSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Size = 512;
  int Seed = 1;

private:
  vtkIceAirTextureSource(const vtkIceAirTextureSource&) = delete;
  void operator=(const vtkIceAirTextureSource&) = delete;
};

#endif
