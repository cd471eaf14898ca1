// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The environment as a rough (frosted) surface shows it, for vtkIcePrefilteredEnvironment: level k
// of the result holds, per direction n, the environment averaged over the GGX lobe of roughness
// k / (levels - 1) around n, the view taken along n. Its CPU mirror is the brute-force integral
// vtkIceOpticsReference::PrefilteredEnvironment (TestIceRoughness compares the two).
uniform samplerCube iceSource;
uniform int iceFace;
uniform float iceTargetSize;  // texels per edge of the face being written
uniform float iceSourceSize;  // texels per edge of the source's level 0
uniform float iceRoughness;
uniform int iceSampleCount;
const float iceTwoPi = 6.28318530717959;

// The OpenGL cube-map direction through texture coordinates `st` ([0, 1]^2) of `face`
// (+X -X +Y -Y +Z -Z), as the specification's face table maps directions to (s, t).
vec3 iceFaceDirection(int face, vec2 st)
{
  vec2 c = 2.0 * st - 1.0;
  if (face == 0) { return vec3(1.0, -c.y, -c.x); }
  if (face == 1) { return vec3(-1.0, -c.y, c.x); }
  if (face == 2) { return vec3(c.x, 1.0, c.y); }
  if (face == 3) { return vec3(c.x, -1.0, -c.y); }
  if (face == 4) { return vec3(c.x, -c.y, 1.0); }
  return vec3(-c.x, -c.y, -1.0);
}

// i's binary digits mirrored behind the point: the second coordinate of the Hammersley set, which
// spreads the lobe's samples evenly.
float iceRadicalInverse(int i)
{
  float value = 0.0;
  float digit = 0.5;
  for (int n = i; n > 0; n /= 2)
  {
    value += digit * float(n - 2 * (n / 2));
    digit *= 0.5;
  }
  return value;
}

// GGX's distribution of micro-normals at cos(theta_h) = nDotH, alpha = roughness^2.
float iceGgxDistribution(float nDotH, float alpha2)
{
  float d = nDotH * nDotH * (alpha2 - 1.0) + 1.0;
  return alpha2 / (3.14159265358979 * d * d);
}
//ICE::Copy
  {
    // Level 0: the source resampled to this size, a 4 x 4 grid of lookups per texel.
    vec3 sum = vec3(0.0);
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        vec2 st = texCoord + (vec2(float(i), float(j)) - 1.5) / (4.0 * iceTargetSize);
        sum += textureLod(iceSource, iceFaceDirection(iceFace, st), 0.0).rgb;
      }
    }
    gl_FragData[0] = vec4(sum / 16.0, 1.0);
  }
//ICE::Convolve
  {
    // The lobe's directions by importance: micro-normals h drawn from GGX, each reflecting the
    // view n to l. Each lookup reads the source's mip level whose texels cover the sample's share
    // of the sphere (filtered importance sampling), so few samples leave no speckle.
    vec3 n = normalize(iceFaceDirection(iceFace, texCoord));
    vec3 up = abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 tangent = normalize(cross(up, n));
    vec3 bitangent = cross(n, tangent);
    float alpha = iceRoughness * iceRoughness;
    float alpha2 = alpha * alpha;
    float texelAngle = 4.0 * 3.14159265358979 / (6.0 * iceSourceSize * iceSourceSize);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < iceSampleCount; ++i)
    {
      float u = (float(i) + 0.5) / float(iceSampleCount);
      float phi = iceTwoPi * iceRadicalInverse(i);
      float cosTheta = sqrt((1.0 - u) / (1.0 + (alpha2 - 1.0) * u));
      float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
      vec3 h = tangent * (cos(phi) * sinTheta) + bitangent * (sin(phi) * sinTheta) + n * cosTheta;
      vec3 l = 2.0 * cosTheta * h - n;
      float nDotL = dot(n, l);
      if (nDotL > 0.0)
      {
        // With the view along n the density of l is D(h) / 4.
        float sampleAngle = 4.0 / (float(iceSampleCount) * iceGgxDistribution(cosTheta, alpha2));
        float level = max(0.0, 0.5 * log2(sampleAngle / texelAngle));
        sum += textureLod(iceSource, l, level).rgb * nDotL;
        weight += nDotL;
      }
    }
    gl_FragData[0] = vec4(sum / max(weight, 1.0e-6), 1.0);
  }
