// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceScreenTarget.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkIceVTKCompat.h"

vtkIceScreenTarget::vtkIceScreenTarget() = default;
vtkIceScreenTarget::~vtkIceScreenTarget() = default;

void vtkIceScreenTarget::Prepare(
  vtkOpenGLRenderWindow* window, int width, int height, int components)
{
  if (!this->ColorTexture)
  {
    this->Cleared.Reset();
    this->ColorTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->ColorTexture->SetContext(window);
    this->ColorTexture->SetFormat(components == 2 ? GL_RG : GL_RGBA);
    this->ColorTexture->SetInternalFormat(components == 2 ? GL_RG32F : GL_RGBA32F);
    this->ColorTexture->SetDataType(GL_FLOAT);
    this->ColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->ColorTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->ColorTexture->Allocate2D(width, height, components, VTK_FLOAT);
  }
  if (!this->DepthTexture && !this->ExternalDepth)
  {
    this->DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->DepthTexture->SetContext(window);
    this->DepthTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
    this->Attached = false;
  }
  this->ColorTexture->Resize(width, height);
  if (this->DepthTexture)
  {
    this->DepthTexture->Resize(width, height);
  }
  this->Width = width;
  this->Height = height;
}

void vtkIceScreenTarget::Bind(vtkOpenGLState* state)
{
  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  if (!this->Attached)
  {
    // Once per framebuffer: the attachments stay (a resize keeps the textures' names).
    this->FrameBuffer->AddColorAttachment(0, this->ColorTexture);
    this->FrameBuffer->ActivateDrawBuffers(1);
    this->Attached = true;
  }
  vtkTextureObject* depth =
    this->ExternalDepth ? this->ExternalDepth.Get() : this->DepthTexture.Get();
  if (depth != this->AttachedDepth)
  {
    this->FrameBuffer->AddDepthAttachment(depth);
    this->AttachedDepth = depth;
  }
  state->vtkglViewport(0, 0, this->Width, this->Height);
  state->vtkglScissor(0, 0, this->Width, this->Height);
}

void vtkIceScreenTarget::Unbind(vtkOpenGLState* state)
{
  state->PopFramebufferBindings();
}

vtkTextureObject* vtkIceScreenTarget::GetColorTexture() const
{
  return this->ColorTexture;
}

vtkTextureObject* vtkIceScreenTarget::GetDepthTexture() const
{
  return this->DepthTexture;
}

void vtkIceScreenTarget::UseDepthOf(vtkTextureObject* depth)
{
  if (depth != this->ExternalDepth)
  {
    this->ExternalDepth = depth;
    if (depth && this->DepthTexture)
    {
      // Its own is no longer attached; a null later makes it again.
      this->DepthTexture = nullptr;
    }
  }
}

void vtkIceScreenTarget::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->FrameBuffer)
  {
    this->FrameBuffer->ReleaseGraphicsResources(window);
  }
  for (vtkTextureObject* texture : { this->ColorTexture.Get(), this->DepthTexture.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  this->FrameBuffer = nullptr;
  this->ColorTexture = nullptr;
  this->DepthTexture = nullptr;
  this->ExternalDepth = nullptr;
  this->AttachedDepth = nullptr;
  this->Attached = false;
}

void vtkIceScreenTarget::Cull(unsigned int face)
{
  if (this->Active)
  {
    this->Active->Culling.Cull(face);
  }
}

namespace
{
vtkOpenGLState* StateOf(vtkRenderer* renderer)
{
  return static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
}

void Scissor(vtkOpenGLState* state, const int rect[4])
{
  state->vtkglScissor(rect[0], rect[1], rect[2] - rect[0], rect[3] - rect[1]);
}
}

vtkIceScreenTarget::Drawing::Drawing(
  vtkIceScreenTarget& target, const vtkRenderState* s, int components)
  : State(StateOf(s->GetRenderer()))
  , Target(target)
  , Culling(this->State)
  , Viewport(this->State)
  , Scissor(this->State)
  , ScissorTest(this->State, GL_SCISSOR_TEST)
  , ClearColorSaver(this->State)
  , ColorMask(this->State)
  , DepthMask(this->State)
  , DepthFunc(this->State)
  , DepthTest(this->State, GL_DEPTH_TEST)
  , Blend(this->State, GL_BLEND)
{
  vtkRenderer* renderer = s->GetRenderer();
  int width;
  int height;
  int x;
  int y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  target.Prepare(
    static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()), width, height, components);
  target.Bind(this->State);
  this->State->vtkglEnable(GL_DEPTH_TEST);
  this->State->vtkglDisable(GL_BLEND);
  this->State->vtkglDepthMask(GL_TRUE);
  vtkIceScreenRegion::Covered(s, width, height, this->Covered);
  ::Scissor(this->State, this->Covered);
  this->State->vtkglEnable(GL_SCISSOR_TEST);
  target.Active = this;
}

vtkIceScreenTarget::Drawing::~Drawing()
{
  this->Target.Active = nullptr;
  this->Target.Unbind(this->State);
}

void vtkIceScreenTarget::Drawing::ClearColor(float red, float green, float blue, float alpha)
{
  int rect[4];
  this->Target.Cleared.ToClear(this->Covered, this->Target.Width, this->Target.Height, rect);
  ::Scissor(this->State, rect);
  this->State->vtkglClearColor(red, green, blue, alpha);
  this->State->vtkglClear(GL_COLOR_BUFFER_BIT);
  ::Scissor(this->State, this->Covered);
}

void vtkIceScreenTarget::Drawing::ClearDepth(double depth)
{
  this->State->vtkglClearDepth(depth);
  this->State->vtkglClear(GL_DEPTH_BUFFER_BIT);
  this->State->vtkglClearDepth(1.0);
}
