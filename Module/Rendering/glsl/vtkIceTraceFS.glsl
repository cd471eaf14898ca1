// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The refracted light traced through the ice's own triangles (vtkIceMapper::MaxBounces > 1), in
// the tree of vtkIceTriangleBVH (four texels per node, six per triangle; vtkIceTraceTextures).
// Mirrored on the CPU by vtkIceTriangleBVH::Intersect and vtkIceOpticsReference::TracedRefraction
// (clean ice; rough ice's functions are mirrored one by one): change them together.
uniform samplerBuffer iceTraceNodes;
uniform samplerBuffer iceTraceTriangles;
uniform mat4 iceTraceWCMC;      // world to the tree's (model) coordinates
uniform int iceTraceMaxBounces; // hits followed inside the ice
uniform float iceTraceEpsilon;  // in model units: how far a hit must lie from the ray's start
// Which way the triangles face: 1 where all are counter-clockwise seen from outside, -1 where all
// are clockwise, 0 where it is not known (vtkIceTriangleBVH::Intersect's orientation). A ray in
// the ice only meets triangles from inside, so one met from outside is skipped where it is known.
// The ray's start is not always inside: with multisampling, a pixel a triangle partly covers
// takes the point of the triangle's plane at its centre, beyond the edge, outside the next
// triangle, which the ray would meet at once (a grid of lines along the edges).
uniform float iceTraceOrientation;
// 1: more paths where one a pixel aliases (vtkIceMapper::TraceAntiAliasing).
uniform int iceTraceAntiAliasing;
// The milky core (vtkIceInteriorLook::CoreFrame, model coordinates) on the segments after the
// first internal reflection: the screen-space interior shows it along the first segment, and
// without it here a face whose light reflects totally inside would show no cloud at all.
uniform vec3 iceTraceCoreCenter;
uniform vec3 iceTraceCoreScale;
uniform float iceTraceCoreDensity; // 0: none
uniform vec3 iceTraceCoreColour;
#ifdef ICE_TRACE_BUBBLES
// The bubbles (vtkIceInteriorFS.glsl's iceBubbles, declared before this) on the first segment
// after a reflection inside, where a face that reflects totally shows the core's bubbles, and
// only within iceBubbleReach of the core's centre in its frame (where iceBubbleProfile ends
// them): the grid's walk is the cost. Later segments carry little light.
#endif
#ifdef ICE_TRACE_WET_BASE
// vtkIceMapper::WetBase: where the ice stands in water, in model y: fully wet below x, dry above y.
uniform vec2 iceTraceWetBase;
uniform vec3 iceTraceWetBaseCentre; // the ice's centre, world coordinates
const float iceWaterIndex = 1.33;
#endif
#ifdef ICE_TRACE_CRACKS
// The cracks on the same segments (vtkIceCracksFS.glsl's search, declared before this): the
// share of a thin gap's reflectance a crack mirrors (CrackIntensity x CrackReflection).
uniform float iceTraceCrackShare;
#endif

// Rough ice (vtkIceProperty::Roughness) at each interface the traced light crosses:
// - what it reflects and transmits is iceRoughInterface's single scattering, which mirrors less
//   near grazing than Fresnel's equations at the geometric normal, and loses what its facets mask;
// - the environment along a leaving ray is sampled at the level of the path's lobe. A microfacet
//   tilted by d turns a reflected ray by 2d and a refracted one by iceRefractionSpread(...) d: the
//   lobe after several interfaces is the hypot of their spreads against the reflected lobe's 2,
//   GGX's alpha (roughness^2) in proportion (the prefiltered copy's levels are linear in
//   roughness, vtkIcePrefilteredEnvironment::LevelOf). spread2 is the squared hypot.
#ifdef ICE_ROUGH_ENVIRONMENT
vec2 iceTracedInterface(float cosIncidence, float eta)
{
  return iceRoughInterface(cosIncidence, eta, iceRoughnessAlpha);
}
vec3 iceTracedEnvironmentColor(vec3 directionWC, float spread2)
{
  return icePrefilteredEnvironmentColor(directionWC, iceRoughnessLevel * sqrt(0.5 * sqrt(spread2)));
}
#else
vec2 iceTracedInterface(float cosIncidence, float eta)
{
  float r = iceDielectricReflectance(cosIncidence, eta);
  return vec2(r, 1.0 - r);
}
vec3 iceTracedEnvironmentColor(vec3 directionWC, float spread2)
{
  return iceEnvironmentColor(directionWC);
}
#endif

// The interval of the ray o + t d inside the box [low, high], clipped to (tMin, tMax); empty
// where x > y. inv is 1 / d, per component.
vec2 iceTraceSlab(vec3 o, vec3 inv, vec3 low, vec3 high, float tMin, float tMax)
{
  vec3 t0 = (low - o) * inv;
  vec3 t1 = (high - o) * inv;
  vec3 entering = min(t0, t1);
  vec3 leaving = max(t0, t1);
  return vec2(max(tMin, max(entering.x, max(entering.y, entering.z))),
    min(tMax, min(leaving.x, min(leaving.y, leaving.z))));
}

// The triangles of the leaf `child` (its first texel) the ray meets before t: t, the
// interpolated normal n and the face's normal (both unnormalised) of the nearest. Those met
// counter-clockwise are skipped where facing > 0, clockwise where facing < 0 (iceTraceOrientation
// for a ray inside the ice; its opposite for one coming from outside).
bool iceTraceLeaf(vec3 o, vec3 d, float tMin, vec4 child, vec4 count, float facing, inout float t,
  inout vec3 n, inout vec3 face)
{
  bool hit = false;
  int first = int(child.w);
  int last = first - int(count.w);
  for (int i = first; i < last; ++i)
  {
    vec3 p0 = texelFetch(iceTraceTriangles, 6 * i).xyz;
    vec3 e1 = texelFetch(iceTraceTriangles, 6 * i + 1).xyz - p0;
    vec3 e2 = texelFetch(iceTraceTriangles, 6 * i + 2).xyz - p0;
    vec3 s = o - p0;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    if (det == 0.0 || facing * det > 0.0) // det > 0: met counter-clockwise
    {
      continue;
    }
    vec3 q = cross(s, e1);
    float u = dot(s, p) / det;
    float v = dot(d, q) / det;
    float along = dot(e2, q) / det;
    // Edges widened by 1e-5: a ray along a shared edge meets one of its triangles.
    if (u < -1.0e-5 || v < -1.0e-5 || u + v > 1.00001 || along <= tMin || along >= t)
    {
      continue;
    }
    t = along;
    hit = true;
    face = cross(e1, e2);
    n = (1.0 - u - v) * texelFetch(iceTraceTriangles, 6 * i + 3).xyz +
      u * texelFetch(iceTraceTriangles, 6 * i + 4).xyz +
      v * texelFetch(iceTraceTriangles, 6 * i + 5).xyz;
  }
  return hit;
}

// The nearest triangle the ray o + t d (model coordinates) meets with tMin < t < tMax: true with
// t, the normal interpolated there and the triangle's own normal (both unnormalised). A visit
// reads both children's boxes; leaves are searched at once (a hit shortens the rest), nodes pushed
// the nearer last, each with where the ray enters it, so one beyond the nearest hit is skipped
// unread.
bool iceTraceHit(
  vec3 o, vec3 d, float tMin, float tMax, float facing, out float t, out vec3 n, out vec3 face)
{
  vec3 inv = vec3(d.x != 0.0 ? 1.0 / d.x : 1.0e30, d.y != 0.0 ? 1.0 / d.y : 1.0e30,
    d.z != 0.0 ? 1.0 / d.z : 1.0e30);
  bool hit = false;
  t = tMax;
  n = vec3(0.0);
  face = vec3(0.0);
  int stack[48];
  float entries[48];
  int top = 1;
  stack[0] = 0;
  entries[0] = tMin;
  while (top > 0)
  {
    --top;
    if (entries[top] >= t)
    {
      continue;
    }
    int node = stack[top];
    vec4 lowA = texelFetch(iceTraceNodes, 4 * node);
    vec4 highA = texelFetch(iceTraceNodes, 4 * node + 1);
    vec4 lowB = texelFetch(iceTraceNodes, 4 * node + 2);
    vec4 highB = texelFetch(iceTraceNodes, 4 * node + 3);
    vec2 a = iceTraceSlab(o, inv, lowA.xyz, highA.xyz, tMin, t);
    if (a.x <= a.y && highA.w < 0.0)
    {
      hit = iceTraceLeaf(o, d, tMin, lowA, highA, facing, t, n, face) || hit;
      a = vec2(1.0, 0.0);
    }
    vec2 b = iceTraceSlab(o, inv, lowB.xyz, highB.xyz, tMin, t);
    if (b.x <= b.y && highB.w < 0.0)
    {
      hit = iceTraceLeaf(o, d, tMin, lowB, highB, facing, t, n, face) || hit;
      b = vec2(1.0, 0.0);
    }
    bool enterA = a.x <= a.y && a.x < t;
    bool enterB = b.x <= b.y && b.x < t;
    // The farther first, so the nearer is visited next.
    bool aFirst = a.x > b.x;
    for (int k = 0; k < 2; ++k)
    {
      bool pickA = (k == 0) == aFirst;
      if ((pickA ? enterA : enterB) && top < 48)
      {
        stack[top] = int(pickA ? lowA.w : lowB.w);
        entries[top] = pickA ? a.x : b.x;
        ++top;
      }
    }
  }
  return hit;
}

// Where less than this share of the light is left inside (after a reflection that is not total,
// usually a few percent), it leaves along the reflected ray: on curved ice most rays then stop at
// their first way out instead of following the last percent through every bounce. The CPU's is
// vtkIceOpticsReference::TraceCutoff.
const float iceTraceCutoff = 0.005;

// Whether a pixel's traced light needs more paths (vtkIceTraceFS's Impl): where it changes across
// the 2 x 2 pixels by more than 60 % of its own value (floor 0.02: dark changes are not
// seen). change: the largest of |dFdx| and |dFdy| per channel.
bool iceTraceNeedsSamples(vec3 light, vec3 change)
{
  return any(greaterThan(change, 0.6 * max(light, vec3(0.02))));
}

// Where the eye ray from startWC along eWC (a unit world vector) enters the ice within `reach`
// (world units): the point and the interpolated normal there, facing the eye. False where it
// meets none, or a face turned away first (the start was inside the ice).
bool iceTraceEntry(vec3 startWC, vec3 eWC, float reach, out vec3 entryWC, out vec3 normalWC)
{
  mat3 linear = mat3(iceTraceWCMC);
  float t;
  vec3 nModel;
  vec3 faceModel;
  entryWC = startWC;
  normalWC = -eWC;
  if (!iceTraceHit((iceTraceWCMC * vec4(startWC, 1.0)).xyz, linear * eWC, 0.0, reach,
        -iceTraceOrientation, t, nModel, faceModel))
  {
    return false;
  }
  entryWC = startWC + t * eWC;
  normalWC = normalize(nModel * linear);
  return dot(normalWC, eWC) < 0.0;
}

// The k-th extra path's offset in the pixel, in pixels from its centre: a rotated grid.
vec2 iceTraceSampleOffset(int k)
{
  vec2 grid[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125), vec2(0.125, 0.375),
    vec2(-0.375, 0.125));
  return grid[k];
}

// The light the eye vector e brings back through the ice it enters at positionWC (front normal
// nFront, eta = n_air / n_ice): refracted in, then at each of up to iceTraceMaxBounces hits from
// inside Fresnel's share (iceTracedInterface) reflects on and the rest refracts out into
// the environment; at the last hit all that is left leaves (refracted, or reflected where it
// cannot), as does a ray that meets no triangle or one with less than iceTraceCutoff left.
// Absorbed along every segment. withBubbles: whether the bubbles show on the segment after the
// first reflection inside, and the air planes on every segment after it (the extra paths of
// TraceAntiAliasing leave them to the centre's).
vec3 iceTracedRefraction(vec3 e, vec3 positionWC, vec3 nFront, float eta, bool withBubbles)
{
  vec3 d = iceRefract(e, nFront, eta);
  // The squared spread of the path so far, per angle of a microfacet's tilt.
  float spreadEntering = iceRefractionSpread(dot(e, nFront), dot(d, nFront), eta);
  float spread2 = spreadEntering * spreadEntering;
  vec3 p = positionWC;
  vec3 throughput = vec3(1.0);
  vec3 light = vec3(0.0);
  mat3 linear = mat3(iceTraceWCMC);
#ifdef ICE_TRACE_BUBBLES
  float travelled = 0.0; // world units from the front face
#endif
  for (int bounce = 1; bounce <= iceTraceMaxBounces; ++bounce)
  {
    // d is a unit world vector: t is the world distance.
    vec3 dModel = linear * d;
    float t;
    vec3 nModel;
    vec3 faceModel;
    if (!iceTraceHit((iceTraceWCMC * vec4(p, 1.0)).xyz, dModel,
          iceTraceEpsilon / length(dModel), 1.0e30, iceTraceOrientation, t, nModel, faceModel))
    {
      break;
    }
#ifdef ICE_TRACE_BUBBLES
    if (bounce == 2 && withBubbles)
    {
      // In front of the core's cloud of the segment, faded by it (as along the first segment);
      // the pixel's footprint grows with the path from the front face (icePixelFootprint).
      vec3 pModel = (iceTraceWCMC * vec4(p, 1.0)).xyz;
      vec3 u = (pModel - iceCoreCenter) * iceCoreScale;
      vec3 du = dModel * iceCoreScale;
      float a = dot(du, du);
      float b = dot(u, du);
      float reach = b * b - a * (dot(u, u) - iceBubbleReach * iceBubbleReach);
      float s0 = reach > 0.0 ? max((-b - sqrt(reach)) / a, 0.0) : t;
      float s1 = reach > 0.0 ? min((-b + sqrt(reach)) / a, t) : 0.0;
      if (s1 > s0)
      {
        vec4 bubbles = iceBubbles(
          pModel + s0 * dModel, dModel, s1 - s0, u + s0 * du, du, travelled + s0, 1.0);
        light += throughput * bubbles.rgb;
        throughput *= bubbles.a;
      }
    }
    travelled += t;
#endif
    if (bounce > 1 && iceTraceCoreDensity > 0.0)
    {
      // The core scatters its white light towards the eye and hides what lies behind it.
      vec3 coreOrigin =
        ((iceTraceWCMC * vec4(p, 1.0)).xyz - iceTraceCoreCenter) * iceTraceCoreScale;
      vec3 coreDirection = dModel * iceTraceCoreScale;
      float depth = iceCoreOpticalDepth(coreOrigin, coreDirection, t, iceTraceCoreDensity);
      depth *= iceCoreStreaks(coreOrigin, coreDirection);
      float cover = 1.0 - exp(-depth);
      light += throughput * cover * iceTraceCoreColour;
      throughput *= 1.0 - cover;
    }
#ifdef ICE_TRACE_AIR
    if (bounce > 1 && withBubbles)
    {
      // The air planes (the interior's records after the cracks) the segment crosses, as the
      // screen-space interior draws them on the first: their bubble image, at the atlas's
      // sharpest level (no derivatives along a traced path), behind the ice before them.
      vec3 pModel = (iceTraceWCMC * vec4(p, 1.0)).xyz;
      for (int k = 0; k < iceAirCount; ++k)
      {
        IceLocalRay ray = iceLocalRay(iceCrackCount + k, pModel, dModel);
        float s = -ray.origin.z / ray.direction.z;
        vec2 xy = ray.origin.xy + s * ray.direction.xy;
        if (s > 0.0 && s < t && abs(xy.x) <= 1.0 && abs(xy.y) <= 1.0)
        {
          vec4 layer = iceAirLayer(
            textureLod(iceAirAtlas, ray.shape.xy + 0.01 + 0.24 * (xy + 1.0), 0.0), iceMilkiness,
            false);
          vec3 reaching = throughput * iceTransmittance(s, iceAttenuationColor,
                                         iceInverseAttenuationDistance * iceAbsorptionPower);
          light += reaching * layer.a * layer.rgb;
          throughput *= 1.0 - layer.a;
        }
      }
    }
#endif
#ifdef ICE_TRACE_CRACKS
    if (bounce > 1)
    {
      // The nearest crack on the segment, as the screen-space interior's sheet on the first
      // (iceCrackSheet, with the sheet's own normal): it mirrors the environment by its share of
      // the gap's reflectance and whitens towards its outline; the rest passes the thin gap
      // straight on. It lies behind the core's cloud of the segment, in front of the rest.
      vec3 pModel = (iceTraceWCMC * vec4(p, 1.0)).xyz;
      float sCrack;
      int crack;
      float edge;
      IceLocalRay crackRay;
      if (iceNearestCrack(pModel, dModel, t, sCrack, crack, edge, crackRay))
      {
        vec3 nCrack = normalize(iceCrackNormal(crackRay, sCrack) * linear);
        nCrack = dot(nCrack, d) > 0.0 ? -nCrack : nCrack;
        float mirror =
          clamp(iceTraceCrackShare * iceCrackReflectance(dot(d, nCrack), 1.0 / eta), 0.0, 1.0);
        float rim = clamp(iceTraceCrackShare * ICE_CRACK_EDGE *
            smoothstep(1.0 - ICE_CRACK_EDGE_WIDTH, 1.0, edge), 0.0, 1.0);
        vec3 reaching =
          throughput * iceTransmittance(
            sCrack, iceAttenuationColor, iceInverseAttenuationDistance * iceAbsorptionPower);
        light += reaching * ((1.0 - rim) * mirror *
            iceTracedEnvironmentColor(reflect(d, nCrack), spread2) + rim * ICE_CORE_COLOUR);
        throughput *= (1.0 - mirror) * (1.0 - rim);
      }
    }
#endif
    throughput *= iceTransmittance(
      t, iceAttenuationColor, iceInverseAttenuationDistance * iceAbsorptionPower);
    p += t * d;
    // Normals go to the world by the inverse transpose: n * M is transpose(M) n.
    vec3 n = normalize(nModel * linear);
    n = dot(n, d) < 0.0 ? -n : n; // outward, along the leaving ray
    vec3 face = normalize(faceModel * linear);
    face = dot(face, n) < 0.0 ? -face : face;
    vec3 leaving = iceRefract(d, -n, 1.0 / eta);
    float spreadLeaving = iceRefractionSpread(dot(d, n), dot(leaving, n), 1.0 / eta);
    float spread2Leaving = spread2 + spreadLeaving * spreadLeaving;
#ifdef ICE_TRACE_WET_BASE
    // At the base the light meets water: refracted out into it, barely turned, never reflected
    // totally; fading to air over the wet band's top half.
    float wet = 1.0 - smoothstep(iceTraceWetBase.x, iceTraceWetBase.y, (iceTraceWCMC * vec4(p, 1.0)).y);
    float etaWater = 1.0 / (eta * iceWaterIndex);
    // Through the thin film the light comes from the ground where it leaves: seen from the
    // ice's centre, not along its own direction (near the horizon that was the far landscape).
    vec3 leavingWet = normalize(p - iceTraceWetBaseCentre);
#endif
    if (bounce == iceTraceMaxBounces)
    {
      d = leaving;
#ifdef ICE_TRACE_WET_BASE
      d = wet > 0.5 ? leavingWet : leaving;
#endif
      spread2 = spread2Leaving;
      break;
    }
    vec2 rt = iceTracedInterface(dot(d, n), 1.0 / eta);
#ifdef ICE_TRACE_WET_BASE
    vec2 rtWet = iceTracedInterface(dot(d, n), etaWater);
    light += throughput *
      ((1.0 - wet) * rt.y * iceTracedEnvironmentColor(leaving, spread2Leaving) +
        wet * rtWet.y * iceTracedEnvironmentColor(leavingWet, spread2Leaving));
    rt.x = mix(rt.x, rtWet.x, wet);
#else
    light += throughput * rt.y * iceTracedEnvironmentColor(leaving, spread2Leaving);
#endif
    throughput *= rt.x;
    d = iceReflectInside(d, n, face);
    spread2 += 4.0; // the mirror inside turns the ray by twice its facet's tilt
    if (max(throughput.r, max(throughput.g, throughput.b)) < iceTraceCutoff)
    {
      break;
    }
  }
  return light + throughput * iceTracedEnvironmentColor(d, spread2);
}
//ICE::Impl
#ifdef ICE_TRACE_BUBBLES
    // The pixel's width where the path leaves the front face, and how fast it grows along it.
    icePixelFootprint = vec2(
      max(length(dFdx(icePositionWCVSOutput)), length(dFdy(icePositionWCVSOutput))),
      max(length(dFdx(e)), length(dFdy(e))));
#endif
    refracted = iceTracedRefraction(e, icePositionWCVSOutput, nFront, iceRefractionRatio, true);
    {
      // vtkIceMapper::TraceAntiAliasing: up to four more paths from inside the pixel (a rotated
      // grid) where one path a pixel aliases. Each eye ray finds its own entry in the tree, from
      // a few pixels' footprints in front of the point the derivatives carry it to; the bumps'
      // tilt of the centre goes with it. The derivatives are taken before the branch, where every
      // pixel of the ice is.
      vec3 dPx = dFdx(icePositionWCVSOutput);
      vec3 dPy = dFdy(icePositionWCVSOutput);
      vec3 change = max(abs(dFdx(refracted)), abs(dFdy(refracted)));
      if (iceTraceAntiAliasing != 0 && iceTraceNeedsSamples(refracted, change))
      {
        vec3 smoothNormal = normalize(iceNormalWCVSOutput);
        vec3 bumpTilt = nFront - (gl_FrontFacing ? smoothNormal : -smoothNormal);
        float reach = 4.0 * max(length(dPx), length(dPy)) + iceTraceEpsilon;
        vec3 sum = refracted;
        float paths = 1.0;
        for (int k = 0; k < 4; ++k)
        {
          vec2 o = iceTraceSampleOffset(k);
          vec3 guess = icePositionWCVSOutput + o.x * dPx + o.y * dPy;
          vec3 eye = iceEyeVectorWC(guess);
          vec3 entry;
          vec3 normal;
          if (iceTraceEntry(guess - reach * eye, eye, 2.0 * reach, entry, normal))
          {
            sum += iceTracedRefraction(
              eye, entry, normalize(normal + bumpTilt), iceRefractionRatio, false);
            paths += 1.0;
          }
        }
        refracted = sum / paths;
      }
    }
#ifdef ICE_ROUGH_ENVIRONMENT
    if (iceDielectricFresnel > 0.5)
    {
      vec2 frontShares = iceTracedInterface(dot(e, nFront), iceRefractionRatio);
      fresnel = frontShares.x;
      refracted *= frontShares.y / max(1.0 - frontShares.x, 1.0e-4);
    }
#endif
