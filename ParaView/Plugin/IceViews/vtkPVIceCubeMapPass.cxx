// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVIceCubeMapPass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPVIceCubeMapPass);

//------------------------------------------------------------------------------
vtkPVIceCubeMapPass::vtkPVIceCubeMapPass() = default;

//------------------------------------------------------------------------------
vtkPVIceCubeMapPass::~vtkPVIceCubeMapPass() = default;

//------------------------------------------------------------------------------
void vtkPVIceCubeMapPass::Background::Get(vtkRenderer* renderer)
{
  renderer->GetBackground(this->Color);
  renderer->GetBackground2(this->Color2);
  this->Alpha = renderer->GetBackgroundAlpha();
  this->Gradient = renderer->GetGradientBackground();
  this->Textured = renderer->GetTexturedBackground();
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapPass::Background::Set(vtkRenderer* renderer) const
{
  renderer->SetBackground(this->Color);
  renderer->SetBackground2(this->Color2);
  renderer->SetBackgroundAlpha(this->Alpha);
  renderer->SetGradientBackground(this->Gradient);
  renderer->SetTexturedBackground(this->Textured);
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapPass::SetFaceBackground(vtkRenderer* renderer)
{
  this->FaceBackground.Get(renderer);
  this->HasFaceBackground = true;
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapPass::Render(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  if (!this->HasFaceBackground)
  {
    this->Superclass::Render(s);
    return;
  }
  Background drawn;
  drawn.Get(renderer);
  this->FaceBackground.Set(renderer);
  this->Superclass::Render(s);
  drawn.Set(renderer);
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HasFaceBackground: " << this->HasFaceBackground << "\n";
}
