// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCrackGeometry.h"

#include "vtkIceCrackSource.h"
#include "vtkIceNoise.h"

#include "vtkAppendPolyData.h"
#include "vtkClipPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSelectEnclosedPoints.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceCrackGeometry);

namespace
{
const int GenericCrackModels = 3;

// Cuts `cracks` to the inside of the closed surface `ice`. The signed distance to the surface
// (negative inside) takes its sign from ray casting (vtkSelectEnclosedPoints):
// vtkImplicitPolyDataDistance's own sign is wrong for some points near edges of concave meshes.
// The clip interpolates the zero crossing along crack edges.
void ClipInside(vtkPolyData* cracks, vtkPolyData* ice, vtkPolyData* output)
{
  vtkNew<vtkSelectEnclosedPoints> enclosed;
  enclosed->SetInputData(cracks);
  enclosed->SetSurfaceData(ice);
  enclosed->Update();
  vtkNew<vtkImplicitPolyDataDistance> distance;
  distance->SetInput(ice);
  vtkNew<vtkDoubleArray> signedDistance;
  signedDistance->SetName("vtkIceCrackDistance");
  signedDistance->SetNumberOfTuples(cracks->GetNumberOfPoints());
  for (vtkIdType i = 0; i < cracks->GetNumberOfPoints(); ++i)
  {
    const double magnitude = std::abs(distance->EvaluateFunction(cracks->GetPoint(i)));
    signedDistance->SetValue(i, enclosed->IsInside(i) ? -magnitude : magnitude);
  }
  vtkNew<vtkPolyData> measured;
  measured->ShallowCopy(cracks);
  measured->GetPointData()->SetScalars(signedDistance);
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(measured);
  clip->InsideOutOn(); // keep negative distances: inside the ice
  clip->SetValue(0.0);
  clip->Update();
  output->ShallowCopy(clip->GetOutput());
  output->GetPointData()->RemoveArray("vtkIceCrackDistance");
}
}

//------------------------------------------------------------------------------
int vtkIceCrackGeometry::ModelSeed(int seed, int index)
{
  return GenericCrackModels * seed + index % GenericCrackModels;
}

//------------------------------------------------------------------------------
void vtkIceCrackGeometry::Placement(
  int seed, int index, const double bounds[6], vtkTransform* placement)
{
  // Near the centre, large enough to span most of the ice.
  const std::uint32_t sequence = static_cast<std::uint32_t>(seed) * 7919U + 1U;
  double center[3];
  vtkIceNoise::RandomPlacement(sequence, index, bounds, 0.3, 0.48, 0.72, placement, center);
}

//------------------------------------------------------------------------------
int vtkIceCrackGeometry::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* ice = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!ice || this->NumberOfCracks == 0)
  {
    return 1;
  }
  double bounds[6];
  ice->GetBounds(bounds);
  if (vtkMath::AreBoundsInitialized(this->PlacementBounds))
  {
    std::copy(this->PlacementBounds, this->PlacementBounds + 6, bounds);
  }

  vtkSmartPointer<vtkPolyData> models[GenericCrackModels];
  for (int m = 0; m < GenericCrackModels; ++m)
  {
    vtkNew<vtkIceCrackSource> source;
    source->SetSeed(ModelSeed(this->Seed, m));
    source->Update();
    models[m] = source->GetOutput();
  }
  vtkNew<vtkAppendPolyData> append;
  for (int i = 0; i < this->NumberOfCracks; ++i)
  {
    vtkNew<vtkTransform> placement;
    Placement(this->Seed, i, bounds, placement);
    vtkNew<vtkTransformPolyDataFilter> place;
    place->SetInputData(models[i % GenericCrackModels]);
    place->SetTransform(placement);
    append->AddInputConnection(place->GetOutputPort());
  }
  append->Update();
  if (this->ClipToSurface)
  {
    ClipInside(append->GetOutput(), ice, output);
  }
  else
  {
    output->ShallowCopy(append->GetOutput());
  }
  return 1;
}
