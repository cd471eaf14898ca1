// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Ice optics of Seipel & Nivfors, "Efficient rendering of multiple refractions and reflections in
// natural objects". Every function here is mirrored on the CPU by vtkIceOpticsReference.h: change
// both together. Vectors are in world space; e runs from the camera to the surface point.

// Eq 1: blend the front normal with the back normal so one refraction approximates two.
vec3 iceBlendNormals(vec3 nFront, vec3 nBack, float a)
{
  return normalize(nFront * (1.0 - a) - nBack * a);
}

// Eq 3: reflected eye vector.
vec3 iceReflect(vec3 e, vec3 n)
{
  return e - 2.0 * dot(n, e) * n;
}

// A ray inside the ice reflected about an interpolated normal n (outward) can point out through
// the flat triangle it reflects on (face: its outward unit normal): near grazing the two normals
// differ by up to half the angle between neighbouring triangles. It would then meet the next
// triangle at once, from outside (bright lines along the edges); it stays just inside instead.
vec3 iceReflectInside(vec3 d, vec3 n, vec3 face)
{
  vec3 r = iceReflect(d, n);
  float outward = dot(r, face) + 1.0e-3;
  return outward > 0.0 ? normalize(r - outward * face) : r;
}

// Eq 2: refracted eye vector, eta = n_from / n_to. Where eq 2 has no real solution
// (total internal reflection, only possible for eta > 1) the ray is reflected instead.
vec3 iceRefract(vec3 e, vec3 n, float eta)
{
  vec3 r = refract(e, n, eta);
  return dot(r, r) > 0.0 ? r : iceReflect(e, n);
}

// Eq 4: Fresnel approximation, evaluated per vertex and interpolated. The base is clamped: |e.n|
// of unit vectors can round past 1 (pow of a negative base is undefined in GLSL), and 0^0 is
// undefined too (power 0 is allowed), so the base stays in [1e-6, 1].
float iceFresnel(vec3 e, vec3 n, float power)
{
  return pow(clamp(1.0 - abs(dot(e, n)), 1.0e-6, 1.0), power);
}

// Beer-Lambert absorption with glTF KHR_materials_volume's meaning: white light that has travelled
// the attenuation distance in the ice has the attenuation colour. inverseDistance is 1 / that
// distance (0: the ice absorbs nothing). The colour is kept above 0 so its logarithm exists.
vec3 iceTransmittance(float pathLength, vec3 attenuationColor, float inverseDistance)
{
  return pow(clamp(attenuationColor, 1.0e-4, 1.0), vec3(pathLength * inverseDistance));
}

// Fresnel's equations for unpolarised light meeting a clean interface at cos(angle) =
// cosIncidence (to its normal), eta = n_from / n_to: the reflected fraction, 1 beyond the
// critical angle (total internal reflection, eta > 1 only). Air to ice head-on: 1.8 %.
float iceDielectricReflectance(float cosIncidence, float eta)
{
  float cosI = clamp(abs(cosIncidence), 0.0, 1.0);
  float sinT2 = eta * eta * (1.0 - cosI * cosI);
  if (sinT2 >= 1.0)
  {
    return 1.0;
  }
  float cosT = sqrt(1.0 - sinT2);
  float rs = (eta * cosI - cosT) / (eta * cosI + cosT);
  float rp = (eta * cosT - cosI) / (eta * cosT + cosI);
  return 0.5 * (rs * rs + rp * rp);
}

// How far a ray refracted through a rough interface turns per angle of tilt of its microfacet:
// Snell's law gives d(theta_t)/d(theta_i) = eta cos(theta_i) / cos(theta_t), and the facet's tilt
// turns the normal too, so the ray turns by |1 - eta cos(theta_i) / cos(theta_t)| of the tilt
// (a mirror turns it by 2). Head-on air to ice 1 - 1/n; near grazing entry or the critical angle
// leaving, the refracted lobe widens without bound. cosIncidence and cosTransmitted are the
// cosines of the ray before and after against the normal (of opposite signs where it could not
// refract and was mirrored); eta = n_from / n_to.
float iceRefractionSpread(float cosIncidence, float cosTransmitted, float eta)
{
  if (cosIncidence * cosTransmitted < 0.0)
  {
    return 2.0;
  }
  return abs(1.0 - eta * abs(cosIncidence) / max(abs(cosTransmitted), 1.0e-3));
}

// Smith's masking of GGX (alpha = roughness^2): the share of a rough surface's microfacets seen
// from a direction at cos(angle) = cosine to its normal.
float iceMasking(float cosine, float alpha)
{
  float c2 = max(cosine * cosine, 1.0e-8);
  return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2));
}

// What a rough interface (GGX, alpha = roughness^2) reflects and transmits of light arriving at
// cos(angle) = cosIncidence to its normal, eta = n_from / n_to: Fresnel's equations at each
// microfacet the light sees, the light leaving masked by the others (single scattering). An
// average over eight fixed samples of the microfacets seen (Heitz 2018's visible normals, the
// same pairs in every pixel): a smooth interface's Fresnel at the geometric normal mirrors more
// near grazing, where the facets seen tilt towards the light.
vec2 iceRoughInterface(float cosIncidence, float eta, float alpha)
{
  float c = clamp(abs(cosIncidence), 1.0e-4, 1.0);
  // The surface's frame: normal +z, the light towards +x.
  vec3 v = vec3(sqrt(1.0 - c * c), 0.0, c);
  vec3 stretched = normalize(vec3(alpha * v.x, 0.0, v.z));
  vec3 t2Axis = vec3(-stretched.z, 0.0, stretched.x);
  float s = 0.5 * (1.0 + stretched.z);
  vec2 reflectedTransmitted = vec2(0.0);
  for (int i = 0; i < 8; ++i)
  {
    float u1 = (float(i) + 0.5) / 8.0;
    float u2 = (float((3 * i) % 8) + 0.5) / 8.0;
    float radius = sqrt(u1);
    float t1 = radius * cos(6.2831853 * u2);
    float t2 = mix(sqrt(1.0 - t1 * t1), radius * sin(6.2831853 * u2), s);
    vec3 h = t1 * vec3(0.0, 1.0, 0.0) + t2 * t2Axis +
      sqrt(max(0.0, 1.0 - t1 * t1 - t2 * t2)) * stretched;
    vec3 m = normalize(vec3(alpha * h.xy, max(h.z, 0.0)));
    float vm = dot(v, m);
    float f = iceDielectricReflectance(vm, eta);
    float reflectedZ = 2.0 * vm * m.z - v.z;
    reflectedTransmitted.x += reflectedZ > 0.0 ? f * iceMasking(reflectedZ, alpha) : 0.0;
    float sinT2 = eta * eta * (1.0 - vm * vm);
    float transmittedZ = -eta * v.z + (eta * vm - sqrt(max(0.0, 1.0 - sinT2))) * m.z;
    reflectedTransmitted.y +=
      sinT2 < 1.0 && transmittedZ < 0.0 ? (1.0 - f) * iceMasking(transmittedZ, alpha) : 0.0;
  }
  return reflectedTransmitted / 8.0;
}

// A crack is a thin gap of air in the ice: light in the ice meeting it is reflected by Fresnel's
// equations at the ice-to-air face of index ratio ior (all of it beyond the critical angle), and
// the gap's two parallel faces together reflect 2R / (1 + R), their reflections added without
// interference.
float iceCrackReflectance(float cosIncidence, float ior)
{
  float r = iceDielectricReflectance(cosIncidence, ior);
  return 2.0 * r / (1.0 + r);
}

// erf (Abramowitz and Stegun 7.1.26, absolute error below 1.5e-7).
float iceErf(float x)
{
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float poly =
    t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return sign(x) * (1.0 - poly * exp(-x * x));
}

// The milky core's optical depth along the ray p + s q, s in [0, sEnd]. The core's air density is
// density * exp(-|u|^2) in its own frame u (its radius is 1 there); p and q are the ray's origin
// and direction in u. The integral of the density over the ray's length in u, in closed form.
float iceCoreOpticalDepth(vec3 p, vec3 q, float sEnd, float density)
{
  float speed = length(q);
  if (speed < 1.0e-12 || density <= 0.0)
  {
    return 0.0;
  }
  float along = dot(p, q) / speed; // the closest approach is at -along
  float miss2 = max(dot(p, p) - along * along, 0.0);
  return density * 0.886226925 * exp(-miss2) * (iceErf(speed * sEnd + along) - iceErf(along));
}

// One well-mixed 32-bit integer of another (Chris Wellons' lowbias32 constants): the same on every
// GPU and on the CPU.
uint iceMix(uint x)
{
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

// Value noise in [0, 1) on the integer lattice: hashed corners (integers, as the CPU hashes them),
// trilinear between them, eased by 3f^2 - 2f^3.
float iceLatticeNoise(vec3 x)
{
  vec3 i = floor(x);
  vec3 f = x - i;
  vec3 u = f * f * (3.0 - 2.0 * f);
  ivec3 c = ivec3(i);
  float corner[8];
  for (int k = 0; k < 8; ++k)
  {
    ivec3 at = c + ivec3(k & 1, (k >> 1) & 1, k >> 2);
    // One mix a corner: the coordinates spread by large odd factors first.
    uint h = iceMix(uint(at.x) * 0x8da6b343u ^ uint(at.y) * 0xd8163841u ^ uint(at.z) * 0xcb1ab31fu);
    corner[k] = float(h >> 8u) * (1.0 / 16777216.0);
  }
  vec4 y0 = mix(vec4(corner[0], corner[2], corner[4], corner[6]),
    vec4(corner[1], corner[3], corner[5], corner[7]), u.x);
  vec2 z0 = mix(y0.xz, y0.yw, u.y);
  return mix(z0.x, z0.y, u.z);
}

// How the milky core's air varies across rays p + s q (its frame, as iceCoreOpticalDepth's): a
// factor of the ray's optical depth from the point where it passes nearest the centre. Clumps of
// that point (two scales), and faint streaks of its direction from the centre (the freezing fronts
// pushed the air inwards along them), so that seen through the ice the cloud is uneven instead of
// glowing evenly; 1 for rays through the centre.
float iceCoreStreaks(vec3 p, vec3 q)
{
  float qq = max(dot(q, q), 1.0e-12);
  vec3 nearest = p - dot(p, q) / qq * q;
  float r = length(nearest);
  vec3 towards = nearest / max(r, 1.0e-6);
  // The clumps' lattice turned off the ice's axes (its cells lined up into a grid of blobs seen
  // through a face), and sampled before and behind the nearest point: the cloud has depth.
  const mat3 turn = mat3(0.0, 0.8, 0.6, -0.8, 0.36, -0.48, -0.6, -0.48, 0.64);
  vec3 along = 0.35 * inversesqrt(qq) * q;
  float clumps = 0.0;
  for (int k = -1; k <= 1; k += 2)
  {
    vec3 at = turn * (nearest + float(k) * along);
    clumps += 0.5 * (iceLatticeNoise(1.9 * at + vec3(1.7, 0.0, 3.1)) +
                      0.5 * iceLatticeNoise(4.3 * at + vec3(0.4, 5.3, 2.2)));
  }
  float streaks = iceLatticeNoise((21.0 + 6.4 * r) * towards);
  float structure =
    mix(0.45, 1.4, smoothstep(-0.2, 0.2, (clumps - 0.75) + 0.2 * (streaks - 0.5)));
  return mix(1.0, structure, smoothstep(0.05, 0.5, r));
}

// The eye ray's path through the ice, from the front surface at view depth frontDepth to the back
// face behind it at backDepth (0: none, no path). View depth grows by e . viewDirection per unit
// of the ray; the floor keeps a ray grazing the view plane finite.
float iceEyePathLength(vec3 e, vec3 viewDirection, float frontDepth, float backDepth)
{
  return backDepth > 0.0 ? max(backDepth - frontDepth, 0.0) / max(dot(e, viewDirection), 0.05)
                         : 0.0;
}
