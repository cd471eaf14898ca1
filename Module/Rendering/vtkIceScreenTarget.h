// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A viewport-sized render target of the ice sub-passes: a float colour texture (sampled texel
// for pixel, never filtered) and a depth texture in a framebuffer, made on first use and resized
// with the viewport. The sub-passes draw only the ice, so a Drawing works only inside the ice's
// projected bounding box (vtkIceScreenRegion): clears there, and the scissor keeps draws there.
#ifndef vtkIceScreenTarget_h
#define vtkIceScreenTarget_h

#include "vtkIceBackfaceCulling.h" // for vtkIceCullingSaver
#include "vtkIceScreenRegion.h"    // for Tracker
#include "vtkOpenGLState.h"        // for Drawing
#include "vtkSmartPointer.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class vtkIceScreenTarget
{
public:
  vtkIceScreenTarget();
  ~vtkIceScreenTarget();

  // Makes or resizes the textures: `components` float channels (2 or 4) and depth. A new or
  // resized colour texture is cleared whole by the next Drawing::ClearColor.
  void Prepare(vtkOpenGLRenderWindow* window, int width, int height, int components);

  // Draws into the target from here to Unbind, with a (0, 0, width, height) viewport and scissor.
  // The caller keeps (scoped savers) the viewport and scissor it wants back.
  void Bind(vtkOpenGLState* state);
  void Unbind(vtkOpenGLState* state);

  vtkTextureObject* GetColorTexture() const;
  vtkTextureObject* GetDepthTexture() const;

  // Attaches `depth` (another target's depth texture, of the same size) instead of a depth
  // texture of this target's own; null goes back to its own. Set before a Drawing.
  void UseDepthOf(vtkTextureObject* depth);

  // While a Drawing of this target lives: culls `face` (GL_FRONT or GL_BACK) for the draws that
  // follow, until the next vtkProperty::Render sets the actor's own culling. Passes call it from
  // SetShaderParameters, which runs after that for every draw. Does nothing without a Drawing.
  void Cull(unsigned int face);

  // For its lifetime: the target sized to the renderer's viewport and bound, depth test on with
  // depth writes, blending off, the scissor test on around the props of `s` (the region they
  // can cover); then everything it changed is put back.
  class Drawing
  {
  public:
    Drawing(vtkIceScreenTarget& target, const vtkRenderState* s, int components);
    ~Drawing();
    vtkOpenGLState* State;

    // Clears the colour texture to `color` where the props can be now or could be in the
    // previous Drawing, all of it when it is new or resized: every other texel already holds
    // `color`, which must be the same every frame. Respects the colour mask.
    void ClearColor(float red, float green, float blue, float alpha);
    // Clears the depth buffer to `depth` where the props can be (it is read only by this pass);
    // the clear depth goes back to VTK's 1.
    void ClearDepth(double depth);

  private:
    friend class vtkIceScreenTarget;
    vtkIceScreenTarget& Target;
    int Covered[4];
    vtkIceCullingSaver Culling;
    vtkOpenGLState::ScopedglViewport Viewport;
    vtkOpenGLState::ScopedglScissor Scissor;
    vtkOpenGLState::ScopedglEnableDisable ScissorTest;
    vtkOpenGLState::ScopedglClearColor ClearColorSaver;
    vtkOpenGLState::ScopedglColorMask ColorMask;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
    vtkOpenGLState::ScopedglDepthFunc DepthFunc;
    vtkOpenGLState::ScopedglEnableDisable DepthTest;
    vtkOpenGLState::ScopedglEnableDisable Blend;
  };

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkSmartPointer<vtkTextureObject> ColorTexture;
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  int Width = 0;
  int Height = 0;
  bool Attached = false; // the textures are attached to FrameBuffer
  vtkSmartPointer<vtkTextureObject> ExternalDepth;
  vtkTextureObject* AttachedDepth = nullptr;
  vtkIceScreenRegion::Tracker Cleared; // what of ColorTexture may not hold the clear colour
  Drawing* Active = nullptr;

  vtkIceScreenTarget(const vtkIceScreenTarget&) = delete;
  void operator=(const vtkIceScreenTarget&) = delete;
};

#endif
