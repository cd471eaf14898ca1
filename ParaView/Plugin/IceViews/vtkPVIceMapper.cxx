// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVIceMapper.h"

#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

vtkStandardNewMacro(vtkPVIceMapper);

//------------------------------------------------------------------------------
vtkPVIceMapper::vtkPVIceMapper() = default;

//------------------------------------------------------------------------------
vtkPVIceMapper::~vtkPVIceMapper() = default;

//------------------------------------------------------------------------------
void vtkPVIceMapper::SetBackgroundEnvironment(vtkTexture* texture)
{
  if (this->BackgroundEnvironment != texture)
  {
    this->BackgroundEnvironment = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTexture* vtkPVIceMapper::GetBackgroundEnvironment()
{
  return this->BackgroundEnvironment;
}

//------------------------------------------------------------------------------
void vtkPVIceMapper::BindEnvironment(vtkRenderer* ren, vtkActor* act)
{
  // vtkIceMapper binds the renderer's environment here (for the surface and for the
  // screen-space interior's step); the renderer has it for that moment only.
  if (!this->BackgroundEnvironment || ren->GetEnvironmentTexture())
  {
    this->Superclass::BindEnvironment(ren, act);
    return;
  }
  ren->SetEnvironmentTexture(this->BackgroundEnvironment);
  this->Superclass::BindEnvironment(ren, act);
  ren->SetEnvironmentTexture(nullptr);
}

//------------------------------------------------------------------------------
void vtkPVIceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundEnvironment: " << this->BackgroundEnvironment << "\n";
}
