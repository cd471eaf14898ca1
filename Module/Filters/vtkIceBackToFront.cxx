// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceBackToFront.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkIceBackToFront);

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkIceBackToFront::Order(
  const std::vector<double>& centers, const double eye[3])
{
  const size_t n = centers.size() / 3;
  std::vector<double> distance(n);
  for (size_t i = 0; i < n; ++i)
  {
    distance[i] = vtkMath::Distance2BetweenPoints(&centers[3 * i], eye);
  }
  std::vector<vtkIdType> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&distance](vtkIdType a, vtkIdType b) { return distance[a] > distance[b]; });
  return order;
}

//------------------------------------------------------------------------------
int vtkIceBackToFront::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input)
  {
    return 1;
  }
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType n = polys->GetNumberOfCells();
  std::vector<double> centroids(3 * static_cast<size_t>(n), 0.0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const double* p = input->GetPoint(ids->GetId(k));
      for (int i = 0; i < 3; ++i)
      {
        centroids[3 * c + i] += p[i] / ids->GetNumberOfIds();
      }
    }
  }
  const std::vector<vtkIdType> order = Order(centroids, this->Eye);
  vtkNew<vtkCellArray> sorted;
  sorted->AllocateExact(n, polys->GetNumberOfConnectivityIds());
  for (vtkIdType c : order)
  {
    polys->GetCellAtId(c, ids);
    sorted->InsertNextCell(ids);
  }
  output->ShallowCopy(input);
  output->SetPolys(sorted);
  return 1;
}
