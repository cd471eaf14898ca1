// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIcePrefilteredEnvironment.h"

#include "vtkIcePrefilterFS.h"
#include "vtkIceShaderSections.h"
#include "vtkIceVTKCompat.h" // for the OpenGL loader

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <string>

namespace
{
std::unique_ptr<vtkOpenGLQuadHelper> MakeQuad(vtkOpenGLRenderWindow* window, const char* part)
{
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(
    fs, "//VTK::FSQ::Decl", vtkIceShaderSections::Get(vtkIcePrefilterFS, "Dec"));
  vtkShaderProgram::Substitute(
    fs, "//VTK::FSQ::Impl", vtkIceShaderSections::Get(vtkIcePrefilterFS, part));
  return std::unique_ptr<vtkOpenGLQuadHelper>(
    new vtkOpenGLQuadHelper(window, nullptr, fs.c_str(), ""));
}

// A cube map with `maxLevel` mip levels below level 0, all allocated.
vtkSmartPointer<vtkTextureObject> MakeCubeMap(
  vtkOpenGLRenderWindow* window, bool highDynamicRange, int maxLevel)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetMaxLevel(maxLevel);
  texture->SetInternalFormat(highDynamicRange ? GL_RGBA16F : GL_RGBA8);
  texture->SetFormat(GL_RGBA);
  texture->SetDataType(highDynamicRange ? GL_FLOAT : GL_UNSIGNED_BYTE);
  void* noData[6] = { nullptr, nullptr, nullptr, nullptr, nullptr, nullptr };
  const int size = vtkIcePrefilteredEnvironment::FaceSize;
  texture->CreateCubeFromRaw(
    size, size, 4, highDynamicRange ? VTK_FLOAT : VTK_UNSIGNED_CHAR, noData);
  texture->Activate();
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  texture->Deactivate();
  return texture;
}
}

//------------------------------------------------------------------------------
// Through VTK's state, which keeps the switch in its cache (and checks that cache against OpenGL
// in builds that report OpenGL errors).
void vtkIcePrefilteredEnvironment::BeginSampling(vtkOpenGLState* state)
{
  this->SeamlessWasOn = state->GetEnumState(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  state->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

void vtkIcePrefilteredEnvironment::EndSampling(vtkOpenGLState* state)
{
  if (!this->SeamlessWasOn)
  {
    state->vtkglDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  }
}

//------------------------------------------------------------------------------
vtkIcePrefilteredEnvironment::vtkIcePrefilteredEnvironment() = default;
vtkIcePrefilteredEnvironment::~vtkIcePrefilteredEnvironment() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkIcePrefilteredEnvironment::Update(
  vtkOpenGLRenderWindow* window, vtkTextureObject* source, vtkMTimeType version)
{
  const bool highDynamicRange = source->GetVTKDataType() != VTK_UNSIGNED_CHAR;
  if (this->Result &&
    (this->Result->GetContext() != window ||
      (this->Result->GetVTKDataType() != VTK_UNSIGNED_CHAR) != highDynamicRange))
  {
    this->ReleaseGraphicsResources(this->Result->GetContext());
  }
  if (this->Result && source == this->Source && source->GetHandle() == this->SourceHandle &&
    version == this->SourceVersion)
  {
    return this->Result;
  }
  this->Allocate(window, highDynamicRange);
  this->Filter(window, source);
  this->Source = source;
  this->SourceHandle = source->GetHandle();
  this->SourceVersion = version;
  ++this->NumberOfUpdates;
  return this->Result;
}

//------------------------------------------------------------------------------
void vtkIcePrefilteredEnvironment::Allocate(vtkOpenGLRenderWindow* window, bool highDynamicRange)
{
  if (!this->Result)
  {
    int workLevels = 0;
    while ((FaceSize >> workLevels) > 1)
    {
      ++workLevels;
    }
    this->Work = MakeCubeMap(window, highDynamicRange, workLevels);
    this->Result = MakeCubeMap(window, highDynamicRange, Levels - 1);
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
  }
  if (!this->Copy)
  {
    this->Copy = MakeQuad(window, "Copy");
    this->Convolve = MakeQuad(window, "Convolve");
  }
}

//------------------------------------------------------------------------------
void vtkIcePrefilteredEnvironment::Draw(
  vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper& quad, vtkTextureObject* target, int level)
{
  const int size = FaceSize >> level;
  window->GetState()->vtkglViewport(0, 0, size, size);
  quad.Program->SetUniformf("iceTargetSize", static_cast<float>(size));
  // Attached here, not with AddColorAttachment: VTK's framebuffer object keeps its first
  // attachment of a texture when asked for another face or level of it.
  for (int face = 0; face < 6; ++face)
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
      GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, target->GetHandle(), level);
    quad.Program->SetUniformi("iceFace", face);
    quad.Render();
  }
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
}

//------------------------------------------------------------------------------
void vtkIcePrefilteredEnvironment::Filter(vtkOpenGLRenderWindow* window, vtkTextureObject* source)
{
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable stencilSaver(state, GL_STENCIL_TEST);
  // It may run in a sub-pass that writes depth only.
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  // The rougher levels sample the resampled source across its faces' edges too.
  this->BeginSampling(state);
  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->ActivateDrawBuffer(0);

  // Level 0 of both textures: the source resampled. A source already bound for the draw keeps its
  // texture unit.
  const bool sourceBound = source->GetTextureUnit() >= 0;
  if (!sourceBound)
  {
    source->Activate();
  }
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  cache->ReadyShaderProgram(this->Copy->Program);
  this->Copy->Program->SetUniformi("iceSource", source->GetTextureUnit());
  this->Draw(window, *this->Copy, this->Work, 0);
  this->Draw(window, *this->Copy, this->Result, 0);
  if (!sourceBound)
  {
    source->Deactivate();
  }

  // The rougher levels average the resampled source's mip levels over their lobes.
  this->Work->Activate();
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  cache->ReadyShaderProgram(this->Convolve->Program);
  vtkShaderProgram* program = this->Convolve->Program;
  program->SetUniformi("iceSource", this->Work->GetTextureUnit());
  program->SetUniformf("iceSourceSize", static_cast<float>(FaceSize));
  program->SetUniformi("iceSampleCount", SampleCount);
  for (int level = 1; level < Levels; ++level)
  {
    program->SetUniformf("iceRoughness", static_cast<float>(level) / (Levels - 1));
    this->Draw(window, *this->Convolve, this->Result, level);
  }
  this->Work->Deactivate();
  state->PopFramebufferBindings();
  this->EndSampling(state);
}

//------------------------------------------------------------------------------
void vtkIcePrefilteredEnvironment::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Work.GetPointer(), this->Result.GetPointer() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  this->Work = nullptr;
  this->Result = nullptr;
  if (this->FrameBuffer)
  {
    this->FrameBuffer->ReleaseGraphicsResources(window);
    this->FrameBuffer = nullptr;
  }
  for (auto* quad : { &this->Copy, &this->Convolve })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  this->Source = nullptr;
  this->SourceHandle = 0;
}
