// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// Glistening ice and snow after Tobias Zirr, "Rendering Ice in Liquidiced": direct light (Phong
// with a very broad, soft specular, both on a subtle wavy bump), rim light, and two layers of
// crack glints from a random normal texture. Everything is in world space; VTK's light uniforms
// (view space) are turned into world directions. Injected at the ice shader's Glistening hook,
// where gl_FragData[0].rgb holds the ice colour.
uniform sampler2D iceGlisteningNoise;     // vtkIceGlisteningTexture: unit vector (RGB), number (A)
uniform float iceGlisteningScale;         // crack cell size, model units
uniform float iceGlisteningIntensity;     // glint brightness
uniform float iceGlisteningAlignmentGain; // glint gain where the view looks along the light
uniform float iceSnowAmount;              // 0: ice, 1: snow

const float iceSoftSpecularPower = 6.0; // the broad, soft specular of the direct light
const float iceGlintPowerA = 250.0;     // a crack reflects the light into a narrow cone; the
const float iceGlintPowerB = 60.0;      // random layer's cones are wider, its normals sparser
const float iceCrackTilt = 0.35;        // layer 1: how far cracks lean from the surface

// The fragment as the lights see it (world space; vectors point away from the surface).
struct IceGlisteningSurface
{
  vec3 normal; // geometric normal, facing the viewer's side
  vec3 wavy;   // normal with the wavy bump
  vec3 toEye;
  vec3 crackA; // layer 1: cracks roughly parallel to the surface
  vec3 crackB; // layer 2: cracks of any orientation
  float shineA;
  float shineB;
};

// What the lights add up to.
struct IceGlisteningSums
{
  vec3 diffuse;
  vec3 specular; // broad and soft
  vec3 rim;
  vec3 glints;
};

// Integer hash of a lattice cell and a layer (cells are offset to be positive: the conversion of
// negative ints to uint is not defined by every GLSL version).
uint iceGlisteningHash(ivec3 cell, uint layer)
{
  uvec3 u = uvec3(cell + ivec3(8388608));
  uint h = layer * 0x9e3779b9u + 0x7f4a7c15u;
  h = (h ^ u.x) * 0x85ebca6bu;
  h ^= h >> 13;
  h = (h ^ u.y) * 0xc2b2ae35u;
  h ^= h >> 16;
  h = (h ^ u.z) * 0x27d4eb2fu;
  h ^= h >> 15;
  h *= 0x2545f491u;
  h ^= h >> 14;
  return h;
}

// The texel of the random normal texture that belongs to a cell: fetched, never filtered.
vec4 iceGlisteningTexel(ivec3 cell, uint layer)
{
  int size = textureSize(iceGlisteningNoise, 0).x; // a power of two
  uint h = iceGlisteningHash(cell, layer);
  ivec2 texel = ivec2(int(h & uint(size - 1)), int((h >> 16u) & uint(size - 1)));
  return texelFetch(iceGlisteningNoise, texel, 0);
}

// A smooth displacement field from the same texture (its vectors interpolated between lattice
// points), components within [-1, 1].
vec3 iceGlisteningWarp(vec3 q, uint layer)
{
  vec3 base = floor(q);
  vec3 f = q - base;
  f = f * f * (3.0 - 2.0 * f);
  ivec3 cell = ivec3(base);
  vec3 w = vec3(0.0);
  for (int k = 0; k < 8; ++k)
  {
    ivec3 corner = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    vec3 weight = mix(1.0 - f, f, vec3(corner));
    vec3 v = 2.0 * iceGlisteningTexel(cell + corner, layer).rgb - 1.0;
    w += weight.x * weight.y * weight.z * v;
  }
  return w;
}

// The crack of one layer at model position p: the texel of the cell of a rotated lattice (so no
// flat face of the model lines up with cell faces) whose coordinates are displaced by the warp
// field, so that cells are irregular, not square. Nearest-neighbour cells: one crack per cell.
vec4 iceGlisteningCrack(vec3 p, mat3 rotation, float cellSize, uint layer)
{
  vec3 q = rotation * p / cellSize;
  q += 0.6 * iceGlisteningWarp(0.4 * q, layer + 16u);
  return iceGlisteningTexel(ivec3(floor(q)), layer);
}

// The normal tilted by three crossing sine waves fixed to the surface, slope 0.05 each, wave
// lengths 40, 27 and 17 crack cells. A wave whose phase changes by more than about a radian per
// pixel fades out, so the bump never turns into noise in the distance.
vec3 iceGlisteningWavyNormal(vec3 p, vec3 n, mat3 gradientToWorld)
{
  const vec3 directions[3] = vec3[3](vec3(0.8, 0.1, 0.59), vec3(-0.3, 0.7, 0.65),
    vec3(0.2, -0.9, 0.39));
  const float lengths[3] = float[3](40.0, 27.0, 17.0);
  vec3 gradient = vec3(0.0);
  for (int i = 0; i < 3; ++i)
  {
    vec3 d = normalize(directions[i]);
    float phase = 6.2831853 * dot(d, p) / (lengths[i] * iceGlisteningScale);
    float fade = 1.0 - smoothstep(0.5, 1.5, fwidth(phase));
    gradient += 0.05 * fade * cos(phase) * d;
  }
  gradient = gradientToWorld * gradient;
  gradient -= dot(gradient, n) * n;
  return normalize(n - gradient);
}

// Light from the environment for the snow's ambient term: six axis samples, each weighted by a
// broad lobe around the normal.
vec3 iceGlisteningAmbient(vec3 n)
{
  const vec3 axes[6] = vec3[6](vec3(1.0, 0.0, 0.0), vec3(-1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0),
    vec3(0.0, -1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, -1.0));
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    float w = 0.5 + 0.5 * dot(n, axes[i]);
    w *= w;
    sum += w * iceEnvironmentColor(axes[i]);
    weights += w;
  }
  return sum / weights;
}

// One light: l points from the surface to the light, radiance is its colour times intensity.
void iceGlisteningAddLight(
  IceGlisteningSurface s, vec3 l, vec3 radiance, inout IceGlisteningSums sums)
{
  // Direct light: Lambert and a broad, soft Phong specular, both on the wavy normal.
  float nl = dot(s.wavy, l);
  sums.diffuse += max(nl, 0.0) * radiance;
  sums.specular += clamp(4.0 * nl, 0.0, 1.0) *
    pow(max(dot(reflect(-l, s.wavy), s.toEye), 0.0), iceSoftSpecularPower) * radiance;

  // Rim light 1 - |n.(-l)|, attenuated by the Fresnel term (1 - n.v)^8 and by the angle between
  // the light's direction of travel (-l) and the direction to the eye: strongest against the light.
  float fresnel = pow(1.0 - clamp(dot(s.wavy, s.toEye), 0.0, 1.0), 8.0);
  float against = max(dot(-l, s.toEye), 0.0);
  sums.rim += 0.5 * (1.0 - abs(dot(s.wavy, -l))) * fresnel * against * radiance;

  // Glistening: each crack layer is a specular layer of its own, added to the surface's. Where
  // the view looks along the light (the light behind the viewer) the surface specular and the
  // parallel layer are gone, so the glints get AlignmentGain (2: doubled, as in Liquidiced).
  float lit = smoothstep(-0.05, 0.1, dot(s.normal, l));
  float glintA = s.shineA *
    smoothstep(0.2, 0.7, pow(max(dot(reflect(-l, s.crackA), s.toEye), 0.0), iceGlintPowerA));
  float glintB = s.shineB *
    smoothstep(0.2, 0.7, pow(max(dot(reflect(-l, s.crackB), s.toEye), 0.0), iceGlintPowerB));
  float aligned = smoothstep(0.7, 0.95, dot(l, s.toEye)); // full within 18 degrees, none beyond 45
  float gain = mix(1.0, iceGlisteningAlignmentGain, aligned);
  sums.glints += gain * lit * (glintA + glintB) * radiance;
}

// A light of VTK's positional light loop (complexity 3): positional lights with VTK's attenuation
// and spot cone, the others directional.
void iceGlisteningAddSceneLight(IceGlisteningSurface s, vec3 position, int positional,
  vec3 directionVC, vec3 positionVC, vec3 attenuation, float coneAngle, float exponent,
  vec3 radiance, inout IceGlisteningSums sums)
{
  vec3 travel = normalize(mat3(iceVCWCMatrix) * directionVC);
  if (positional == 0)
  {
    iceGlisteningAddLight(s, -travel, radiance, sums);
    return;
  }
  vec3 toLight = (iceVCWCMatrix * vec4(positionVC, 1.0)).xyz - position;
  float range = length(toLight);
  vec3 l = toLight / max(range, 1e-20);
  float factor = 1.0 / (attenuation.x + attenuation.y * range + attenuation.z * range * range);
  if (coneAngle < 90.0)
  {
    float coneDot = dot(-l, travel);
    factor = coneDot >= cos(radians(coneAngle)) ? factor * pow(coneDot, exponent) : 0.0;
  }
  iceGlisteningAddLight(s, l, factor * radiance, sums);
}
//ICE::Impl
    {
      IceGlisteningSurface glisten;
      glisten.normal = normalize(iceNormalWCVSOutput);
      if (gl_FrontFacing == false) { glisten.normal = -glisten.normal; }
      glisten.toEye = -iceEyeVectorWC(icePositionWCVSOutput);
      vec3 glistenMC = (iceWCMCMatrix * vec4(icePositionWCVSOutput, 1.0)).xyz;
      // Model-space gradients and normals to world space (the inverse transpose of model to world).
      mat3 glistenToWorld = transpose(mat3(iceWCMCMatrix));
      glisten.wavy = iceGlisteningWavyNormal(glistenMC, glisten.normal, glistenToWorld);

      // Crispness: the crack of the cell under the pixel's centre is used, whatever the number of
      // cells in the pixel's footprint. Averaging the footprint (mip-mapping, filtering) smudges
      // distant glints into a flat, dim specular; taking the brightest cell of the footprint makes
      // glints ever denser with distance (and costs a loop). One cell per pixel is a one-sample
      // estimate of the footprint's average: on average the brightness is the filtered one, and
      // what filtering would average away stays visible as full-strength, one-pixel glints; about
      // the same fraction of pixels glints near and far. Up close a cell covers many pixels: a
      // flat crack facet that glints as a whole, not per-pixel noise.
      const mat3 glistenLatticeA = mat3(0.69060, 0.45745, -0.56019, -0.15211, 0.84910, 0.50585,
        0.70706, -0.26413, 0.65597);
      const mat3 glistenLatticeB = mat3(0.02231, 0.35385, -0.93504, -0.87286, -0.44912, -0.19079,
        -0.48745, 0.82042, 0.29884);
      vec4 crackA = iceGlisteningCrack(glistenMC, glistenLatticeA, iceGlisteningScale, 1u);
      vec4 crackB = iceGlisteningCrack(glistenMC, glistenLatticeB, 0.8 * iceGlisteningScale, 2u);
      vec3 leanA = glistenToWorld * (2.0 * crackA.rgb - 1.0);
      glisten.crackA = normalize(glisten.normal + iceCrackTilt * normalize(leanA));
      glisten.crackB = normalize(glistenToWorld * (2.0 * crackB.rgb - 1.0));
      // A crack reflects on both of its faces.
      if (dot(glisten.crackB, glisten.toEye) < 0.0) { glisten.crackB = -glisten.crackB; }
      glisten.shineA = 0.5 + crackA.a;
      glisten.shineB = 0.5 + crackB.a;

      IceGlisteningSums glistenSums = IceGlisteningSums(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
      //ICEHOOK::GlisteningLights

      // Ice: the environment (refraction and reflection) with the soft specular, a little diffuse
      // light and the rim. Snow: white (only a hint of IceColor), diffuse (environment ambient plus
      // the lights), a weaker specular, the rim. The glints go on both.
      vec3 iceLook = gl_FragData[0].rgb + 0.35 * glistenSums.specular +
        0.08 * iceTint * glistenSums.diffuse + glistenSums.rim;
      vec3 snowAlbedo = 0.85 * mix(vec3(1.0), iceTint, 0.3);
      vec3 snowLight = 0.6 * iceGlisteningAmbient(glisten.wavy) + 0.7 * glistenSums.diffuse;
      vec3 snowLook = snowAlbedo * snowLight + 0.2 * glistenSums.specular + glistenSums.rim;
      gl_FragData[0].rgb = mix(iceLook, snowLook, iceSnowAmount) +
        iceGlisteningIntensity * glistenSums.glints;
    }
