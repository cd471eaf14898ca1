// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The environment as frosted ice shows it (vtkIceMapper's Roughness): a cube map whose mip level k
// holds the environment averaged over the GGX lobe of roughness k / (Levels - 1), made from the
// cube map the ice samples (the renderer's environment or a dynamic cube map) and made again only
// when that changes. vtkIcePrefilterFS.glsl does the averaging. VTK's vtkPBRPrefilterTexture is
// not used: it takes a vtkOpenGLTexture that it loads itself (a dynamic cube map is a texture
// object a pass renders) and samples its input's own mip levels, which an environment texture
// rarely has and which the ice may not add to the user's texture.
#ifndef vtkIcePrefilteredEnvironment_h
#define vtkIcePrefilteredEnvironment_h

#include "vtkSmartPointer.h"
#include "vtkType.h" // for vtkMTimeType

#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkTextureObject;
class vtkWindow;

class vtkIcePrefilteredEnvironment
{
public:
  vtkIcePrefilteredEnvironment();
  ~vtkIcePrefilteredEnvironment();

  static constexpr int Levels = 5;         // roughness 0, 0.25, 0.5, 0.75, 1
  static constexpr int FaceSize = 64;      // texels per edge of level 0
  static constexpr int SampleCount = 1024; // lobe samples per texel

  // The mip level holding `roughness` (in [0, 1]): the shader interpolates between levels.
  static double LevelOf(double roughness) { return roughness * (Levels - 1); }

  // The prefiltered copy of the cube map `source`, made again when `source` or `version` changed
  // since the last call (a caller's count of the changes to the source's texels).
  vtkTextureObject* Update(
    vtkOpenGLRenderWindow* window, vtkTextureObject* source, vtkMTimeType version);

  // How often it has prefiltered since creation.
  int GetNumberOfUpdates() const { return this->NumberOfUpdates; }

  void ReleaseGraphicsResources(vtkWindow* window);

  // Around a draw that samples the result: cube maps filtered across their faces' edges
  // (GL_TEXTURE_CUBE_MAP_SEAMLESS), as OpenGL had it before afterwards. The coarse levels'
  // texels are large: filtered face by face, their seams would show.
  void BeginSampling(vtkOpenGLState* state);
  void EndSampling(vtkOpenGLState* state);

private:
  vtkIcePrefilteredEnvironment(const vtkIcePrefilteredEnvironment&) = delete;
  void operator=(const vtkIcePrefilteredEnvironment&) = delete;

  void Allocate(vtkOpenGLRenderWindow* window, bool highDynamicRange);
  void Filter(vtkOpenGLRenderWindow* window, vtkTextureObject* source);
  void Draw(
    vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper& quad, vtkTextureObject* target, int level);

  // The source resampled to FaceSize with its box-filtered mip levels: what the lobes sample.
  vtkSmartPointer<vtkTextureObject> Work;
  vtkSmartPointer<vtkTextureObject> Result;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Copy;
  std::unique_ptr<vtkOpenGLQuadHelper> Convolve;
  vtkTextureObject* Source = nullptr;
  unsigned int SourceHandle = 0;
  vtkMTimeType SourceVersion = 0;
  int NumberOfUpdates = 0;
  bool SeamlessWasOn = false;
};

#endif
