// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceVolumeStep.h"

#include "vtkIceTranslucentStep.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkVolumetricPass.h"

vtkStandardNewMacro(vtkIceVolumeStep);

//------------------------------------------------------------------------------
vtkIceVolumeStep::vtkIceVolumeStep()
  : Volumes(vtkSmartPointer<vtkVolumetricPass>::New())
{
}

vtkIceVolumeStep::~vtkIceVolumeStep() = default;

void vtkIceVolumeStep::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (this->Translucent && this->Translucent->DrewVolumes)
  {
    return;
  }
  this->Volumes->Render(s);
  this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
}

void vtkIceVolumeStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Volumes->ReleaseGraphicsResources(w);
}
