// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: culls an ice actor's back faces for one draw where none of them can be
// seen. VTK draws both sides of a surface; on a CPU renderer every back-face fragment drawn
// before the front face hiding it runs the whole ice shader (its discard keeps the depth test
// late), which cost a quarter of a two-sided frame (Documentation/performance.md).
#ifndef vtkIceBackfaceCulling_h
#define vtkIceBackfaceCulling_h

#include "vtkOpenGLState.h" // for vtkIceCullingSaver's member

#include <memory> // for members

class vtkActor;
class vtkMapper;
class vtkRenderer;

// Whether faces are culled and which, saved when made and put back when destroyed; Cull changes
// both in between.
class vtkIceCullingSaver
{
public:
  explicit vtkIceCullingSaver(vtkOpenGLState* state);
  ~vtkIceCullingSaver();
  void Cull(unsigned int face);

private:
  vtkOpenGLState* State;
  int Mode;
  vtkOpenGLState::ScopedglEnableDisable Enabled;

  vtkIceCullingSaver(const vtkIceCullingSaver&) = delete;
  void operator=(const vtkIceCullingSaver&) = delete;
};

class vtkIceBackfaceCulling
{
public:
  // Whether no back face of `actor` can be seen in this draw: its input (`closedOutward`,
  // vtkIceSurfaceCheck::Closure) is closed and faces outward, it is drawn opaque as a surface
  // without edges or vertices shown, clipping planes, culling of its own property or a mirroring
  // transform, all of its bounds lie beyond the active camera's near plane (the camera is outside
  // it and no front face is clipped away). The caller checks that no sub-pass draws it (InSubPass).
  static bool BackfacesHidden(
    vtkRenderer* renderer, vtkActor* actor, vtkMapper* mapper, bool closedOutward);

  // Whether a render pass other than vtkIcePass draws `actor` now (an ice sub-pass, VTK's).
  static bool InSubPass(vtkActor* actor);

  // Culls back faces until End, restoring the OpenGL state then.
  void Begin(vtkRenderer* renderer);
  void End() { this->Saved.reset(); }

private:
  std::unique_ptr<vtkIceCullingSaver> Saved;
};

#endif
