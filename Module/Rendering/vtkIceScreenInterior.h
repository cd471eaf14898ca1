// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The screen-space step of vtkIceMapper::InteriorScreenSpace: an ice prop's cracks, milky core and
// bubbles evaluated once per pixel inside its projected bounding box, by a quad over a
// viewport-sized target (RGBA float: what the interior adds to the ice colour and how much of it
// it keeps), and its air planes drawn as quads between (vtkIceScreenAir); the ice's surface
// program then applies the result (ICE_FRAME_SCREEN_INTERIOR). Its cost follows the ice's
// pixels, not its triangles or their overdraw. vtkIcePass owns one and draws
// it prop by prop before the scene, after the back faces. Inside the module.
#ifndef vtkIceScreenInterior_h
#define vtkIceScreenInterior_h

#include "vtkIceScreenAir.h"
#include "vtkIceScreenTarget.h"

#include <map>
#include <memory>
#include <string>

class vtkActor;
class vtkIceDepthIntervalPass;
class vtkIceFrame;
class vtkIceMapper;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderState;
class vtkTextureObject;
class vtkWindow;

class vtkIceScreenInterior
{
public:
  vtkIceScreenInterior();
  ~vtkIceScreenInterior();

  // Starts a frame: the first Draw clears the target where the ice props of `iceState` can be.
  void Begin() { this->Cleared = false; }

  // Evaluates the interior of `actor` (drawn by `mapper`) where its front faces are, as `front`
  // rendered them last (FrontOnly: their view depth, and their window depth, against which the
  // quad is depth-tested so that no other pixel runs the shader), and where they are the nearest
  // of the ice (`nearest`: the nearest front faces' view depth of all the ice; null when this is
  // the only ice with a screen-space interior: then no draw reads it). The frame holds the back
  // faces.
  void Draw(const vtkRenderState* iceState, vtkActor* actor, vtkIceMapper* mapper,
    vtkIceFrame* frame, vtkIceDepthIntervalPass* front, vtkTextureObject* nearest);

  // What the ice's surface programs sample (the frame's ScreenInterior).
  vtkTextureObject* GetTexture() const { return this->Target.GetColorTexture(); }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkIceScreenTarget Target;
  // The quad (null where it failed to compile) for the fragment shader `source`.
  vtkOpenGLQuadHelper* ReadyQuad(vtkOpenGLRenderWindow* window, const std::string& source);

  // Where `nearest` is given: the prop's front faces' window depth (the target's depth) moved to
  // the far plane wherever another ice prop's front faces are nearer. False where it failed.
  bool KeepNearest(vtkOpenGLRenderWindow* window, vtkOpenGLState* state, vtkIceFrame* frame,
    vtkTextureObject* front, vtkTextureObject* nearest);

  vtkIceScreenAir Air;
  // By fragment shader source (the nearest prop's quad among them): the lights and the
  // roughness of the environment change the interior's.
  std::map<std::string, std::unique_ptr<vtkOpenGLQuadHelper>> Quads;
  bool Cleared = false;

  vtkIceScreenInterior(const vtkIceScreenInterior&) = delete;
  void operator=(const vtkIceScreenInterior&) = delete;
};

#endif
