// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceStaticEnvironment.h"

#include "vtkIceCubeMapSource.h"
#include "vtkIceVTKCompat.h"

#include "vtkAlgorithm.h"
#include "vtkFloatArray.h"
#include "vtkEquirectangularToCubeMapTexture.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>

namespace
{
// Whether every face of a cube-map texture has an image. A reader that failed (missing or
// corrupt files) gives empty faces: bound anyway, the texture reports an error every frame and
// the ice samples an incomplete texture (GL_INVALID_VALUE for its sampler).
bool HasFaceImages(vtkTexture* texture)
{
  for (int port = 0; port < texture->GetNumberOfInputPorts(); ++port)
  {
    int outputPort = 0;
    vtkAlgorithm* producer = texture->GetNumberOfInputConnections(port) > 0
      ? texture->GetInputAlgorithm(port, 0, outputPort)
      : nullptr;
    if (!producer)
    {
      return false;
    }
    producer->Update(outputPort);
    vtkImageData* face = vtkImageData::SafeDownCast(producer->GetOutputDataObject(outputPort));
    if (!face || face->GetNumberOfPoints() == 0 || !face->GetPointData()->GetScalars())
    {
      return false;
    }
  }
  return true;
}

// Whether a skybox shows `env` gamma-corrected: the renderer's visible vtkSkybox of that texture
// decides (ParaView's corrects, VTK's default does not); without one, an sRGB texture does (its
// values are stored gamma-encoded, and sampled as linear).
bool ShowsGammaCorrected(vtkRenderer* renderer, vtkTexture* env)
{
  if (!env)
  {
    return false;
  }
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* skybox = vtkSkybox::SafeDownCast(prop);
    if (skybox && skybox->GetVisibility() && skybox->GetTexture() == env)
    {
      return skybox->GetGammaCorrect();
    }
  }
  return env->GetUseSRGBColorSpace();
}

// The colours of an sRGB image as linear floats (alpha dropped).
vtkSmartPointer<vtkImageData> DecodeSRGB(vtkImageData* image)
{
  vtkDataArray* stored = image->GetPointData()->GetScalars();
  const int components = std::min(stored->GetNumberOfComponents(), 3);
  const vtkIdType count = stored->GetNumberOfTuples();
  vtkNew<vtkFloatArray> linear;
  linear->SetNumberOfComponents(3);
  linear->SetNumberOfTuples(count);
  // Integer texels are normalized as OpenGL does.
  const double scale = stored->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0
    : stored->GetDataType() == VTK_UNSIGNED_SHORT                 ? 1.0 / 65535.0
                                                                  : 1.0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = scale * stored->GetComponent(i, std::min(c, components - 1));
      linear->SetComponent(i, c, v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
  }
  auto decoded = vtkSmartPointer<vtkImageData>::New();
  decoded->CopyStructure(image);
  decoded->GetPointData()->SetScalars(linear);
  return decoded;
}
}

//------------------------------------------------------------------------------
bool vtkIceStaticEnvironment::ShowsEncodedLight(vtkRenderer* renderer)
{
  return ShowsGammaCorrected(renderer, renderer->GetEnvironmentTexture());
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceStaticEnvironment::Select(vtkRenderer* renderer, vtkObject* owner)
{
  vtkTexture* env = renderer->GetEnvironmentTexture();
  const bool cubeMap = env && env->GetCubeMap();
  const float identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  std::copy(identity, identity + 9, this->LookupMatrix);
  const bool srgb = env && env->GetUseSRGBColorSpace();
  this->ColorSpace = ShowsGammaCorrected(renderer, env) ? FromLinear : AsSampled;
  if (cubeMap && HasFaceImages(env))
  {
    if (vtkIceVTKCompat::CubeMapLookupFlipsZ)
    {
      this->LookupMatrix[8] = -1;
    }
    return env;
  }
  auto* image = vtkOpenGLTexture::SafeDownCast(env);
  if (image && !cubeMap && HasFaceImages(image))
  {
    // An equirectangular panorama. VTK's conversion puts the panorama's pixel at longitude
    // atan2(z, x), latitude asin(y) into the cube texel of direction (x, y, z): the mapping of
    // vtkSkybox's sphere projection in ParaView's orientation, so the raw direction lines up.
    if (!this->Converted || this->PanoramaSource != image)
    {
      this->PanoramaSource = image;
      this->Panorama = vtkSmartPointer<vtkOpenGLTexture>::New();
      // No mipmaps: the longitude seam of the conversion's lookup would pick the smallest level.
      this->Panorama->InterpolateOn();
      this->Panorama->SetColorModeToDirectScalars();
      this->Converted = vtkSmartPointer<vtkEquirectangularToCubeMapTexture>::New();
      this->Converted->SetInputTexture(this->Panorama);
      this->Converted->SetCubeMapSize(512);
      this->Converted->InterpolateOn();
      this->PanoramaTime = 0;
    }
    vtkImageData* pixels = image->GetInput();
    if (pixels->GetMTime() != this->PanoramaTime)
    {
      // VTK gives the cube map the panorama's texture format: an sRGB one would be decoded
      // twice. Decoded here into floats instead, the cube map is filtered in linear space, as
      // the skybox filters its sRGB texture.
      this->PanoramaTime = pixels->GetMTime();
      this->Panorama->SetInputData(srgb ? DecodeSRGB(pixels).GetPointer() : pixels);
    }
    return this->Converted;
  }
  if (owner && !this->Warned)
  {
    vtkWarningWithObjectMacro(
      owner, << (!env          ? "The renderer has no environment texture"
                    : !cubeMap ? "The renderer's environment texture is neither a cube map nor "
                                 "an image"
                               : "The renderer's environment cube map has faces without "
                                 "an image (did its reader fail?)")
             << "; the ice reflects a built-in sky. Set a vtkTexture with CubeMapOn() "
                "with vtkRenderer::SetEnvironmentTexture.");
    this->Warned = true;
  }
  this->ColorSpace = AsSampled;
  if (!this->Fallback)
  {
    vtkNew<vtkIceCubeMapSource> sky;
    sky->SetFaceSize(64);
    this->Fallback = vtkSmartPointer<vtkTexture>::New();
    sky->ConfigureTexture(this->Fallback);
  }
  return this->Fallback;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceStaticEnvironment::Bind(vtkRenderer* renderer, vtkObject* owner)
{
  this->Bound = this->Select(renderer, owner);
  this->Bound->Render(renderer);
  // The texture, its face images, or the panorama it was converted from.
  this->Version = std::max(this->Bound->GetMTime(), this->PanoramaTime);
  for (int port = 0; port < this->Bound->GetNumberOfInputPorts(); ++port)
  {
    vtkDataObject* face = this->Bound->GetNumberOfInputConnections(port)
      ? this->Bound->GetInputDataObject(port, 0)
      : nullptr;
    if (face)
    {
      this->Version = std::max(this->Version, face->GetMTime());
    }
  }
  return static_cast<vtkOpenGLTexture*>(this->Bound)->GetTextureObject();
}

//------------------------------------------------------------------------------
void vtkIceStaticEnvironment::Unbind(vtkRenderer* renderer)
{
  if (this->Bound)
  {
    this->Bound->PostRender(renderer);
    this->Bound = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkIceStaticEnvironment::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Converted)
  {
    this->Converted->ReleaseGraphicsResources(window);
    this->Panorama->ReleaseGraphicsResources(window);
  }
  if (this->Fallback)
  {
    this->Fallback->ReleaseGraphicsResources(window);
  }
}
