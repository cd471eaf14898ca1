// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceInteriorSources.h"

#include "vtkIceAirTextureSource.h"
#include "vtkIceCrackGeometry.h"

#include "vtkPolyData.h"
#include "vtkTexture.h"

//------------------------------------------------------------------------------
vtkIceInteriorSources::vtkIceInteriorSources()
{
  // The screen-space interior samples the images in a loop: without anisotropic filtering,
  // which makes llvmpipe a hundred times slower there (15 s a frame for 19 planes).
  this->AirAtlas->SetInputConnection(this->AirImages->GetOutputPort());
  this->AirAtlas->InterpolateOn();
  this->AirAtlas->MipmapOn();
  this->AirAtlas->SetMaximumAnisotropicFiltering(1.0);
  this->AirAtlas->RepeatOff();
  this->AirAtlas->EdgeClampOn();
  this->AirAtlas->SetColorModeToDirectScalars();
}

//------------------------------------------------------------------------------
vtkIceInteriorSources::~vtkIceInteriorSources() = default;

//------------------------------------------------------------------------------
vtkPolyData* vtkIceInteriorSources::UpdateCracks(
  vtkPolyData* ice, const double bounds[6], int number, int seed, bool clipToSurface)
{
  this->Cracks->SetInputData(ice);
  this->Cracks->SetPlacementBounds(
    bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  this->Cracks->SetNumberOfCracks(number);
  this->Cracks->SetSeed(seed);
  this->Cracks->SetClipToSurface(clipToSurface);
  this->Cracks->Update();
  return this->Cracks->GetOutput();
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceInteriorSources::GetAirAtlas(int seed)
{
  this->AirImages->SetSeed(seed);
  return this->AirAtlas;
}

//------------------------------------------------------------------------------
void vtkIceInteriorSources::ReleaseGraphicsResources(vtkWindow* window)
{
  this->AirAtlas->ReleaseGraphicsResources(window);
}
