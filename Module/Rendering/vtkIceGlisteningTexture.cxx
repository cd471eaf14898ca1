// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceGlisteningTexture.h"

#include "vtkIceNoise.h"

#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceGlisteningTexture);

namespace
{
unsigned char Encode(double value)
{
  // [-1, 1] to 0..255 (rounded), the inverse of the shader's 2 t - 1 up to 1/255.
  const double byte = std::round((0.5 * value + 0.5) * 255.0);
  return static_cast<unsigned char>(std::min(255.0, std::max(0.0, byte)));
}
}

//------------------------------------------------------------------------------
vtkIceGlisteningTexture::vtkIceGlisteningTexture() = default;

//------------------------------------------------------------------------------
vtkIceGlisteningTexture::~vtkIceGlisteningTexture() = default;

//------------------------------------------------------------------------------
void vtkIceGlisteningTexture::SetSize(int size)
{
  size = std::min(1024, std::max(4, size));
  int power = 4;
  while (2 * power <= size)
  {
    power *= 2;
  }
  if (power != this->Size)
  {
    this->Size = power;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkIceGlisteningTexture::GetImage()
{
  if (this->Image && this->ImageTime >= this->GetMTime())
  {
    return this->Image;
  }
  const int n = this->Size;
  vtkNew<vtkUnsignedCharArray> texels;
  texels->SetName("vtkIceGlisteningTexels");
  texels->SetNumberOfComponents(4);
  texels->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  const std::uint32_t sequence = static_cast<std::uint32_t>(this->Seed) * 2654435761U + 12345U;
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(n) * n; ++t)
  {
    const std::uint32_t index = 3U * static_cast<std::uint32_t>(t);
    // Uniform on the sphere: z uniform in [-1, 1], longitude uniform.
    const double z = 2.0 * vtkIceNoise::Uniform(sequence, index) - 1.0;
    const double phi = 2.0 * vtkMath::Pi() * vtkIceNoise::Uniform(sequence, index + 1U);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    texels->SetTypedComponent(t, 0, Encode(r * std::cos(phi)));
    texels->SetTypedComponent(t, 1, Encode(r * std::sin(phi)));
    texels->SetTypedComponent(t, 2, Encode(z));
    texels->SetTypedComponent(t, 3, Encode(2.0 * vtkIceNoise::Uniform(sequence, index + 2U) - 1.0));
  }
  this->Image = vtkSmartPointer<vtkImageData>::New();
  this->Image->SetDimensions(n, n, 1);
  this->Image->GetPointData()->SetScalars(texels);
  this->ImageTime = this->GetMTime();
  return this->Image;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceGlisteningTexture::GetTextureObject(vtkOpenGLRenderWindow* window)
{
  vtkImageData* image = this->GetImage();
  if (this->TextureObject && this->TextureObject->GetContext() == window &&
    this->TextureObject->GetHandle() != 0 && this->TextureTime >= this->ImageTime)
  {
    return this->TextureObject;
  }
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->TextureObject->SetContext(window);
  this->TextureObject->SetMinificationFilter(vtkTextureObject::Nearest);
  this->TextureObject->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->TextureObject->SetWrapS(vtkTextureObject::Repeat);
  this->TextureObject->SetWrapT(vtkTextureObject::Repeat);
  this->TextureObject->SetGenerateMipmap(false);
  this->TextureObject->Create2DFromRaw(static_cast<unsigned int>(this->Size),
    static_cast<unsigned int>(this->Size), 4, VTK_UNSIGNED_CHAR,
    image->GetPointData()->GetScalars()->GetVoidPointer(0));
  this->TextureTime = this->ImageTime;
  return this->TextureObject;
}

//------------------------------------------------------------------------------
void vtkIceGlisteningTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkIceGlisteningTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
