// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Seeded noise shared by the procedural sources: the same seed gives the same numbers on every
// platform (integer hashing, unlike std:: distributions, is not implementation defined).
#ifndef vtkIceNoise_h
#define vtkIceNoise_h

#include "FiltersIceModule.h" // for export macro

#include <cstdint>

class vtkTransform;

namespace vtkIceNoise
{
// A few octaves of gradient noise at `p`, about [-1, 1], smooth in p.
FILTERSICE_EXPORT double FractalNoise(const double p[3], std::uint32_t seed);

// A uniform number in [0, 1), the `index`-th of the sequence of `seed`.
FILTERSICE_EXPORT double Uniform(std::uint32_t seed, std::uint32_t index);

// Random placement `index` of `sequence` inside `bounds`, set on `placement`: a random
// orientation (axis uniform on the sphere), the centre within the middle `spread` fraction of the
// bounds, a uniform scale between minScale and maxScale times the largest extent. Writes the
// centre.
FILTERSICE_EXPORT void RandomPlacement(std::uint32_t sequence, int index, const double bounds[6], double spread,
  double minScale, double maxScale, vtkTransform* placement, double center[3]);
}

#endif
