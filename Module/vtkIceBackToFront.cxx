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
  std::vector<double> distance(static_cast<size_t>(n));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    polys->GetCellAtId(c, ids);
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const double* p = input->GetPoint(ids->GetId(k));
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += p[i] / ids->GetNumberOfIds();
      }
    }
    distance[static_cast<size_t>(c)] = vtkMath::Distance2BetweenPoints(centroid, this->Eye);
  }
  std::vector<vtkIdType> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&distance](vtkIdType a, vtkIdType b) { return distance[a] > distance[b]; });
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
