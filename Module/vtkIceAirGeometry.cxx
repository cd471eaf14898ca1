#include "vtkIceAirGeometry.h"

#include "vtkIceNoise.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"

#include <cstdint>

vtkStandardNewMacro(vtkIceAirGeometry);

//------------------------------------------------------------------------------
int vtkIceAirGeometry::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* ice = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!ice)
  {
    return 1;
  }
  double bounds[6];
  ice->GetBounds(bounds);
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> uv;
  uv->SetName("vtkIceAirUV");
  uv->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  const std::uint32_t sequence = static_cast<std::uint32_t>(this->Seed) * 6151U + 7U;
  for (int i = 0; i < this->NumberOfPlanes; ++i)
  {
    // In the middle 40 % of the bounds, half-sizes of 0.2 to 0.4 of the largest extent.
    double center[3];
    vtkNew<vtkTransform> place;
    vtkIceNoise::RandomPlacement(sequence, i, bounds, 0.4, 0.2, 0.4, place, center);
    // Each plane shows one tile of the 2 x 2 atlas, inset against bleeding.
    const double tileU = 0.5 * (i % 2);
    const double tileV = 0.5 * ((i / 2) % 2);
    const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    for (const auto& corner : corners)
    {
      double p[3] = { corner[0], corner[1], 0.0 };
      place->TransformPoint(p, p);
      points->InsertNextPoint(p);
      uv->InsertNextTuple2(
        tileU + 0.01 + 0.24 * (corner[0] + 1.0), tileV + 0.01 + 0.24 * (corner[1] + 1.0));
      double n[3] = { 0.0, 0.0, 1.0 };
      place->TransformNormal(n, n);
      vtkMath::Normalize(n);
      normals->InsertNextTuple(n);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (vtkIdType i = 0; i < this->NumberOfPlanes; ++i)
  {
    const vtkIdType quad[4] = { 4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3 };
    quads->InsertNextCell(4, quad);
  }
  output->SetPoints(points);
  output->SetPolys(quads);
  output->GetPointData()->AddArray(uv);
  output->GetPointData()->SetNormals(normals);
  return 1;
}
