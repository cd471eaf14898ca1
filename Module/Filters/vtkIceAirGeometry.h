// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceAirGeometry
 * @brief   The air-bubble planes inside an ice surface (for the project's modules: not installed).
 *
 * Input: the ice surface. Output: NumberOfPlanes squares at random orientations in the middle of
 * the input's bounds (half-sizes 0.2 to 0.4 of its largest extent, placement picked by Seed),
 * each with the texture coordinates "vtkIceAirUV" of one tile of the 2 x 2 bubble atlas and its
 * normal. A pipeline filter: the planes are placed again only when the input or a parameter
 * changes (vtkIceBackToFront orders them for the camera).
 */
#ifndef vtkIceAirGeometry_h
#define vtkIceAirGeometry_h

#include "FiltersIceModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkTransform;

class FILTERSICE_EXPORT vtkIceAirGeometry : public vtkPolyDataAlgorithm
{
public:
  static vtkIceAirGeometry* New();
  vtkTypeMacro(vtkIceAirGeometry, vtkPolyDataAlgorithm);

  vtkSetClampMacro(NumberOfPlanes, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfPlanes, int);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  // The bounds the placement is scaled to; uninitialized (the default): the input's bounds.
  vtkSetVector6Macro(PlacementBounds, double);
  vtkGetVector6Macro(PlacementBounds, double);

  // Plane `index` of `seed` in ice of `bounds`: the placement of the square [-1, 1]^2 (z = 0)
  // and the lower left corner of its atlas tile; a point (x, y) of the square shows the atlas at
  // tile + TileInset + TileScale (x + 1, y + 1).
  static void Placement(int seed, int index, const double bounds[6], vtkTransform* placement);
  static void Tile(int index, double tile[2]);
  static constexpr double TileInset = 0.01;
  static constexpr double TileScale = 0.24;

protected:
  vtkIceAirGeometry() = default;
  ~vtkIceAirGeometry() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfPlanes = 0;
  int Seed = 1;
  double PlacementBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };

private:
  vtkIceAirGeometry(const vtkIceAirGeometry&) = delete;
  void operator=(const vtkIceAirGeometry&) = delete;
};

#endif
