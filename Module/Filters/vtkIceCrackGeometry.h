// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCrackGeometry
 * @brief   The crack surfaces inside an ice surface (for the project's modules: not installed).
 *
 * Input: the ice surface. Output: NumberOfCracks instances of three generic crack models
 * (vtkIceCrackSource, models picked by Seed), randomly rotated, near the centre of the input's
 * bounds and scaled to them. With ClipToSurface on, the sheets are cut where they leave the
 * surface (which must be closed). A pipeline filter: it runs again only when the input or a
 * parameter changes.
 */
#ifndef vtkIceCrackGeometry_h
#define vtkIceCrackGeometry_h

#include "FiltersIceModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkTransform;

class FILTERSICE_EXPORT vtkIceCrackGeometry : public vtkPolyDataAlgorithm
{
public:
  static vtkIceCrackGeometry* New();
  vtkTypeMacro(vtkIceCrackGeometry, vtkPolyDataAlgorithm);

  vtkSetClampMacro(NumberOfCracks, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfCracks, int);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  vtkSetMacro(ClipToSurface, bool);
  vtkGetMacro(ClipToSurface, bool);
  // The bounds the placement is scaled to; uninitialized (the default): the input's bounds.
  vtkSetVector6Macro(PlacementBounds, double);
  vtkGetVector6Macro(PlacementBounds, double);

  // Crack `index` of `seed` in ice of `bounds`: its model's seed (vtkIceCrackSource) and the
  // placement of that model.
  static int ModelSeed(int seed, int index);
  static void Placement(int seed, int index, const double bounds[6], vtkTransform* placement);

protected:
  vtkIceCrackGeometry() = default;
  ~vtkIceCrackGeometry() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfCracks = 0;
  int Seed = 1;
  double PlacementBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  bool ClipToSurface = false;

private:
  vtkIceCrackGeometry(const vtkIceCrackGeometry&) = delete;
  void operator=(const vtkIceCrackGeometry&) = delete;
};

#endif
