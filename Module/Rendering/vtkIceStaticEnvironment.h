// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The environment an ice mapper samples when no pass hands it a dynamic cube map: the renderer's
// environment texture (a cube map, or an equirectangular 2D image converted to one, as ParaView
// sets for its skybox), or a built-in sky (with one warning) when that is missing or unusable.
#ifndef vtkIceStaticEnvironment_h
#define vtkIceStaticEnvironment_h

#include "vtkSmartPointer.h"
#include "vtkType.h" // for vtkMTimeType

class vtkEquirectangularToCubeMapTexture;
class vtkObject;
class vtkOpenGLTexture;
class vtkRenderer;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

class vtkIceStaticEnvironment
{
public:
  // Binds the environment for a draw of `owner` (who warns; nullptr: no warning) in `renderer`;
  // returns what the shader samples.
  vtkTextureObject* Bind(vtkRenderer* renderer, vtkObject* owner);
  // After the draw.
  void Unbind(vtkRenderer* renderer);
  // The matrix (column-major, as GLSL reads it) the shader applies to a world direction before it
  // samples the bound texture, so that the ice lines up with VTK's skybox of the same texture.
  const float* GetLookupMatrix() const { return this->LookupMatrix; }
  // How the shader shows the sampled colours as the skybox of the same texture does: AsSampled,
  // or FromLinear (gamma-corrected, as ParaView's skybox and an sRGB texture without a skybox).
  enum ColorSpaces
  {
    AsSampled = 0,
    FromLinear = 1
  };
  int GetColorSpace() const { return this->ColorSpace; }
  // Whether `renderer` shows its environment texture gamma-corrected (FromLinear): then the
  // colours around the ice, in that texture as the shader shows them and in a dynamic cube map
  // of the scene, are gamma-encoded linear light.
  static bool ShowsEncodedLight(vtkRenderer* renderer);
  // Changes when the bound texture's texels may have changed (for a copy made of them).
  vtkMTimeType GetVersion() const { return this->Version; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTexture* Select(vtkRenderer* renderer, vtkObject* owner);

  vtkSmartPointer<vtkTexture> Fallback;
  vtkSmartPointer<vtkEquirectangularToCubeMapTexture> Converted;
  vtkSmartPointer<vtkOpenGLTexture> Panorama;
  vtkTexture* PanoramaSource = nullptr;
  vtkMTimeType PanoramaTime = 0;
  float LookupMatrix[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  int ColorSpace = AsSampled;
  vtkMTimeType Version = 0;
  vtkTexture* Bound = nullptr;
  bool Warned = false;
};

#endif
