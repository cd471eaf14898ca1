// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCrackGrid
 * @brief   Which crack sheets each cell of a grid over the ice can hold, laid out for a shader
 *          (for the project's modules: not installed).
 *
 * A ray through the ice looks for its nearest crack. Testing every sheet costs each pixel as
 * many intersections as there are cracks, and the sheets are large (about the ice's size), so
 * culling them by screen tile leaves most of them. The grid splits the ice's box into cubic cells
 * and lists, per cell, the sheets that may pass through it; a ray visits the cells front to back
 * and stops after the first cell in which it found a crack nearer than the cell's far side. Dense
 * cracks are met early, so the ray tests the few sheets of its first cells.
 *
 * A sheet is z = a x^2 + b y^2 in its own frame, inside a radius (its outline's largest); a cell
 * lists it when interval arithmetic over the cell (mapped into the sheet's frame) cannot rule
 * that out: the lists hold every sheet that passes through a cell, and a few more.
 *
 * GetTexels() is what the shader reads (vtkIceInteriorFS.glsl): the first cell count + 1 texels
 * hold where each cell's list starts (the next one's start ends it), then the lists, as floats
 * (exact for the sizes Build allows).
 */
#ifndef vtkIceCrackGrid_h
#define vtkIceCrackGrid_h

#include "FiltersIceModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For the sheets and texels

class FILTERSICE_EXPORT vtkIceCrackGrid : public vtkObject
{
public:
  static vtkIceCrackGrid* New();
  vtkTypeMacro(vtkIceCrackGrid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr int MaximumCellsAcross = 32;

  // One sheet: model coordinates to its frame (three rows of a 3 x 4 matrix), the sheet's
  // z = Bowl[0] x^2 + Bowl[1] y^2 and the largest radius of its outline, in its frame.
  struct Sheet
  {
    double ModelToSheet[12];
    double Bowl[2];
    double Radius;
  };

  /**
   * The lists of `sheets` in the box `bounds` (model coordinates; widened a little, so that
   * points on the ice's surface lie inside). The cells across the box's longest side grow with
   * the number of sheets (CellsAcross).
   */
  void Build(const std::vector<Sheet>& sheets, const double bounds[6]);

  // Cells along the box's longest side for `sheets` sheets: 1 for a few, up to
  // MaximumCellsAcross.
  static int CellsAcross(int sheets);

  const std::vector<float>& GetTexels() const { return this->Texels; }
  const int* GetDimensions() const { return this->Dimensions; }
  const double* GetOrigin() const { return this->Origin; }
  double GetCellSize() const { return this->CellSize; }
  // The sheets listed in the cell that holds model point `p` (clamped to the grid).
  std::vector<int> GetSheetsAt(const double p[3]) const;
  // The mean length of a cell's list (0 for an empty grid).
  double GetMeanListLength() const;

protected:
  vtkIceCrackGrid() = default;
  ~vtkIceCrackGrid() override = default;

private:
  int Dimensions[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSize = 1.0;
  std::vector<float> Texels;

  vtkIceCrackGrid(const vtkIceCrackGrid&) = delete;
  void operator=(const vtkIceCrackGrid&) = delete;
};

#endif
