// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCubeMapSource.h"
#include "vtkIceVTKCompat.h"
#include "vtkIceCubeMapTexture.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkIceCubeMapSource);

namespace
{
constexpr int NumberOfFaces = vtkIceCubeMapTexture::NumberOfFaces;

double Smooth(double edge0, double edge1, double x)
{
  const double t = std::min(1.0, std::max(0.0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3.0 - 2.0 * t);
}

void Mix(const double a[3], const double b[3], double t, double out[3])
{
  for (int c = 0; c < 3; ++c)
  {
    out[c] = a[c] + (b[c] - a[c]) * t;
  }
}

// Smooth, distinct on every face, and steep enough that a direction error of a few
// milliradians changes the colour measurably.
void DirectionTestColor(const double d[3], double rgb[3])
{
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = 0.5 + 0.45 * std::sin(4.0 * d[c] + c);
  }
}

// A sky with a sun above a ring of snowy mountains and a checkered plain, +Y up.
void SkyColor(const double d[3], double rgb[3])
{
  const double zenith[3] = { 0.18, 0.38, 0.78 };
  const double horizon[3] = { 0.78, 0.86, 0.95 };
  const double haze[3] = { 0.72, 0.78, 0.84 };
  const double rock[3] = { 0.32, 0.36, 0.45 };
  const double snow[3] = { 0.95, 0.96, 0.98 };
  const double fieldA[3] = { 0.30, 0.46, 0.28 };
  const double fieldB[3] = { 0.82, 0.84, 0.76 };

  const double elevation = d[1];
  const double azimuth = std::atan2(d[2], d[0]);
  const double ridge = 0.06 + 0.035 * std::sin(3.0 * azimuth + 0.5) +
    0.02 * std::sin(7.0 * azimuth) + 0.01 * std::sin(19.0 * azimuth + 2.0);

  if (elevation >= 0.0)
  {
    double sky[3];
    Mix(horizon, zenith, std::sqrt(std::min(1.0, elevation)), sky);
    const double sun[3] = { 0.45, 0.55, -0.70 };
    const double cosSun = vtkMath::Dot(d, sun) / vtkMath::Norm(sun);
    const double disk = Smooth(0.9985, 0.9992, cosSun);
    const double glow = 0.35 * std::pow(std::max(0.0, cosSun), 64.0);
    for (int c = 0; c < 3; ++c)
    {
      sky[c] = std::min(1.0, sky[c] + glow + disk);
    }
    // Mountains: rock with snow on the upper part of each peak, a soft skyline.
    double mountain[3];
    Mix(rock, snow, Smooth(0.55, 0.75, elevation / ridge), mountain);
    Mix(mountain, haze, 0.25, mountain);
    Mix(mountain, sky, Smooth(ridge - 0.004, ridge + 0.004, elevation), rgb);
  }
  else
  {
    // Ground plane one unit below the eye with a checker of 0.5 units, its edges softened by
    // the footprint of a texel on the plane (about t^2 texel angles) so it does not alias.
    const double t = 1.0 / std::max(-elevation, 1e-6);
    const double x = 2.0 * d[0] * t;
    const double z = 2.0 * d[2] * t;
    const double footprint = 0.004 * t * t;
    auto square = [footprint](double u) {
      return std::min(
        1.0, std::max(-1.0, std::sin(vtkMath::Pi() * u) / (vtkMath::Pi() * footprint)));
    };
    double ground[3];
    Mix(fieldA, fieldB, 0.5 + 0.5 * square(x) * square(z), ground);
    Mix(ground, haze, 1.0 - std::exp(-0.08 * t), rgb);
  }
}
}

//------------------------------------------------------------------------------
vtkIceCubeMapSource::vtkIceCubeMapSource()
  : Pattern(Sky)
  , FaceSize(256)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(NumberOfFaces);
}

//------------------------------------------------------------------------------
void vtkIceCubeMapSource::Evaluate(const double dir[3], double rgb[3]) const
{
  double d[3] = { dir[0], dir[1], dir[2] };
  if (vtkMath::Normalize(d) == 0.0)
  {
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    return;
  }
  if (this->Pattern == DirectionTest)
  {
    DirectionTestColor(d, rgb);
  }
  else
  {
    SkyColor(d, rgb);
  }
}

//------------------------------------------------------------------------------
void vtkIceCubeMapSource::TexelDirection(int face, int i, int j, int size, double dir[3])
{
  // Texel centre in [-1, 1]; (s, t) as in the OpenGL specification's cube map table.
  const double s = 2.0 * (i + 0.5) / size - 1.0;
  const double t = 2.0 * (j + 0.5) / size - 1.0;
  switch (face)
  {
    case 0:
      dir[0] = 1.0;
      dir[1] = -t;
      dir[2] = -s;
      break;
    case 1:
      dir[0] = -1.0;
      dir[1] = -t;
      dir[2] = s;
      break;
    case 2:
      dir[0] = s;
      dir[1] = 1.0;
      dir[2] = t;
      break;
    case 3:
      dir[0] = s;
      dir[1] = -1.0;
      dir[2] = -t;
      break;
    case 4:
      dir[0] = s;
      dir[1] = -t;
      dir[2] = 1.0;
      break;
    default:
      dir[0] = -s;
      dir[1] = -t;
      dir[2] = -1.0;
      break;
  }
  // The faces hold the world as this VTK's skybox and environment lookups show it, so a pattern
  // (and a panorama read into faces) looks the same in every VTK version.
  vtkIceVTKCompat::CubeMapTexelToWorld(dir);
}

//------------------------------------------------------------------------------
void vtkIceCubeMapSource::ConfigureTexture(vtkTexture* texture)
{
  vtkIceCubeMapTexture::Configure(texture, this);
}

//------------------------------------------------------------------------------
int vtkIceCubeMapSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkIceCubeMapTexture::SetFaceInformation(outputVector, this->FaceSize, VTK_UNSIGNED_CHAR);
  return 1;
}

//------------------------------------------------------------------------------
int vtkIceCubeMapSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int size = this->FaceSize;
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    vtkImageData* image = vtkImageData::GetData(outputVector, face);
    image->SetDimensions(size, size, 1);
    vtkNew<vtkUnsignedCharArray> pixels;
    pixels->SetName("CubeFace");
    pixels->SetNumberOfComponents(3);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
    unsigned char* texels = pixels->GetPointer(0);
    // Rows in parallel: Evaluate is a pure function of the direction.
    vtkSMPTools::For(0, size, [&](int firstRow, int endRow) {
      unsigned char* out = texels + 3 * static_cast<size_t>(firstRow) * size;
      for (int j = firstRow; j < endRow; ++j)
      {
        for (int i = 0; i < size; ++i)
        {
          double dir[3];
          double rgb[3];
          TexelDirection(face, i, j, size, dir);
          this->Evaluate(dir, rgb);
          for (int c = 0; c < 3; ++c)
          {
            *out++ =
              static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, rgb[c]))));
          }
        }
      }
    });
    image->GetPointData()->SetScalars(pixels);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceCubeMapSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Pattern: " << (this->Pattern == Sky ? "Sky" : "DirectionTest") << "\n";
  os << indent << "FaceSize: " << this->FaceSize << "\n";
}
