// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceFrameTextures.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>

//------------------------------------------------------------------------------
bool vtkIceFrameTextures::Bind(
  vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture)
{
  if (!texture || !program->IsUniformUsed(sampler))
  {
    return false;
  }
  if (std::find(this->Active.begin(), this->Active.end(), texture) == this->Active.end())
  {
    texture->Activate();
    this->Active.push_back(texture);
  }
  program->SetUniformi(sampler, texture->GetTextureUnit());
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceFrameTextures::BindScreen(
  vtkShaderProgram* program, vtkRenderer* renderer, const char* sampler, vtkTextureObject* texture)
{
  if (!this->Bind(program, sampler, texture))
  {
    return false;
  }
  int viewport[4];
  static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())
    ->GetState()
    ->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  program->SetUniform2i("iceViewportOrigin", viewport);
  return true;
}

//------------------------------------------------------------------------------
void vtkIceFrameTextures::Release(vtkTextureObject* texture)
{
  auto found = std::find(this->Active.begin(), this->Active.end(), texture);
  if (found != this->Active.end())
  {
    texture->Deactivate();
    this->Active.erase(found);
  }
}

//------------------------------------------------------------------------------
void vtkIceFrameTextures::ReleaseAll()
{
  for (vtkTextureObject* texture : this->Active)
  {
    texture->Deactivate();
  }
  this->Active.clear();
}
