// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's tree measurement: how long vtkIceTriangleBVH (the trace's tree, built on the CPU
// whenever the ice's input changes) takes to build, and how much it uploads, by triangle count;
// the same for the cracks' grid (vtkIceCrackGrid, built when the cracks change), by crack count.
#include "IceBench.h"
#include "IceBenchScene.h"

#include "vtkIceCrackGrid.h"
#include "vtkIceCrackTable.h"
#include "vtkIceTriangleBVH.h"

#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <ostream>
#include <string>

namespace
{
// The fastest of three runs of `build`, in ms.
double Best(const std::function<void()>& build)
{
  double best = 0.0;
  for (int run = 0; run < 3; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    build();
    const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    best = run == 0 ? ms : std::min(best, ms);
  }
  return best;
}

void MeasureCrackGrids(std::ostream& out)
{
  using IceBench::Fixed;
  out << "\n== The cracks' grid (vtkIceCrackTable and vtkIceCrackGrid::Build, CPU; the best of 3;"
         " a box of side 2)\n"
      << "   cracks   build ms   cells          sheets a cell   MB uploaded\n";
  const double bounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  for (const int cracks : { 2, 32, 128, 512, 1000 })
  {
    vtkNew<vtkIceCrackTable> table;
    vtkNew<vtkIceCrackGrid> grid;
    const double ms = Best([&] {
      table->Build(1, cracks, bounds);
      grid->Build(table->GetSheets(), bounds);
    });
    const int* n = grid->GetDimensions();
    const std::string cells =
      std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]);
    out << "   " << cracks << std::string(9 - std::to_string(cracks).size(), ' ') << Fixed(ms, 1)
        << "   " << cells << std::string(15 - cells.size(), ' ')
        << Fixed(grid->GetMeanListLength(), 1) << "   "
        << Fixed(4.0 * static_cast<double>(grid->GetTexels().size()) / (1024.0 * 1024.0), 2)
        << "\n";
  }
}
}

void IceBench::MeasureTrees(std::ostream& out)
{
  out << "\n== The trace's tree (vtkIceTriangleBVH::Build, CPU; the best of 3 builds)\n"
      << "   object             triangles   build ms   ms per 1M   nodes   depth   MB uploaded\n";
  for (const char* object : { "cube", "teapot", "sphere-100k", "sphere-1M" })
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> surface = IceBench::MakeObject(object, error);
    if (!surface)
    {
      out << "   " << object << ": " << error << "\n";
      continue;
    }
    // The mapper's prepared input has point normals; so does this.
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(surface);
    normals->SplittingOff();
    normals->Update();
    vtkPolyData* prepared = normals->GetOutput();
    vtkNew<vtkIceTriangleBVH> tree;
    const double best =
      Best([&] { tree->Build(prepared, prepared->GetPointData()->GetNormals()); });
    const double triangles = static_cast<double>(tree->GetNumberOfTriangles());
    const double bytes =
      4.0 * static_cast<double>(tree->GetNodes().size() + tree->GetTriangles().size());
    out << "   " << object << std::string(19 - std::string(object).size(), ' ')
        << Fixed(triangles, 0) << "   " << Fixed(best, 1) << "   "
        << Fixed(triangles > 0.0 ? best * 1.0e6 / triangles : 0.0, 0) << "   "
        << tree->GetNumberOfNodes() << "   " << tree->GetDepth() << "   "
        << Fixed(bytes / (1024.0 * 1024.0), 1) << "\n";
  }
  MeasureCrackGrids(out);
}
