// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The cracks' grid (vtkIceCrackGrid) on the CPU, one behaviour per case (--case NAME):
// - holds-every-crossing: random sheets (turned, stretched, bowled and saddled, some reaching
//   out of the box) in a box; every point of every sheet inside the box lies in a cell that lists
//   its sheet, so a ray walking the cells misses no crack.
// - culls: 128 sheets the size of the box, as the look places them: a cell lists far fewer than
//   128, and a few sheets make a single cell (their plain list).
#include "IceTestUtilities.h"
#include "vtkIceCrackGrid.h"

#include "vtkMatrix4x4.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using IceTest::Expect;

// `count` random sheets of radius `radius` (before their frame's stretch), their centres inside
// `bounds`; `placements` gets each sheet's frame to model coordinates.
std::vector<vtkIceCrackGrid::Sheet> RandomSheets(int count, const double bounds[6],
  double radius, std::vector<vtkSmartPointer<vtkTransform>>& placements)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(17);
  const auto next = [&](double low, double high) {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  std::vector<vtkIceCrackGrid::Sheet> sheets;
  for (int i = 0; i < count; ++i)
  {
    auto where = vtkSmartPointer<vtkTransform>::New();
    where->Translate(
      next(bounds[0], bounds[1]), next(bounds[2], bounds[3]), next(bounds[4], bounds[5]));
    where->RotateWXYZ(next(0.0, 360.0), next(-1.0, 1.0), next(-1.0, 1.0), next(-1.0, 1.0));
    where->Scale(next(0.6, 1.4), next(0.6, 1.4), next(0.6, 1.4));
    vtkNew<vtkMatrix4x4> toSheet;
    vtkMatrix4x4::Invert(where->GetMatrix(), toSheet);
    vtkIceCrackGrid::Sheet sheet;
    for (int row = 0; row < 3; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        sheet.ModelToSheet[4 * row + column] = toSheet->GetElement(row, column);
      }
    }
    sheet.Radius = radius;
    sheet.Bowl[0] = next(-0.6, 0.6) / sheet.Radius;
    sheet.Bowl[1] = next(-0.6, 0.6) / sheet.Radius;
    sheets.push_back(sheet);
    placements.push_back(where);
  }
  return sheets;
}

bool HoldsEveryCrossing()
{
  const double bounds[6] = { -0.7, 0.5, -0.2, 0.3, 1.0, 1.9 };
  bool ok = true;
  for (const int count : { 3, 8, 40, 128 })
  {
    std::vector<vtkSmartPointer<vtkTransform>> placements;
    const std::vector<vtkIceCrackGrid::Sheet> sheets =
      RandomSheets(count, bounds, 0.4, placements);
    vtkNew<vtkIceCrackGrid> grid;
    grid->Build(sheets, bounds);
    long long points = 0;
    long long missing = 0;
    for (int s = 0; s < count; ++s)
    {
      const vtkIceCrackGrid::Sheet& sheet = sheets[s];
      // A polar lattice over the sheet, finer than a hundredth of the box.
      for (int ring = 0; ring <= 120; ++ring)
      {
        const double r = sheet.Radius * ring / 120.0;
        const int around = std::max(1, 8 * ring);
        for (int a = 0; a < around; ++a)
        {
          const double angle = 2.0 * 3.14159265358979 * a / around;
          const double x = r * std::cos(angle);
          const double y = r * std::sin(angle);
          const double local[3] = { x, y, sheet.Bowl[0] * x * x + sheet.Bowl[1] * y * y };
          double p[3];
          placements[s]->TransformPoint(local, p);
          if (p[0] < bounds[0] || p[0] > bounds[1] || p[1] < bounds[2] || p[1] > bounds[3] ||
            p[2] < bounds[4] || p[2] > bounds[5])
          {
            continue;
          }
          ++points;
          const std::vector<int> listed = grid->GetSheetsAt(p);
          missing += std::find(listed.begin(), listed.end(), s) == listed.end() ? 1 : 0;
        }
      }
    }
    const int* n = grid->GetDimensions();
    ok = Expect(points > 1000 * count && missing == 0,
           std::to_string(count) + " sheets in " + std::to_string(n[0]) + " x " +
             std::to_string(n[1]) + " x " + std::to_string(n[2]) + " cells: " +
             std::to_string(missing) + " of " + std::to_string(points) +
             " points on the sheets lie in a cell that does not list their sheet") &&
      ok;
  }
  return ok;
}

bool Culls()
{
  // As the look places cracks: centres near the middle, half-sizes about 0.6 of the longest side.
  const double bounds[6] = { -1.0, 1.0, -0.8, 0.8, -0.6, 0.6 };
  const double middle[6] = { -0.3, 0.3, -0.25, 0.25, -0.2, 0.2 };
  std::vector<vtkSmartPointer<vtkTransform>> placements;
  vtkNew<vtkIceCrackGrid> grid;
  grid->Build(RandomSheets(128, middle, 1.2, placements), bounds);
  const double mean = grid->GetMeanListLength();
  bool ok = Expect(mean < 128.0 / 6.0,
    "128 sheets the size of the box: " + std::to_string(mean) + " listed in a cell on average");
  placements.clear();
  grid->Build(RandomSheets(2, middle, 1.2, placements), bounds);
  const int* n = grid->GetDimensions();
  ok = Expect(n[0] * n[1] * n[2] == 1 && grid->GetMeanListLength() == 2.0,
         "2 sheets: one cell listing both") &&
    ok;
  return ok;
}
}

int TestIceCrackGrid(int argc, char* argv[])
{
  const IceTest::Cases cases = {
    { "holds-every-crossing", HoldsEveryCrossing },
    { "culls", Culls },
  };
  return IceTest::RunCases("TestIceCrackGrid", argc, argv, cases);
}
