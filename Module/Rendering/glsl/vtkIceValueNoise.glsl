// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// Value noise on the integer lattice, for bumps fixed in an object's own space.
float iceHash(vec3 p)
{
  p = fract(p * 0.1031 + vec3(0.13, 0.71, 0.37));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

// The gradient of value noise on the integer lattice (trilinear between hashed corners, eased
// by 3f^2 - 2f^3), from the same eight corners the value needs: the derivative of the easing
// times the trilinear form's slopes, instead of six evaluations of central differences.
vec3 iceValueNoiseGradient(vec3 x)
{
  vec3 i = floor(x);
  vec3 f = fract(x);
  vec3 u = f * f * (3.0 - 2.0 * f);
  vec3 du = 6.0 * f * (1.0 - f);
  float a = iceHash(i);
  float b = iceHash(i + vec3(1, 0, 0));
  float c = iceHash(i + vec3(0, 1, 0));
  float d = iceHash(i + vec3(1, 1, 0));
  float e = iceHash(i + vec3(0, 0, 1));
  float g = iceHash(i + vec3(1, 0, 1));
  float h = iceHash(i + vec3(0, 1, 1));
  float k = iceHash(i + vec3(1, 1, 1));
  // value = a + bx ux + by uy + bz uz + bxy ux uy + byz uy uz + bxz ux uz + bxyz ux uy uz
  float bx = b - a;
  float by = c - a;
  float bz = e - a;
  float bxy = a - b - c + d;
  float byz = a - c - e + h;
  float bxz = a - b - e + g;
  float bxyz = -a + b + c - d + e - g - h + k;
  return du * vec3(bx + bxy * u.y + bxz * u.z + bxyz * u.y * u.z,
                by + bxy * u.x + byz * u.z + bxyz * u.x * u.z,
                bz + byz * u.y + bxz * u.x + bxyz * u.x * u.y);
}

// Gradient of two octaves of value noise.
vec3 iceNoiseGradient(vec3 p)
{
  vec3 g = vec3(0.0);
  float amplitude = 1.0;
  for (int octave = 0; octave < 2; ++octave)
  {
    // Each octave's slope in its own coordinates: the finer one tilts half as much.
    g += amplitude * iceValueNoiseGradient(p);
    p = 2.03 * p + vec3(17.0, 5.0, 11.0);
    amplitude *= 0.5;
  }
  return g;
}

// Tilts the unit normal n against gradient g (both in the same space) by `strength`.
vec3 iceBumpNormal(vec3 n, vec3 g, float strength)
{
  return normalize(n - strength * (g - dot(g, n) * n));
}
