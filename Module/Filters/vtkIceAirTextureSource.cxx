// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceAirTextureSource.h"

#include "vtkIceNoise.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkIceAirTextureSource);

namespace
{
// Bubbles of one tile: count, radius range (fractions of the tile; small ones more often than
// large), how much longer than wide along the tile's v axis, and clustering.
struct TileStyle
{
  int Count;
  double MinRadius;
  double MaxRadius;
  double MinStretch;
  double MaxStretch;
  bool Clustered;
};
const TileStyle Styles[4] = {
  { 900, 0.004, 0.010, 1.0, 1.3, false }, // fine, dense
  { 220, 0.010, 0.025, 1.0, 1.3, false }, // small
  { 120, 0.005, 0.012, 2.0, 3.5, false }, // tubes, long along v (vtkIceAirGeometry::Placement)
  { 400, 0.005, 0.020, 1.0, 1.5, true },  // clusters
};

// Coverage (alpha) of a bubble at normalised distance d from its centre (d = 1 at the rim):
// a bright rim, a thin interior and a highlight on the upper left.
double BubbleAlpha(double d, double dx, double dy)
{
  if (d >= 1.0)
  {
    return 0.0;
  }
  const double rim = std::exp(-std::pow((1.0 - d) / 0.18, 2.0));
  const double highlight =
    std::exp(-((dx + 0.35) * (dx + 0.35) + (dy - 0.35) * (dy - 0.35)) / 0.02);
  return std::min(1.0, 0.15 + 0.75 * rim + 0.8 * highlight);
}
}

//------------------------------------------------------------------------------
vtkIceAirTextureSource::vtkIceAirTextureSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkIceAirTextureSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, this->Size - 1, 0, this->Size - 1, 0, 0 };
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_UNSIGNED_CHAR, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkIceAirTextureSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(outputVector);
  const int size = this->Size;
  const int tile = size / 2;
  image->SetDimensions(size, size, 1);
  std::vector<double> alpha(static_cast<size_t>(size) * size, 0.0);
  const std::uint32_t seed = static_cast<std::uint32_t>(this->Seed);
  std::uint32_t draw = 0;
  auto uniform = [seed, &draw]() { return vtkIceNoise::Uniform(seed, draw++); };

  for (int t = 0; t < 4; ++t)
  {
    const TileStyle& style = Styles[t];
    const int x0 = (t % 2) * tile;
    const int y0 = (t / 2) * tile;
    // Faint cloudy haze so stacked planes turn the ice milky (rows in parallel: the noise is a
    // pure function of the position).
    vtkSMPTools::For(0, tile, [&](int firstRow, int endRow) {
      for (int j = firstRow; j < endRow; ++j)
      {
        for (int i = 0; i < tile; ++i)
        {
          const double p[3] = { 6.0 * i / tile, 6.0 * j / tile, 0.37 * t };
          const double haze = 0.06 * (0.5 + 0.5 * vtkIceNoise::FractalNoise(p, seed + 101));
          alpha[static_cast<size_t>(y0 + j) * size + x0 + i] = haze;
        }
      }
    });
    double clusterX = 0.5;
    double clusterY = 0.5;
    for (int b = 0; b < style.Count; ++b)
    {
      if (style.Clustered && b % 40 == 0)
      {
        clusterX = 0.2 + 0.6 * uniform();
        clusterY = 0.2 + 0.6 * uniform();
      }
      const double spread = style.Clustered ? 0.12 : 0.5;
      // Bubbles keep a margin from the tile edge so mip-mapping does not bleed between tiles.
      const double cx = std::min(0.94,
        std::max(0.06, (style.Clustered ? clusterX : 0.5) + spread * (2.0 * uniform() - 1.0)));
      const double cy = std::min(0.94,
        std::max(0.06, (style.Clustered ? clusterY : 0.5) + spread * (2.0 * uniform() - 1.0)));
      const double r =
        style.MinRadius + (style.MaxRadius - style.MinRadius) * uniform() * uniform();
      const double length =
        r * (style.MinStretch + (style.MaxStretch - style.MinStretch) * uniform());
      const int radiusPixels = static_cast<int>(std::ceil(r * tile)) + 1;
      const int lengthPixels = static_cast<int>(std::ceil(length * tile)) + 1;
      const int ci = static_cast<int>(cx * tile);
      const int cj = static_cast<int>(cy * tile);
      for (int j = std::max(0, cj - lengthPixels); j <= std::min(tile - 1, cj + lengthPixels); ++j)
      {
        for (int i = std::max(0, ci - radiusPixels); i <= std::min(tile - 1, ci + radiusPixels);
             ++i)
        {
          const double dx = ((i + 0.5) / tile - cx) / r;
          const double dy = ((j + 0.5) / tile - cy) / length;
          const double a = BubbleAlpha(std::sqrt(dx * dx + dy * dy), dx, dy);
          double& target = alpha[(y0 + j) * size + x0 + i];
          target = 1.0 - (1.0 - target) * (1.0 - a);
        }
      }
    }
  }

  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetName("AirBubbles");
  pixels->SetNumberOfComponents(4);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(size) * size; ++p)
  {
    // Bubbles scatter light: near white, faintly blue in the thin parts.
    const double a = alpha[p];
    const unsigned char rgba[4] = { static_cast<unsigned char>(235 + 20 * a),
      static_cast<unsigned char>(242 + 13 * a), 255,
      static_cast<unsigned char>(std::lround(255.0 * a)) };
    pixels->SetTypedTuple(p, rgba);
  }
  image->GetPointData()->SetScalars(pixels);
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceAirTextureSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
