// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The frame's textures that vtkIcePass hands to the shaders sampling them.
#ifndef vtkIceFrameTextures_h
#define vtkIceFrameTextures_h

#include <vector>

class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

// A texture gets a texture unit the first time a program samples it and keeps it for the draws
// that follow (a pass has no hook after a draw); the pass releases it before the texture is
// rendered again and at the end of the frame.
class vtkIceFrameTextures
{
public:
  // Sets `sampler` of `program` to `texture`, activating it if needed. False (nothing done) when
  // the program does not sample `sampler`.
  bool Bind(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture);

  // As Bind, for a texture covering the renderer's viewport: also sets iceViewportOrigin, the
  // origin of the current GL viewport in whatever framebuffer the draw goes to.
  bool BindScreen(vtkShaderProgram* program, vtkRenderer* renderer, const char* sampler,
    vtkTextureObject* texture);

  void Release(vtkTextureObject* texture);
  void ReleaseAll();

private:
  std::vector<vtkTextureObject*> Active;
};

#endif
