// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The ice's cracks and air along the view ray from a front-surface point to the nearest back face
// (its view depth is in the back-face target's alpha), intersected with the crack sheets of
// vtkIceInteriorTable's table (the cracks of the grid's cells the ray crosses) and with its air
// planes: the air is composited over the ice colour back to front, the cracks' highlights are
// added on top, as the paper's passes composite them. The screen-space step
// (vtkIceScreenInterior) evaluates it once per pixel, the air planes drawn as quads between the
// core behind them and the rest (iceAirPlane), and hands the surface its result.
uniform sampler3D iceInteriorBump;  // periodic noise gradient, 8 noise cells per repeat
uniform sampler2D iceAirAtlas;      // bubble images (RGBA), 2 x 2 tiles
uniform int iceAirCount;            // the next records, back to front for this camera
uniform float iceCrackIntensity;
uniform float iceCrackReflection; // the cracks as sheets: 0 none
uniform float iceCrackBumpStrength;
uniform float iceCrackBumpFrequency; // noise cells per model unit
uniform float iceMilkiness;          // 0: sparse clear bubbles, 1: white and cloudy
uniform int iceInteriorDebug;        // ICE_DEBUG_CRACKS, ICE_DEBUG_AIR or 0
uniform vec3 iceCoreCenter;          // the milky core, model coordinates
uniform vec3 iceCoreScale;           // model to the core's frame (its radius 1), per axis
uniform float iceCoreDensity;        // 0: no core
uniform float iceBubbleDensity;      // 0: no bubbles
uniform float iceBubbleCell;         // the bubbles' grid cell, model units
uniform float iceBubbleFade;         // how much a bubble fades per model unit of ice in front

// The pixel's width at view depth z is icePixelFootprint.x + z * icePixelFootprint.y (world
// units): the screen-space step sets it, so that a bubble smaller than a pixel covers its share
// of the pixel instead of flickering.
vec2 icePixelFootprint = vec2(0.0);

// Three independent numbers in [0, 1) for a grid cell, the same on every GPU.
vec3 iceCellRandom(ivec3 c)
{
  uint h = iceMix(uint(c.x) + iceMix(uint(c.y) + iceMix(uint(c.z))));
  uint a = iceMix(h ^ 0x9e3779b9u);
  uint b = iceMix(a ^ 0x85ebca6bu);
  return vec3(uvec3(h, a, b) >> 8u) * (1.0 / 16777216.0);
}

// Where the bubbles gather, u in the core's frame: 1 at its centre, thinning gradually outwards
// as the core's cloud does (ice freezes from its faces inwards, pushing the air to the middle).
// A Gaussian, as the cloud: a rounded cube's steeper edge (exp(-sum u^4)) showed through the
// faces as the outline of a second, smaller block inside the ice. None where the Gaussian is
// under iceBubbleFloor (beyond iceBubbleReach, 1.73, from the centre): the last freezing water
// holds the air, the shell around it is clear; its sparse bubbles read as glitter sprinkled
// through the ice.
const float iceBubbleFloor = 0.05;
const float iceBubbleReach = sqrt(-log(iceBubbleFloor));
float iceBubbleProfile(vec3 u)
{
  return max(exp(-dot(u, u)) - iceBubbleFloor, 0.0) / (1.0 - iceBubbleFloor);
}

//ICE::Bubbles
// The bubbles along the ray o + s d (model coordinates, s in world units up to sBack), front to
// back through the cells of their grid (one bubble at most in a cell, fully inside it), as
// vec4(add, keep) with the nearest first. A bubble scatters white light, brightest at its rim;
// the ice and the core's cloud in front of it fade it. Rays through a column that holds a stream
// meet bubbles lined up vertically. Also traced (vtkIceTraceFS.glsl) on the segments after a
// reflection inside, with the pixel's footprint carried along the path.
// One grid of cells `cell` wide; `large`: the coarse grid of a few larger bubbles.
vec4 iceBubbleGrid(vec3 o, vec3 d, float sBack, vec3 coreOrigin, vec3 coreDirection,
  float viewDepth, float along, float cell, bool large)
{
  vec4 layer = vec4(0.0, 0.0, 0.0, 1.0);
  float modelPerWorld = length(d);
  vec3 p = o / cell; // in cells
  vec3 v = d / cell;
  IceGridWalk walk = iceGridWalk(p, v, floor(p));
  float sCell = 0.0;
  int i = 0;
  // Tested at the end, as iceNearestCrack's loops: with sBack <= 0 the one step adds nothing.
  do
  {
    ivec3 c = ivec3(walk.cell);
    vec3 column = iceCellRandom(ivec3(c.x, -7919, c.z));
    vec3 r = iceCellRandom(c);
    vec3 more = iceCellRandom(c + ivec3(40503, 0, 0));
    // Streams: small bubbles on the column's axis, drawn out upwards; elsewhere mostly tiny, a
    // few large, some drawn out too (the water froze upwards around them).
    bool stream = !large && column.x < ICE_BUBBLE_STREAMS;
    // The larger ones 1.5 to 3 times the fine grid's largest radius.
    float radius = large ? mix(0.065, 0.13, more.y)
                         : (stream ? mix(0.06, 0.14, more.y) : mix(0.04, 0.3, pow(more.y, 2.0)));
    float stretch = min(stream ? 2.0 : 1.0 + 1.5 * max(more.z - 0.6, 0.0) / 0.4, 0.45 / radius);
    // Anywhere in the cell that keeps the bubble inside it: no grid shows.
    vec3 extent = vec3(radius, radius * stretch, radius);
    vec3 place = vec3(c) + extent + (1.0 - 2.0 * extent) * r;
    if (stream)
    {
      place.xz = vec2(c.xz) + 0.45 + 0.1 * column.yz;
    }
    vec3 u = (place * cell - iceCoreCenter) * iceCoreScale;
    float profile = iceBubbleProfile(u);
    float chance = iceBubbleDensity * (stream ? min(0.7, 2.0 * sqrt(profile)) : profile);
    if (large)
    {
      chance *= ICE_BUBBLE_LARGE_SHARE;
    }
    else if (!stream)
    {
      // Feathers: the cloud's density varies with the direction from its centre, so it runs in
      // streaks towards the centre, as the freezing fronts left it; and in clumps some eight
      // cells across, clear between them. Never every cell, even in the middle: a bubble in each
      // showed the grid's rows wherever a rounded edge magnified them. (Both only where they
      // could matter: at most 1.6 and 1.5 times.)
      if (more.x < min(2.4 * chance, ICE_BUBBLE_FULL))
      {
        float n = textureLod(iceInteriorBump, normalize(u + 1.0e-6) * 0.6, 0.0).x;
        float clump = iceLatticeNoise(0.12 * place + vec3(3.1, 7.7, 1.3));
        chance = min(chance * mix(0.3, 1.6, smoothstep(-0.25, 0.25, n)) *
            mix(0.05, 1.5, smoothstep(0.3, 0.7, clump)), ICE_BUBBLE_FULL);
      }
      else
      {
        chance = 0.0;
      }
    }
    if (more.x < chance)
    {
      // The ray in the bubble's frame, where it is a ball of radius `radius`.
      vec3 squash = vec3(1.0, 1.0 / stretch, 1.0);
      vec3 w = (place - p) * squash;
      vec3 vb = v * squash;
      float sClosest = dot(w, vb) / dot(vb, vb);
      float miss = length(w - sClosest * vb);
      float pixel = 0.5 * max(icePixelFootprint.x + icePixelFootprint.y *
          (viewDepth + sClosest * along), 1.0e-6) * modelPerWorld / cell;
      float cover = clamp((radius + pixel - miss) / (2.0 * pixel), 0.0, 1.0) *
        min(1.0, radius * radius / (pixel * pixel));
      // Small bubbles scatter less of the light that reaches them: dimmer specks. A larger one
      // is a bright ring (the light reflected totally at its rim) around a clearer middle.
      float rim = large ? mix(0.12, 0.9, smoothstep(0.55, 1.0, miss / radius))
                        : mix(0.3, 0.8, smoothstep(0.3, 1.0, miss / radius)) *
          mix(0.45, 1.0, smoothstep(0.04, 0.2, radius));
      float seen = exp(-iceBubbleFade * sClosest * modelPerWorld -
        iceCoreOpticalDepth(coreOrigin, coreDirection, max(sClosest, 0.0), iceCoreDensity));
      float a = sClosest > 0.0 && sClosest < sBack ? cover * rim * seen : 0.0;
      layer.rgb += layer.a * a * ICE_CORE_COLOUR;
      layer.a *= 1.0 - a;
    }
    sCell = iceGridStep(walk);
  } while (++i < 160 && sCell < sBack && layer.a > 0.02);
  return layer;
}

vec4 iceBubbles(vec3 o, vec3 d, float sBack, vec3 coreOrigin, vec3 coreDirection,
  float viewDepth, float along)
{
  if (iceBubbleDensity <= 0.0 || iceInteriorDebug != 0)
  {
    return vec4(0.0, 0.0, 0.0, 1.0);
  }
  vec4 fine = iceBubbleGrid(
    o, d, sBack, coreOrigin, coreDirection, viewDepth, along, iceBubbleCell, false);
  vec4 large = iceBubbleGrid(o, d, sBack, coreOrigin, coreDirection, viewDepth, along,
    ICE_BUBBLE_LARGE_CELLS * iceBubbleCell, true);
  // The two grids' bubbles rarely overlap: the fine ones over the larger.
  return vec4(fine.rgb + fine.a * large.rgb, fine.a * large.a);
}

//ICE::Functions
// The interior as what it does to the ice colour c behind it: c * keep + add, kept as
// vec4(add, keep), since every layer mixes c towards its own colour by a scalar or adds light.
// Layer `colour` over `t` with coverage `a`.
void iceInteriorOver(inout vec4 t, vec3 colour, float a)
{
  t = vec4(mix(t.rgb, colour, a), t.a * (1.0 - a));
}

// The nearest crack seen along the eye ray e (the paper passes' crack program has no
// environment), at its normal n, as a sheet over `t`: it mirrors the environment (`mirrored`:
// what lies along e reflected about n) by `share` of its reflectance, all of it at glancing
// angles (iceCrackReflectance), and its rim (`edge`, 1 at the outline) scatters white light, so
// its outline shows even where it mirrors little.
void iceCrackSheet(inout vec4 t, vec3 e, vec3 n, float edge, float ior, float share,
  vec3 mirrored)
{
  iceInteriorOver(t, mirrored, clamp(share * iceCrackReflectance(dot(e, n), ior), 0.0, 1.0));
  float rim = smoothstep(1.0 - ICE_CRACK_EDGE_WIDTH, 1.0, edge);
  iceInteriorOver(t, ICE_CORE_COLOUR, clamp(share * ICE_CRACK_EDGE * rim, 0.0, 1.0));
}

// Highlights of VTK's lights on a crack at `positionWC` with normal n (facing the viewer).
vec3 iceCrackLight(vec3 n, vec3 toEye, vec3 positionWC)
{
  vec3 light = vec3(0.0);
  //ICEHOOK::InteriorLights
  return light;
}

// The interior behind the front-surface point `positionWC` (`positionMC` in model coordinates,
// `viewDepth` in front of the camera) up to the nearest back face at view depth `backDepth`
// (0: none), as vec4(add, keep) (iceInteriorOver), without the air planes (iceAirPlane). The
// milky core and the bubbles (ICE_INTERIOR_CLOUD) and the cracks (ICE_INTERIOR_CRACKS) are
// compiled in only where the look has them: llvmpipe runs the code of a branch not taken (the
// cloud's alone took about a tenth of the teapot's full look). Where air planes lie between, the
// core behind them is drawn first (ICE_INTERIOR_CORE_ONLY), the rest after them
// (ICE_INTERIOR_AFTER_CORE).
vec4 iceInteriorAlong(vec3 positionWC, vec3 positionMC, vec3 refracted, float viewDepth,
  float backDepth, float cloudLength)
{
  vec4 t = vec4(0.0, 0.0, 0.0, 1.0);
  vec3 e = iceEyeVectorWC(positionWC);
  float along = dot(e, iceViewDirectionWC);
  float sBack = (backDepth - viewDepth) / max(along, 1.0e-6);
  if (backDepth <= 0.0 || sBack <= 0.0)
  {
    return t;
  }
  // The ray in model coordinates: s runs over world units from the front to the back face.
  vec3 o = positionMC;
  vec3 d = mat3(iceWCMCMatrix) * e;
#ifdef ICE_INTERIOR_CLOUD
  // The cloud and its bubbles are seen along the ray refracted at the front face (refracted), up
  // to where it leaves (cloudLength, from the back faces; the eye ray's length where that is not
  // known): through a face seen at a slant they show where the light that reaches the eye
  // crossed the ice, not behind the face's outline, and not cut where the eye ray would leave
  // through a nearer side. The cracks and air planes keep the eye ray, as the paper's passes
  // draw them.
  vec3 dCloud = mat3(iceWCMCMatrix) * refracted;
  float alongCloud = dot(refracted, iceViewDirectionWC);
  float sCloud = cloudLength > 0.0 ? cloudLength : sBack;
  vec3 coreOrigin = (o - iceCoreCenter) * iceCoreScale;
  vec3 coreDirection = dCloud * iceCoreScale;
#ifndef ICE_INTERIOR_AFTER_CORE
  // The milky core behind the air: the air planes in front of it are seen through less of it.
  if (iceCoreDensity > 0.0 && iceInteriorDebug == 0)
  {
    float depth = iceCoreOpticalDepth(coreOrigin, coreDirection, sCloud, iceCoreDensity) *
      iceCoreStreaks(coreOrigin, coreDirection);
    iceInteriorOver(t, ICE_CORE_COLOUR, iceMilkyCoreCover(depth));
  }
#endif
#ifdef ICE_INTERIOR_CORE_ONLY
  return t;
#endif
#endif

#ifdef ICE_INTERIOR_CLOUD
  // The bubbles in front of the core's cloud and the air planes they lie in.
  vec4 bubbles = iceBubbles(o, dCloud, sCloud, coreOrigin, coreDirection, viewDepth, alongCloud);
  t = vec4(bubbles.rgb + bubbles.a * t.rgb, bubbles.a * t.a);
#endif

  // Cracks: only the nearest is shaded, once: its mirror hides what lies behind it where it
  // reflects totally, and seen square on a gap reflects a few percent, so the cracks behind it
  // would add little.
  vec3 highlights = vec3(0.0);
  bool crackSeen = false;
#ifdef ICE_INTERIOR_CRACKS
  float nearest;
  int nearestRecord;
  float nearestEdge;
  IceLocalRay nearestRay;
  iceNearestCrack(o, d, sBack, nearest, nearestRecord, nearestEdge, nearestRay);
  crackSeen = nearestRecord >= 0;
  vec3 nearestNormal = vec3(0.0);
  if (crackSeen)
  {
    // The sheet's normal (gradient of z - a x^2 - b y^2) back in model, then world space,
    // tilted by the noise fixed to the model (as the paper passes' crack shader, precomputed),
    // facing the viewer.
    vec3 n = normalize(iceNormalMCWCMatrix * iceCrackNormal(nearestRay, nearest));
    vec3 sheetNormal = dot(n, e) > 0.0 ? -n : n;
    vec3 gradient = iceNormalMCWCMatrix *
      textureLod(iceInteriorBump, (o + nearest * d) * iceCrackBumpFrequency / 8.0, 0.0).xyz;
    n = normalize(n - iceCrackBumpStrength * (gradient - dot(gradient, n) * n));
    n = dot(n, e) > 0.0 ? -n : n;
    // A thin gap of air reflects a light as it reflects the environment: little where it is seen
    // face on, all of it beyond the critical angle; and as a flat fracture, with part of the tilt.
    nearestNormal = normalize(mix(sheetNormal, n, ICE_CRACK_MIRROR_BUMPS));
    highlights = iceCrackReflectance(dot(e, nearestNormal), 1.0 / iceRefractionRatio) *
      iceCrackLight(nearestNormal, -e, positionWC + nearest * e);
  }
  if (crackSeen && iceInteriorDebug == 0 && iceCrackReflection > 0.0)
  {
    iceCrackSheet(t, e, nearestNormal, nearestEdge, 1.0 / iceRefractionRatio,
      iceCrackIntensity * iceCrackReflection, iceSurfaceEnvironmentColor(reflect(e, nearestNormal)));
  }
#endif
  return iceInteriorDebug == ICE_DEBUG_CRACKS && crackSeen
    ? vec4(1.0, 0.0, 0.0, 0.0)
    : vec4(t.rgb + iceCrackIntensity * highlights, t.a);
}

// Air plane fragments (vtkIceScreenAir): the plane at `positionWC`, its bubble image `bubble`
// there, where the depth test passed it behind the pixel's front face (view depth `viewDepth`,
// read only for the milky core), over the ice's interior where it lies in front of the nearest
// back face (`backDepth`, 0: none), as vec4(add, keep). The planes' quads, drawn in the table's
// order (back to front), do what a loop over every plane a pixel's ray meets would do.
vec4 iceAirPlane(vec3 positionWC, vec4 bubble, float viewDepth, float backDepth)
{
  float depth = dot(positionWC - iceCameraWC, iceViewDirectionWC);
  vec4 layer = iceAirLayer(bubble, iceMilkiness, iceInteriorDebug == ICE_DEBUG_AIR);
#ifdef ICE_INTERIOR_CLOUD
  if (iceCoreDensity > 0.0 && iceInteriorDebug == 0)
  {
    // The core in front of the plane, along the eye ray from the front face.
    vec3 e = iceEyeVectorWC(positionWC);
    float s = (depth - viewDepth) / max(dot(e, iceViewDirectionWC), 1.0e-6);
    vec3 o = (iceWCMCMatrix * vec4(positionWC - s * e, 1.0)).xyz;
    vec3 coreOrigin = (o - iceCoreCenter) * iceCoreScale;
    vec3 coreDirectionEye = mat3(iceWCMCMatrix) * e * iceCoreScale;
    layer.a *= iceAirNearCore(coreOrigin + s * coreDirectionEye,
      iceCoreOpticalDepth(coreOrigin, coreDirectionEye, s, iceCoreDensity));
  }
#endif
  // Behind the front faces (the depth test), in front of the back faces.
  float a = depth < backDepth ? layer.a : 0.0;
  return vec4(a * layer.rgb, 1.0 - a);
}
