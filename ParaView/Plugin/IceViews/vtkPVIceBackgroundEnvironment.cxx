// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVIceBackgroundEnvironment.h"

#include "vtkIceCubeMapSource.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkPVIceBackgroundEnvironment);

//------------------------------------------------------------------------------
vtkPVIceBackgroundEnvironment::vtkPVIceBackgroundEnvironment()
{
  this->Built.fill(0.0);
  // CubeMapOn first: it gives the texture its six input ports.
  this->Texture->CubeMapOn();
  for (int face = 0; face < 6; ++face)
  {
    this->Texture->SetInputData(face, this->Faces[face]);
  }
  this->Texture->InterpolateOn();
  this->Texture->MipmapOff();
  this->Texture->RepeatOff();
  this->Texture->EdgeClampOn();
  // Float colours as they are (the default colour mode would map them through a lookup table).
  this->Texture->SetColorModeToDirectScalars();
}

//------------------------------------------------------------------------------
vtkPVIceBackgroundEnvironment::~vtkPVIceBackgroundEnvironment() = default;

//------------------------------------------------------------------------------
vtkTexture* vtkPVIceBackgroundEnvironment::GetTexture()
{
  return this->Texture;
}

//------------------------------------------------------------------------------
bool vtkPVIceBackgroundEnvironment::Update(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr;
  if (!camera || renderer->GetTexturedBackground() || renderer->GetEnvironmentTexture())
  {
    return false;
  }
  std::array<double, 14> wanted;
  wanted.fill(0.0);
  renderer->GetBackground(&wanted[0]);
  renderer->GetBackground2(&wanted[3]);
  const bool gradient = renderer->GetGradientBackground();
  wanted[6] = gradient ? 1.0 : 0.0;
  if (gradient)
  {
    // Only the camera's orientation and view angle move a gradient across directions.
    double up[3], forward[3];
    camera->GetViewUp(up);
    camera->GetDirectionOfProjection(forward);
    // The part of the view-up across the view: the screen's vertical.
    const double along = vtkMath::Dot(up, forward);
    for (int i = 0; i < 3; ++i)
    {
      up[i] -= along * forward[i];
    }
    vtkMath::Normalize(up);
    double tangent = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
    if (camera->GetUseHorizontalViewAngle())
    {
      tangent /= std::max(renderer->GetTiledAspectRatio(), 1e-6);
    }
    std::copy_n(up, 3, &wanted[7]);
    std::copy_n(forward, 3, &wanted[10]);
    wanted[13] = tangent;
  }
  if (!this->HasBuilt || wanted != this->Built)
  {
    this->Built = wanted;
    this->HasBuilt = true;
    this->Build(gradient ? this->GradientFaceSize : 1);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPVIceBackgroundEnvironment::Build(int size)
{
  const double* bottom = &this->Built[0];
  const double* top = &this->Built[3];
  const bool gradient = this->Built[6] != 0.0;
  const double* up = &this->Built[7];
  const double* forward = &this->Built[10];
  const double tangent = this->Built[13];
  for (int face = 0; face < 6; ++face)
  {
    vtkNew<vtkFloatArray> colours;
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
    float* out = colours->GetPointer(0);
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        // Where the background shows this direction: the gradient's height on the screen
        // (0 bottom, 1 top) for a direction in front of the camera, its end colours beyond.
        double height = 0.0;
        if (gradient)
        {
          double direction[3];
          vtkIceCubeMapSource::TexelDirection(face, i, j, size, direction);
          const double y = vtkMath::Dot(direction, up);
          const double z = vtkMath::Dot(direction, forward);
          height = z > 0.0 ? 0.5 + 0.5 * y / (z * tangent) : (y > 0.0 ? 1.0 : 0.0);
          height = std::min(1.0, std::max(0.0, height));
        }
        for (int c = 0; c < 3; ++c)
        {
          *out++ = static_cast<float>((1.0 - height) * bottom[c] + height * top[c]);
        }
      }
    }
    vtkImageData* image = this->Faces[face];
    image->SetDimensions(size, size, 1);
    image->GetPointData()->SetScalars(colours);
    image->Modified();
  }
  this->Texture->Modified();
}

//------------------------------------------------------------------------------
void vtkPVIceBackgroundEnvironment::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GradientFaceSize: " << this->GradientFaceSize << "\n";
  os << indent << "Gradient: " << (this->Built[6] != 0.0) << "\n";
}
