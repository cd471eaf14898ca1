// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceNoise.h"

#include "vtkMath.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>

namespace vtkIceNoise
{
namespace
{
// Integer hashing keeps the noise identical on every platform for a seed
// (std:: distributions are implementation defined).
std::uint32_t MixBits(std::uint32_t h)
{
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

std::uint32_t HashLattice(int x, int y, int z, std::uint32_t seed)
{
  std::uint32_t h = MixBits(seed ^ 0x9e3779b9U);
  h = MixBits(h ^ static_cast<std::uint32_t>(x));
  h = MixBits(h ^ static_cast<std::uint32_t>(y));
  return MixBits(h ^ static_cast<std::uint32_t>(z));
}

double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double Lerp(double a, double b, double t)
{
  return a + t * (b - a);
}

// Gradient noise with values in about [-1, 1].
double GradientNoise(const double p[3], std::uint32_t seed)
{
  static const double gradients[12][3] = { { 1, 1, 0 }, { -1, 1, 0 }, { 1, -1, 0 }, { -1, -1, 0 },
    { 1, 0, 1 }, { -1, 0, 1 }, { 1, 0, -1 }, { -1, 0, -1 }, { 0, 1, 1 }, { 0, -1, 1 }, { 0, 1, -1 },
    { 0, -1, -1 } };

  int cell[3];
  double f[3];
  for (int c = 0; c < 3; ++c)
  {
    const double fl = std::floor(p[c]);
    cell[c] = static_cast<int>(fl);
    f[c] = p[c] - fl;
  }

  double value[2][2][2];
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int k = 0; k < 2; ++k)
      {
        const double* g = gradients[HashLattice(cell[0] + i, cell[1] + j, cell[2] + k, seed) % 12];
        value[i][j][k] = g[0] * (f[0] - i) + g[1] * (f[1] - j) + g[2] * (f[2] - k);
      }
    }
  }

  const double wx = Fade(f[0]);
  const double wy = Fade(f[1]);
  const double wz = Fade(f[2]);
  const double y0 =
    Lerp(Lerp(value[0][0][0], value[1][0][0], wx), Lerp(value[0][1][0], value[1][1][0], wx), wy);
  const double y1 =
    Lerp(Lerp(value[0][0][1], value[1][0][1], wx), Lerp(value[0][1][1], value[1][1][1], wx), wy);
  return Lerp(y0, y1, wz);
}

}

double Uniform(std::uint32_t seed, std::uint32_t index)
{
  return HashLattice(static_cast<int>(index), 0x51ed, 0x2f0b, seed) / 4294967296.0;
}

// A few octaves of gradient noise, normalized to about [-1, 1]. Each octave
// gets its own lattice hash and a random offset so that the lattices do not
// line up with each other or with the cube.
double FractalNoise(const double p[3], std::uint32_t seed)
{
  const int octaves = 4;
  double frequency = 1.5;
  double amplitude = 1.0;
  double sum = 0.0;
  double norm = 0.0;
  for (int octave = 0; octave < octaves; ++octave)
  {
    const std::uint32_t octaveSeed =
      MixBits(seed + 0x632be5abU * static_cast<std::uint32_t>(octave));
    double q[3];
    for (int c = 0; c < 3; ++c)
    {
      const double offset = 256.0 * (HashLattice(c, octave, 0, octaveSeed) / 4294967296.0);
      q[c] = frequency * p[c] + offset;
    }
    sum += amplitude * GradientNoise(q, octaveSeed);
    norm += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / norm;
}

//------------------------------------------------------------------------------
void RandomPlacement(std::uint32_t sequence, int index, const double bounds[6], double spread,
  double minScale, double maxScale, vtkTransform* placement, double center[3])
{
  double u[7];
  for (int k = 0; k < 7; ++k)
  {
    u[k] = Uniform(sequence, static_cast<std::uint32_t>(7 * index + k));
  }
  const double z = 2.0 * u[0] - 1.0;
  const double phi = 2.0 * vtkMath::Pi() * u[1];
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double extent = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double size = bounds[2 * c + 1] - bounds[2 * c];
    center[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]) + spread * (u[3 + c] - 0.5) * size;
    extent = std::max(extent, size);
  }
  placement->Identity();
  placement->Translate(center);
  placement->RotateWXYZ(360.0 * u[2], r * std::cos(phi), r * std::sin(phi), z);
  const double scale = extent * (minScale + (maxScale - minScale) * u[6]);
  placement->Scale(scale, scale, scale);
}
}
