// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
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

#include <algorithm>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceAirGeometry);

//------------------------------------------------------------------------------
void vtkIceAirGeometry::Placement(
  int seed, int index, const double bounds[6], vtkTransform* placement)
{
  // In the middle 40 % of the bounds, half-sizes of 0.2 to 0.4 of the largest extent.
  const std::uint32_t sequence = static_cast<std::uint32_t>(seed) * 6151U + 7U;
  double center[3];
  vtkIceNoise::RandomPlacement(sequence, index, bounds, 0.4, 0.2, 0.4, placement, center);
  double tile[2];
  Tile(index, tile);
  if (tile[0] == 0.0 && tile[1] == 0.5)
  {
    // The tile of tube-shaped bubbles, long along its v axis (vtkIceAirTextureSource): turned
    // in its plane so that they all run along world +Y (VTK's default up), as bubbles trapped
    // by ice freezing from the top do. A plane facing +Y keeps its turn.
    double across[3] = { 1.0, 0.0, 0.0 };
    double along[3] = { 0.0, 1.0, 0.0 };
    placement->TransformVector(across, across);
    placement->TransformVector(along, along);
    const double a = across[1] / vtkMath::Dot(across, across);
    const double b = along[1] / vtkMath::Dot(along, along);
    if (a * a + b * b > 1.0e-6)
    {
      placement->RotateZ(vtkMath::DegreesFromRadians(std::atan2(-a, b)));
    }
  }
}

//------------------------------------------------------------------------------
void vtkIceAirGeometry::Tile(int index, double tile[2])
{
  // Each plane shows one tile of the 2 x 2 atlas, inset against bleeding.
  tile[0] = 0.5 * (index % 2);
  tile[1] = 0.5 * ((index / 2) % 2);
}

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
  if (vtkMath::AreBoundsInitialized(this->PlacementBounds))
  {
    std::copy(this->PlacementBounds, this->PlacementBounds + 6, bounds);
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> uv;
  uv->SetName("vtkIceAirUV");
  uv->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < this->NumberOfPlanes; ++i)
  {
    vtkNew<vtkTransform> place;
    Placement(this->Seed, i, bounds, place);
    double tile[2];
    Tile(i, tile);
    const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    for (const auto& corner : corners)
    {
      double p[3] = { corner[0], corner[1], 0.0 };
      place->TransformPoint(p, p);
      points->InsertNextPoint(p);
      uv->InsertNextTuple2(tile[0] + TileInset + TileScale * (corner[0] + 1.0),
        tile[1] + TileInset + TileScale * (corner[1] + 1.0));
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
