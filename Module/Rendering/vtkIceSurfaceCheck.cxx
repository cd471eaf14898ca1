// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceSurfaceCheck.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCleanPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
bool HasOnlyFinitePoints(vtkPoints* points)
{
  vtkDataArray* data = points->GetData();
  const vtkIdType n = data->GetNumberOfTuples();
  const int components = data->GetNumberOfComponents();
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < components; ++k)
    {
      if (!std::isfinite(data->GetComponent(i, k)))
      {
        return false;
      }
    }
  }
  return true;
}

// Checks one cell array of `input` ("polygon", "strip", ...): offsets that start at 0, never
// decrease and end at the connectivity's size, cells of at least `minimum` points, point ids
// within [0, points). Returns "" or the first problem.
std::string FindCellProblem(
  vtkCellArray* cells, const char* kind, vtkIdType minimum, vtkIdType points)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return std::string();
  }
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  const vtkIdType numberOfCells = offsets->GetNumberOfValues() - 1;
  const vtkIdType size = connectivity->GetNumberOfValues();
  std::ostringstream problem;
  vtkIdType previous = static_cast<vtkIdType>(offsets->GetComponent(0, 0));
  if (previous != 0)
  {
    problem << "its " << kind << " offsets do not start at 0";
    return problem.str();
  }
  for (vtkIdType cell = 0; cell < numberOfCells; ++cell)
  {
    const vtkIdType next = static_cast<vtkIdType>(offsets->GetComponent(cell + 1, 0));
    if (next < previous || next > size)
    {
      problem << "its " << kind << " offsets are inconsistent at " << kind << " " << cell;
      return problem.str();
    }
    if (next - previous < minimum)
    {
      problem << kind << " " << cell << " has " << next - previous << " point"
              << (next - previous == 1 ? "" : "s") << " (at least " << minimum << " needed)";
      return problem.str();
    }
    for (vtkIdType i = previous; i < next; ++i)
    {
      const double id = connectivity->GetComponent(i, 0);
      if (id < 0 || id >= points)
      {
        problem << kind << " " << cell << " uses point " << static_cast<long long>(id)
                << ", which does not exist (" << points << " points)";
        return problem.str();
      }
    }
    previous = next;
  }
  if (previous != size)
  {
    problem << "its " << kind << " offsets end before the connectivity does";
    return problem.str();
  }
  return std::string();
}
}

namespace vtkIceSurfaceCheck
{
std::string FindInputProblem(vtkPolyData* input)
{
  if (!input)
  {
    return "No input.";
  }
  std::ostringstream problem;
  const vtkIdType points = input->GetNumberOfPoints();
  const vtkIdType surfaces = input->GetNumberOfPolys() + input->GetNumberOfStrips();
  if (points == 0 || surfaces == 0)
  {
    problem << "Input has no polygons to render as ice (" << points << " points, "
            << input->GetNumberOfLines() << " lines, " << input->GetNumberOfVerts()
            << " vertices); it is not drawn.";
    return problem.str();
  }
  if (!HasOnlyFinitePoints(input->GetPoints()))
  {
    return "Input has NaN or infinite point coordinates; it is not drawn as ice.";
  }
  struct
  {
    vtkCellArray* Cells;
    const char* Kind;
    vtkIdType Minimum;
  } const kinds[] = { { input->GetPolys(), "polygon", 3 }, { input->GetStrips(), "strip", 3 },
    { input->GetLines(), "line", 2 }, { input->GetVerts(), "vertex cell", 1 } };
  for (const auto& kind : kinds)
  {
    const std::string cellProblem = FindCellProblem(kind.Cells, kind.Kind, kind.Minimum, points);
    if (!cellProblem.empty())
    {
      return "Input is broken: " + cellProblem + "; it is not drawn as ice.";
    }
  }
  vtkPointData* pointData = input->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    if (array && array->GetNumberOfTuples() < points)
    {
      problem << "Input is broken: its point array '"
              << (array->GetName() ? array->GetName() : "(unnamed)") << "' has "
              << array->GetNumberOfTuples() << " values for " << points
              << " points; it is not drawn as ice (remove that array, or give it a value for "
                 "every point).";
      return problem.str();
    }
  }
  double bounds[6];
  input->GetPoints()->GetBounds(bounds);
  if (bounds[0] == bounds[1] && bounds[2] == bounds[3] && bounds[4] == bounds[5])
  {
    problem << "Input has no extent: all its " << points << " points are at (" << bounds[0] << ", "
            << bounds[2] << ", " << bounds[4] << "); it is not drawn.";
    return problem.str();
  }
  return std::string();
}

void Extents(vtkPoints* points, double& thickness, double& size)
{
  thickness = 0.0;
  size = 0.0;
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (n == 0)
  {
    return;
  }
  double mean[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      mean[k] += p[k] / n;
    }
  }
  double covariance[3][3] = { { 0.0 } };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        covariance[r][c] += (p[r] - mean[r]) * (p[c] - mean[c]);
      }
    }
  }
  double* rows[3] = { covariance[0], covariance[1], covariance[2] };
  double values[3];
  double vectors[3][3];
  double* vectorRows[3] = { vectors[0], vectors[1], vectors[2] };
  // Eigenvalues in decreasing order; eigenvectors in the columns.
  vtkMath::Jacobi(rows, values, vectorRows);
  double range[2][2] = { { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX }, { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX } };
  const int axes[2] = { 2, 0 }; // least and most variance
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int a = 0; a < 2; ++a)
    {
      double d = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        d += (p[k] - mean[k]) * vectors[k][axes[a]];
      }
      range[a][0] = std::min(range[a][0], d);
      range[a][1] = std::max(range[a][1], d);
    }
  }
  thickness = range[0][1] - range[0][0];
  size = range[1][1] - range[1][0];
}

bool IsFlat(double thickness, double size)
{
  return thickness <= 1e-5 * size;
}

namespace
{
Closure CheckClosureOf(vtkPolyData* merged)
{
  vtkPoints* points = merged->GetPoints();
  const vtkIdType numberOfPoints = merged->GetNumberOfPoints();

  // Every triangle (polygons as fans, strips with their alternating order) with its directed
  // edges; the components of the surface by union-find over its points.
  struct Edge
  {
    vtkIdType Low, High;
    bool Forward;
    bool operator<(const Edge& other) const
    {
      return Low != other.Low ? Low < other.Low : High < other.High;
    }
  };
  std::vector<Edge> edges;
  std::vector<vtkIdType> parent(static_cast<size_t>(numberOfPoints));
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    parent[i] = i;
  }
  auto root = [&parent](vtkIdType i) {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  auto addEdge = [&](vtkIdType a, vtkIdType b) {
    if (a != b)
    {
      edges.push_back({ std::min(a, b), std::max(a, b), a < b });
      parent[root(a)] = root(b);
    }
  };
  std::vector<std::array<vtkIdType, 3>> triangles;
  const size_t cells =
    static_cast<size_t>(merged->GetNumberOfPolys() + merged->GetNumberOfStrips());
  edges.reserve(3 * cells);
  triangles.reserve(cells);
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto polys = vtk::TakeSmartPointer(merged->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(n, ids);
    for (vtkIdType i = 0; i < n; ++i)
    {
      addEdge(ids[i], ids[(i + 1) % n]);
    }
    for (vtkIdType i = 1; i + 1 < n; ++i)
    {
      triangles.push_back({ ids[0], ids[i], ids[i + 1] });
    }
  }
  auto strips = vtk::TakeSmartPointer(merged->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(n, ids);
    for (vtkIdType i = 0; i + 2 < n; ++i)
    {
      const bool even = i % 2 == 0;
      const std::array<vtkIdType, 3> t = { ids[even ? i : i + 1], ids[even ? i + 1 : i],
        ids[i + 2] };
      addEdge(t[0], t[1]);
      addEdge(t[1], t[2]);
      addEdge(t[2], t[0]);
      triangles.push_back(t);
    }
  }

  // The edges grouped by their lower point (a counting sort: linear, where sorting all of them
  // took most of a second for a million triangles), each group, a few edges, sorted on its own.
  std::vector<size_t> start(static_cast<size_t>(numberOfPoints) + 1, 0);
  for (const Edge& edge : edges)
  {
    ++start[static_cast<size_t>(edge.Low) + 1];
  }
  for (size_t i = 1; i < start.size(); ++i)
  {
    start[i] += start[i - 1];
  }
  std::vector<Edge> grouped(edges.size());
  {
    std::vector<size_t> next(start.begin(), start.end() - 1);
    for (const Edge& edge : edges)
    {
      grouped[next[static_cast<size_t>(edge.Low)]++] = edge;
    }
  }
  Closure closure;
  for (size_t p = 0; p + 1 < start.size(); ++p)
  {
    const auto first = grouped.begin() + static_cast<std::ptrdiff_t>(start[p]);
    const auto last = grouped.begin() + static_cast<std::ptrdiff_t>(start[p + 1]);
    std::sort(first, last);
    for (auto i = first; i != last;)
    {
      auto j = i;
      while (j != last && j->High == i->High)
      {
        ++j;
      }
      // Two faces meeting at an edge are oriented alike when they run along it in opposite
      // directions; more than two faces at one edge have no consistent sides.
      const auto uses = j - i;
      closure.OpenEdges += uses == 1 ? 1 : 0;
      closure.MisorientedEdges += uses > 2 || (uses == 2 && i->Forward == (i + 1)->Forward) ? 1 : 0;
      i = j;
    }
  }

  // Signed volume per component (divergence theorem, about the bounds' centre for precision):
  // positive where the faces' order (counter-clockwise seen from outside) points outward.
  double centre[3] = { 0.0, 0.0, 0.0 };
  if (numberOfPoints > 0)
  {
    double bounds[6];
    points->GetBounds(bounds);
    for (int c = 0; c < 3; ++c)
    {
      centre[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
    }
  }
  std::vector<double> volume(static_cast<size_t>(numberOfPoints), 0.0);
  for (const std::array<vtkIdType, 3>& t : triangles)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(t[k], p[k]);
      vtkMath::Subtract(p[k], centre, p[k]);
    }
    double cross[3];
    vtkMath::Cross(p[1], p[2], cross);
    volume[root(t[0])] += vtkMath::Dot(p[0], cross) / 6.0;
  }
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    closure.InwardComponents += root(i) == i && volume[i] < 0.0 ? 1 : 0;
    closure.OutwardComponents += root(i) == i && volume[i] > 0.0 ? 1 : 0;
  }
  return closure;
}
}

Closure CheckClosure(vtkPolyData* surface)
{
  // Most closed surfaces share their points already: merging (the larger part of the cost) is
  // needed only for seams of duplicated points.
  const Closure given = CheckClosureOf(surface);
  if (given.IsClosedOutward())
  {
    return given;
  }
  vtkNew<vtkStaticCleanPolyData> merge;
  merge->SetInputData(surface);
  merge->ToleranceIsAbsoluteOff();
  merge->SetTolerance(1e-6);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  merge->Update();
  return CheckClosureOf(merge->GetOutput());
}

vtkIdType CountOpenEdges(vtkPolyData* surface)
{
  return CheckClosure(surface).OpenEdges;
}
}
