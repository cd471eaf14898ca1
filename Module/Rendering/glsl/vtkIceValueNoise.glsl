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

float iceValueNoise(vec3 x)
{
  vec3 i = floor(x);
  vec3 f = fract(x);
  f = f * f * (3.0 - 2.0 * f);
  float a = mix(iceHash(i), iceHash(i + vec3(1, 0, 0)), f.x);
  float b = mix(iceHash(i + vec3(0, 1, 0)), iceHash(i + vec3(1, 1, 0)), f.x);
  float c = mix(iceHash(i + vec3(0, 0, 1)), iceHash(i + vec3(1, 0, 1)), f.x);
  float d = mix(iceHash(i + vec3(0, 1, 1)), iceHash(i + vec3(1, 1, 1)), f.x);
  return mix(mix(a, b, f.y), mix(c, d, f.y), f.z);
}

// Gradient of two octaves of value noise, by central differences.
vec3 iceNoiseGradient(vec3 p)
{
  const float h = 0.05;
  vec3 g = vec3(0.0);
  float amplitude = 1.0;
  for (int octave = 0; octave < 2; ++octave)
  {
    g += amplitude * vec3(
      iceValueNoise(p + vec3(h, 0, 0)) - iceValueNoise(p - vec3(h, 0, 0)),
      iceValueNoise(p + vec3(0, h, 0)) - iceValueNoise(p - vec3(0, h, 0)),
      iceValueNoise(p + vec3(0, 0, h)) - iceValueNoise(p - vec3(0, 0, h))) / (2.0 * h);
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
