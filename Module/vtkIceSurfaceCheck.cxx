#include "vtkIceSurfaceCheck.h"

#include "vtkCellArray.h"
#include "vtkStaticCleanPolyData.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace vtkIceSurfaceCheck
{
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

vtkIdType CountOpenEdges(vtkPolyData* surface)
{
  vtkNew<vtkStaticCleanPolyData> merge;
  merge->SetInputData(surface);
  merge->ToleranceIsAbsoluteOff();
  merge->SetTolerance(1e-6);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  merge->Update();
  vtkPolyData* merged = merge->GetOutput();

  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  auto add = [&edges](vtkIdType a, vtkIdType b)
  {
    if (a != b)
    {
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  };
  vtkNew<vtkIdList> cell;
  vtkCellArray* polys = merged->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    const vtkIdType n = cell->GetNumberOfIds();
    for (vtkIdType i = 0; i < n; ++i)
    {
      add(cell->GetId(i), cell->GetId((i + 1) % n));
    }
  }
  vtkCellArray* strips = merged->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(cell);)
  {
    for (vtkIdType i = 0; i + 2 < cell->GetNumberOfIds(); ++i)
    {
      add(cell->GetId(i), cell->GetId(i + 1));
      add(cell->GetId(i + 1), cell->GetId(i + 2));
      add(cell->GetId(i), cell->GetId(i + 2));
    }
  }
  std::sort(edges.begin(), edges.end());
  vtkIdType open = 0;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    open += j - i == 1 ? 1 : 0;
    i = j;
  }
  return open;
}
}
