// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCrackGrid.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkIceCrackGrid);

namespace
{
struct Interval
{
  double Low;
  double High;
};

Interval Square(const Interval& x)
{
  const double a = x.Low * x.Low;
  const double b = x.High * x.High;
  if (x.Low <= 0.0 && x.High >= 0.0)
  {
    return { 0.0, std::max(a, b) };
  }
  return { std::min(a, b), std::max(a, b) };
}

Interval Scaled(double factor, const Interval& x)
{
  return factor >= 0.0 ? Interval{ factor * x.Low, factor * x.High }
                       : Interval{ factor * x.High, factor * x.Low };
}

// Whether the sheet may pass through the box of centre `centre` and half-sizes `half` (model
// coordinates): the box's range in the sheet's frame, then z - a x^2 - b y^2 over it.
bool MayCross(const vtkIceCrackGrid::Sheet& sheet, const double centre[3], const double half[3])
{
  Interval local[3];
  for (int row = 0; row < 3; ++row)
  {
    const double* m = sheet.ModelToSheet + 4 * row;
    const double c = m[0] * centre[0] + m[1] * centre[1] + m[2] * centre[2] + m[3];
    const double h =
      std::abs(m[0]) * half[0] + std::abs(m[1]) * half[1] + std::abs(m[2]) * half[2];
    local[row] = { c - h, c + h };
  }
  const Interval x2 = Square(local[0]);
  const Interval y2 = Square(local[1]);
  const Interval a = Scaled(sheet.Bowl[0], x2);
  const Interval b = Scaled(sheet.Bowl[1], y2);
  const double lowest = local[2].Low - a.High - b.High;
  const double highest = local[2].High - a.Low - b.Low;
  return lowest <= 0.0 && highest >= 0.0 && x2.Low + y2.Low <= sheet.Radius * sheet.Radius;
}

// The sheet's box (inside its radius, between its lowest and highest z) in model coordinates.
void SheetBounds(const vtkIceCrackGrid::Sheet& sheet, double bounds[6])
{
  vtkNew<vtkMatrix4x4> toModel;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      toModel->SetElement(row, column, sheet.ModelToSheet[4 * row + column]);
    }
  }
  toModel->Invert();
  const double r = sheet.Radius;
  const double a = sheet.Bowl[0] * r * r;
  const double b = sheet.Bowl[1] * r * r;
  const double z[2] = { std::min(0.0, a) + std::min(0.0, b), std::max(0.0, a) + std::max(0.0, b) };
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] = VTK_DOUBLE_MAX;
    bounds[2 * c + 1] = -VTK_DOUBLE_MAX;
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    double p[4] = { corner & 1 ? r : -r, corner & 2 ? r : -r, z[(corner >> 2) & 1], 1.0 };
    toModel->MultiplyPoint(p, p);
    for (int c = 0; c < 3; ++c)
    {
      bounds[2 * c] = std::min(bounds[2 * c], p[c]);
      bounds[2 * c + 1] = std::max(bounds[2 * c + 1], p[c]);
    }
  }
}
}

//------------------------------------------------------------------------------
int vtkIceCrackGrid::CellsAcross(int sheets)
{
  // A few sheets: one cell, the plain list (walking cells costs more than it saves). More: the
  // cells shrink as the sheets come closer together: 7 cube roots of the count measured best of
  // 3, 4, 5 and 7 (the teapot's 128 cracks in ice-bench, llvmpipe: +56 %, +54 %, +44 % over 2
  // for 3-5; 7, which the cap makes 32 cells, about 4 ms of 30 less than 5).
  if (sheets <= 4)
  {
    return 1;
  }
  const int across = static_cast<int>(std::lround(7.0 * std::cbrt(static_cast<double>(sheets))));
  return std::max(1, std::min(MaximumCellsAcross, across));
}

//------------------------------------------------------------------------------
void vtkIceCrackGrid::Build(const std::vector<Sheet>& sheets, const double bounds[6])
{
  double side[3];
  double longest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    side[c] = std::max(0.0, bounds[2 * c + 1] - bounds[2 * c]);
    longest = std::max(longest, side[c]);
  }
  // Widened by 1 % of the longest side (at least a little): the surface's points, computed in
  // floats from the depth buffer, lie inside.
  const double margin = std::max(0.01 * longest, 1.0e-6);
  const int across = CellsAcross(static_cast<int>(sheets.size()));
  this->CellSize = (longest + 2.0 * margin) / across;
  for (int c = 0; c < 3; ++c)
  {
    this->Origin[c] = bounds[2 * c] - margin;
    this->Dimensions[c] = std::max(1,
      std::min(across, static_cast<int>(std::ceil((side[c] + 2.0 * margin) / this->CellSize))));
  }
  const int nx = this->Dimensions[0];
  const int ny = this->Dimensions[1];
  const size_t cells = static_cast<size_t>(nx) * ny * this->Dimensions[2];

  std::vector<std::vector<int>> lists(cells);
  // Half a cell, a little more: the shader's float arithmetic stays inside.
  const double h = 0.5 * this->CellSize * (1.0 + 1.0e-3);
  const double half[3] = { h, h, h };
  for (size_t s = 0; s < sheets.size(); ++s)
  {
    double box[6];
    SheetBounds(sheets[s], box);
    int range[6];
    for (int c = 0; c < 3; ++c)
    {
      const auto cell = [&](double x) {
        const double u = std::floor((x - this->Origin[c]) / this->CellSize);
        return static_cast<int>(std::max(0.0, std::min(this->Dimensions[c] - 1.0, u)));
      };
      range[2 * c] = cell(box[2 * c]);
      range[2 * c + 1] = cell(box[2 * c + 1]);
    }
    for (int k = range[4]; k <= range[5]; ++k)
    {
      for (int j = range[2]; j <= range[3]; ++j)
      {
        for (int i = range[0]; i <= range[1]; ++i)
        {
          const double centre[3] = { this->Origin[0] + (i + 0.5) * this->CellSize,
            this->Origin[1] + (j + 0.5) * this->CellSize,
            this->Origin[2] + (k + 0.5) * this->CellSize };
          if (MayCross(sheets[s], centre, half))
          {
            lists[(static_cast<size_t>(k) * ny + j) * nx + i].push_back(static_cast<int>(s));
          }
        }
      }
    }
  }

  this->Texels.assign(cells + 1, 0.0f);
  size_t at = cells + 1;
  for (size_t cell = 0; cell < cells; ++cell)
  {
    this->Texels[cell] = static_cast<float>(at);
    at += lists[cell].size();
  }
  this->Texels[cells] = static_cast<float>(at);
  for (const std::vector<int>& list : lists)
  {
    this->Texels.insert(this->Texels.end(), list.begin(), list.end());
  }
}

//------------------------------------------------------------------------------
std::vector<int> vtkIceCrackGrid::GetSheetsAt(const double p[3]) const
{
  if (this->Texels.empty())
  {
    return {};
  }
  int cell[3];
  for (int c = 0; c < 3; ++c)
  {
    const double u = std::floor((p[c] - this->Origin[c]) / this->CellSize);
    cell[c] = static_cast<int>(std::max(0.0, std::min(this->Dimensions[c] - 1.0, u)));
  }
  const size_t index =
    (static_cast<size_t>(cell[2]) * this->Dimensions[1] + cell[1]) * this->Dimensions[0] + cell[0];
  std::vector<int> sheets;
  for (auto i = static_cast<size_t>(this->Texels[index]);
       i < static_cast<size_t>(this->Texels[index + 1]); ++i)
  {
    sheets.push_back(static_cast<int>(this->Texels[i]));
  }
  return sheets;
}

//------------------------------------------------------------------------------
double vtkIceCrackGrid::GetMeanListLength() const
{
  const size_t cells =
    static_cast<size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (this->Texels.empty() || cells == 0)
  {
    return 0.0;
  }
  return static_cast<double>(this->Texels.size() - cells - 1) / static_cast<double>(cells);
}

//------------------------------------------------------------------------------
void vtkIceCrackGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " x " << this->Dimensions[1] << " x "
     << this->Dimensions[2] << "\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
  os << indent << "MeanListLength: " << this->GetMeanListLength() << "\n";
}
