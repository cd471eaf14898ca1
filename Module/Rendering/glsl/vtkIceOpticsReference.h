// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// CPU reference of the ice optics in vtkIceOptics.glsl and vtkIceSurface*.glsl, written with GLM
// in double precision. Tests evaluate it per pixel and compare with what the GPU rendered, so the
// two must stay equation for equation the same. Vectors are in world space; e runs from the
// camera to the surface point.
#ifndef vtkIceOpticsReference_h
#define vtkIceOpticsReference_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>

namespace vtkIceOpticsReference
{
using Vec3 = glm::dvec3;

// Eq 1: n_r = n_f (1 - a) - n_b a, normalised.
inline Vec3 BlendNormals(const Vec3& nFront, const Vec3& nBack, double a)
{
  return glm::normalize(nFront * (1.0 - a) - nBack * a);
}

// Eq 3: r_refl = e - 2 (n . e) n.
inline Vec3 Reflect(const Vec3& e, const Vec3& n)
{
  return e - 2.0 * glm::dot(n, e) * n;
}

// iceReflectInside: reflected about the interpolated normal n, kept inside the flat triangle it
// reflects on (face: its outward unit normal).
inline Vec3 ReflectInside(const Vec3& d, const Vec3& n, const Vec3& face)
{
  const Vec3 r = Reflect(d, n);
  const double outward = glm::dot(r, face) + 1.0e-3;
  return outward > 0.0 ? glm::normalize(r - outward * face) : r;
}

// Eq 2: r_refr = eta e - (eta (n . e) + sqrt(1 - eta^2 (1 - (n . e)^2))) n; reflection where the
// root is imaginary (total internal reflection).
inline Vec3 Refract(const Vec3& e, const Vec3& n, double eta)
{
  const double ne = glm::dot(n, e);
  const double k = 1.0 - eta * eta * (1.0 - ne * ne);
  if (k < 0.0)
  {
    return Reflect(e, n);
  }
  return eta * e - (eta * ne + std::sqrt(k)) * n;
}

// Eq 4: f = (1 - |e . n|)^P, the base clamped to [1e-6, 1] as in the shader.
inline double Fresnel(const Vec3& e, const Vec3& n, double power)
{
  return std::pow(std::min(1.0, std::max(1.0e-6, 1.0 - std::abs(glm::dot(e, n)))), power);
}

// Fresnel's equations for unpolarised light (iceDielectricReflectance), eta = n_from / n_to: 1
// beyond the critical angle.
inline double DielectricReflectance(double cosIncidence, double eta)
{
  const double cosI = std::min(1.0, std::abs(cosIncidence));
  const double sinT2 = eta * eta * (1.0 - cosI * cosI);
  if (sinT2 >= 1.0)
  {
    return 1.0;
  }
  const double cosT = std::sqrt(1.0 - sinT2);
  const double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double rp = (eta * cosT - cosI) / (eta * cosT + cosI);
  return 0.5 * (rs * rs + rp * rp);
}

// How far a ray refracted through a tilted microfacet turns per angle of tilt
// (iceRefractionSpread): 2 where it was mirrored instead (cosines of opposite signs).
inline double RefractionSpread(double cosIncidence, double cosTransmitted, double eta)
{
  if (cosIncidence * cosTransmitted < 0.0)
  {
    return 2.0;
  }
  return std::abs(1.0 - eta * std::abs(cosIncidence) / std::max(std::abs(cosTransmitted), 1.0e-3));
}

// Smith's masking of GGX (iceMasking), alpha = roughness^2.
inline double Masking(double cosine, double alpha)
{
  const double c2 = std::max(cosine * cosine, 1.0e-8);
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2));
}

// A rough interface's reflected and transmitted shares (iceRoughInterface): Fresnel at eight
// fixed samples of the visible microfacets, the leaving light masked.
inline std::pair<double, double> RoughInterface(double cosIncidence, double eta, double alpha)
{
  const double c = std::min(1.0, std::max(1.0e-4, std::abs(cosIncidence)));
  const Vec3 v(std::sqrt(1.0 - c * c), 0.0, c);
  const Vec3 stretched = glm::normalize(Vec3(alpha * v.x, 0.0, v.z));
  const Vec3 t2Axis(-stretched.z, 0.0, stretched.x);
  const double s = 0.5 * (1.0 + stretched.z);
  const double twoPi = 6.2831853;
  double reflected = 0.0;
  double transmitted = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    const double u1 = (i + 0.5) / 8.0;
    const double u2 = ((3 * i) % 8 + 0.5) / 8.0;
    const double radius = std::sqrt(u1);
    const double t1 = radius * std::cos(twoPi * u2);
    const double t2 = std::sqrt(1.0 - t1 * t1) * (1.0 - s) + radius * std::sin(twoPi * u2) * s;
    const Vec3 h = t1 * Vec3(0.0, 1.0, 0.0) + t2 * t2Axis +
      std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2)) * stretched;
    const Vec3 m = glm::normalize(Vec3(alpha * h.x, alpha * h.y, std::max(h.z, 0.0)));
    const double vm = glm::dot(v, m);
    const double f = DielectricReflectance(vm, eta);
    const double reflectedZ = 2.0 * vm * m.z - v.z;
    reflected += reflectedZ > 0.0 ? f * Masking(reflectedZ, alpha) : 0.0;
    const double sinT2 = eta * eta * (1.0 - vm * vm);
    const double cosT = std::sqrt(std::max(0.0, 1.0 - sinT2));
    const double transmittedZ = -eta * v.z + (eta * vm - cosT) * m.z;
    transmitted +=
      sinT2 < 1.0 && transmittedZ < 0.0 ? (1.0 - f) * Masking(transmittedZ, alpha) : 0.0;
  }
  return { reflected / 8.0, transmitted / 8.0 };
}

// A crack's reflectance (iceCrackReflectance): the thin gap's two faces together 2R / (1 + R).
inline double CrackReflectance(double cosIncidence, double ior)
{
  const double r = DielectricReflectance(cosIncidence, ior);
  return 2.0 * r / (1.0 + r);
}

// Beer-Lambert absorption (iceTransmittance): white light that has travelled the attenuation
// distance has the attenuation colour; inverseDistance 0 absorbs nothing.
inline Vec3 Transmittance(double pathLength, const Vec3& attenuationColor, double inverseDistance)
{
  return glm::pow(
    glm::clamp(attenuationColor, Vec3(1.0e-4), Vec3(1.0)), Vec3(pathLength * inverseDistance));
}

// The milky core's optical depth (iceCoreOpticalDepth): density * exp(-|u|^2) integrated along the
// ray p + s q (in the core's frame u) over s in [0, sEnd], by its length in u.
inline double CoreOpticalDepth(const Vec3& p, const Vec3& q, double sEnd, double density)
{
  const double speed = glm::length(q);
  if (speed < 1.0e-12 || density <= 0.0)
  {
    return 0.0;
  }
  const double along = glm::dot(p, q) / speed;
  const double miss2 = std::max(glm::dot(p, p) - along * along, 0.0);
  return density * 0.886226925452758 /* sqrt(pi) / 2 */ * std::exp(-miss2) *
    (std::erf(speed * sEnd + along) - std::erf(along));
}

// iceMix: lowbias32.
inline std::uint32_t Mix(std::uint32_t x)
{
  x ^= x >> 16U;
  x *= 0x7feb352dU;
  x ^= x >> 15U;
  x *= 0x846ca68bU;
  x ^= x >> 16U;
  return x;
}

// iceLatticeNoise: value noise in [0, 1) from hashed lattice corners, eased trilinear.
inline double LatticeNoise(const Vec3& x)
{
  const Vec3 i = glm::floor(x);
  const Vec3 f = x - i;
  const Vec3 u = f * f * (3.0 - 2.0 * f);
  double corner[8];
  for (int k = 0; k < 8; ++k)
  {
    const std::uint32_t cx = static_cast<std::uint32_t>(static_cast<int>(i.x) + (k & 1));
    const std::uint32_t cy = static_cast<std::uint32_t>(static_cast<int>(i.y) + ((k >> 1) & 1));
    const std::uint32_t cz = static_cast<std::uint32_t>(static_cast<int>(i.z) + (k >> 2));
    const std::uint32_t h = Mix(cx * 0x8da6b343U ^ cy * 0xd8163841U ^ cz * 0xcb1ab31fU);
    corner[k] = static_cast<double>(h >> 8U) / 16777216.0;
  }
  const auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double y0 = lerp(lerp(corner[0], corner[1], u.x), lerp(corner[2], corner[3], u.x), u.y);
  const double y1 = lerp(lerp(corner[4], corner[5], u.x), lerp(corner[6], corner[7], u.x), u.y);
  return lerp(y0, y1, u.z);
}

inline double SmoothStep(double edge0, double edge1, double x)
{
  const double t = std::min(1.0, std::max(0.0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3.0 - 2.0 * t);
}

// iceCoreStreaks: the factor of the core's optical depth along the ray p + s q (its frame), from
// the point where the ray passes nearest the centre.
inline double CoreStreaks(const Vec3& p, const Vec3& q)
{
  const double qq = std::max(glm::dot(q, q), 1.0e-12);
  const Vec3 nearest = p - glm::dot(p, q) / qq * q;
  const double r = glm::length(nearest);
  const Vec3 towards = nearest / std::max(r, 1.0e-6);
  // Column-major, as GLSL's mat3.
  const glm::dmat3 turn(0.0, 0.8, 0.6, -0.8, 0.36, -0.48, -0.6, -0.48, 0.64);
  const Vec3 along = 0.35 / std::sqrt(qq) * q;
  double clumps = 0.0;
  for (int k = -1; k <= 1; k += 2)
  {
    const Vec3 at = turn * (nearest + double(k) * along);
    clumps += 0.5 *
      (LatticeNoise(1.9 * at + Vec3(1.7, 0.0, 3.1)) +
        0.5 * LatticeNoise(4.3 * at + Vec3(0.4, 5.3, 2.2)));
  }
  const double streaks = LatticeNoise((21.0 + 6.4 * r) * towards);
  const double structure =
    0.45 + 0.95 * SmoothStep(-0.2, 0.2, (clumps - 0.75) + 0.2 * (streaks - 0.5));
  return 1.0 + (structure - 1.0) * SmoothStep(0.05, 0.5, r);
}

// The eye ray's path through the ice between the view depths of its front and back faces
// (iceEyePathLength); backDepth 0: no back face, no path.
inline double EyePathLength(
  const Vec3& e, const Vec3& viewDirection, double frontDepth, double backDepth)
{
  return backDepth > 0.0
    ? std::max(backDepth - frontDepth, 0.0) / std::max(glm::dot(e, viewDirection), 0.05)
    : 0.0;
}

struct Material
{
  double RefractionRatio = 1.0 / 1.31;
  double FresnelPower = 3.0;
  bool DielectricFresnel = false; // vtkIceProperty::FresnelDielectric
  double BackNormalWeight = 0.33;
  Vec3 Tint = Vec3(1.0);
  Vec3 AttenuationColor = Vec3(1.0);
  double InverseAttenuationDistance = 0.0;
};

// Colour of an ice surface point whose refracted ray leaves in `refractedDirection` after a path
// of `pathLength` in the ice.
template <typename Environment>
Vec3 ShadeWithDirection(const Vec3& e, const Vec3& nFront, const Vec3& refractedDirection,
  const Material& material, const Environment& environment, double pathLength = 0.0)
{
  const Vec3 refracted = environment(refractedDirection) *
    Transmittance(pathLength, material.AttenuationColor, material.InverseAttenuationDistance);
  const Vec3 reflected = environment(Reflect(e, nFront));
  const double f = material.DielectricFresnel
    ? DielectricReflectance(glm::dot(e, nFront), material.RefractionRatio)
    : std::min(1.0, std::max(0.0, Fresnel(e, nFront, material.FresnelPower)));
  return material.Tint * (refracted + (reflected - refracted) * f);
}

// The light traced through the ice (iceTracedRefraction of vtkIceTraceFS.glsl): refracted in at
// `position`, then at each of up to maxBounces hits from inside Fresnel's share reflects on and the
// rest refracts out (into water at a wet base); at the last hit all that is left leaves, as does
// a ray that meets nothing.
// `hit(origin, direction, tMin, t, n, face)` is the nearest triangle (vtkIceTriangleBVH::Intersect,
// in world coordinates here) with its interpolated and its own normal; tMin the shader's epsilon.
// The milky core on the traced path (iceTraceCore* of vtkIceTraceFS.glsl), here in world
// coordinates: density 0 is none.
struct TracedCore
{
  Vec3 Center = Vec3(0.0);
  Vec3 Scale = Vec3(1.0);
  double Density = 0.0;
  Vec3 Colour = Vec3(1.0);
};

// The cracks on the traced path (ICE_TRACE_CRACKS of vtkIceTraceFS.glsl), here in world
// coordinates: Share 0 is none. Nearest(p, d, sEnd, s, n, edge) is the nearest crack on the
// segment p + s d with 0 < s < sEnd: its s, its normal (either side, unnormalised) and `edge`
// (vtkIceCrackTable::Nearest and ::Normal, taken to the world).
struct TracedCracks
{
  double Share = 0.0;      // iceTraceCrackShare
  double Edge = 0.0;       // ICE_CRACK_EDGE
  double EdgeWidth = 0.0;  // ICE_CRACK_EDGE_WIDTH
  Vec3 Colour = Vec3(1.0); // ICE_CORE_COLOUR
  std::function<bool(const Vec3&, const Vec3&, double, double&, Vec3&, double&)> Nearest;
};

// The ice's base in water (ICE_TRACE_WET_BASE of vtkIceTraceFS.glsl, vtkIceMapper::WetBase), here
// in world y: fully wet below Wet, dry above Dry; Wet == Dry (the default): none. The light that
// leaves into the water comes from the ground where it leaves, seen from the ice's Centre.
struct TracedWetBase
{
  double Wet = 0.0;
  double Dry = 0.0;
  Vec3 Centre = Vec3(0.0);
};

// iceWaterIndex: the index of refraction of the water the base stands in.
constexpr double WaterIndex = 1.33;

// iceTraceCutoff: less light than this left inside leaves along the reflected ray.
constexpr double TraceCutoff = 0.005;

template <typename Hit, typename Environment>
Vec3 TracedRefraction(const Vec3& e, const Vec3& position, const Vec3& nFront, int maxBounces,
  double tMin, const Material& material, const Hit& hit, const Environment& environment,
  const TracedCore& core = TracedCore(), const TracedCracks& cracks = TracedCracks(),
  const TracedWetBase& base = TracedWetBase())
{
  const double eta = material.RefractionRatio;
  Vec3 d = Refract(e, nFront, eta);
  Vec3 p = position;
  Vec3 throughput(1.0);
  Vec3 light(0.0);
  for (int bounce = 1; bounce <= maxBounces; ++bounce)
  {
    double t;
    Vec3 n;
    Vec3 face;
    if (!hit(p, d, tMin, t, n, face))
    {
      break;
    }
    if (bounce > 1 && core.Density > 0.0)
    {
      const Vec3 origin = (p - core.Center) * core.Scale;
      const Vec3 direction = d * core.Scale;
      const double cover = 1.0 -
        std::exp(-CoreOpticalDepth(origin, direction, t, core.Density) *
          CoreStreaks(origin, direction));
      light += throughput * cover * core.Colour;
      throughput *= 1.0 - cover;
    }
    double sCrack;
    Vec3 nCrack;
    double edge;
    if (bounce > 1 && cracks.Share > 0.0 && cracks.Nearest &&
      cracks.Nearest(p, d, t, sCrack, nCrack, edge))
    {
      nCrack = glm::normalize(nCrack);
      nCrack = glm::dot(nCrack, d) > 0.0 ? -nCrack : nCrack;
      const double mirror = std::min(
        1.0, std::max(0.0, cracks.Share * CrackReflectance(glm::dot(d, nCrack), 1.0 / eta)));
      const double rim = std::min(1.0,
        std::max(0.0, cracks.Share * cracks.Edge * SmoothStep(1.0 - cracks.EdgeWidth, 1.0, edge)));
      const Vec3 reaching = throughput *
        Transmittance(sCrack, material.AttenuationColor, material.InverseAttenuationDistance);
      light += reaching *
        ((1.0 - rim) * mirror * environment(Reflect(d, nCrack)) + rim * cracks.Colour);
      throughput *= (1.0 - mirror) * (1.0 - rim);
    }
    throughput *= Transmittance(t, material.AttenuationColor, material.InverseAttenuationDistance);
    p += t * d;
    n = glm::normalize(n);
    n = glm::dot(n, d) < 0.0 ? -n : n;
    face = glm::normalize(face);
    face = glm::dot(face, n) < 0.0 ? -face : face;
    const Vec3 leaving = Refract(d, -n, 1.0 / eta);
    const double wet = base.Dry > base.Wet ? 1.0 - SmoothStep(base.Wet, base.Dry, p.y) : 0.0;
    const double etaWater = 1.0 / (eta * WaterIndex);
    const Vec3 leavingWet = glm::normalize(p - base.Centre);
    if (bounce == maxBounces)
    {
      d = wet > 0.5 ? leavingWet : leaving;
      break;
    }
    const double r = DielectricReflectance(glm::dot(d, n), 1.0 / eta);
    const double rWet = DielectricReflectance(glm::dot(d, n), etaWater);
    light += throughput *
      ((1.0 - wet) * (1.0 - r) * environment(leaving) + wet * (1.0 - rWet) * environment(leavingWet));
    throughput *= r + (rWet - r) * wet;
    d = ReflectInside(d, n, face);
    if (std::max({ throughput.r, throughput.g, throughput.b }) < TraceCutoff)
    {
      break;
    }
  }
  return light + throughput * environment(d);
}

// Colour of an ice surface point. `environment(direction)` returns the environment's colour.
// Pass nBack = nullptr for one-sided refraction.
template <typename Environment>
Vec3 Shade(const Vec3& e, const Vec3& nFront, const Vec3* nBack, const Material& material,
  const Environment& environment)
{
  const Vec3 nRefract = nBack ? BlendNormals(nFront, *nBack, material.BackNormalWeight) : nFront;
  return ShadeWithDirection(
    e, nFront, Refract(e, nRefract, material.RefractionRatio), material, environment);
}

// A texel of the back-face target: the nearest back face's world normal and view depth; Depth 0
// where there is no ice.
struct BackTexel
{
  Vec3 Normal = Vec3(0.0);
  double Depth = 0.0;
};

// The camera as the exit-point search sees it.
struct View
{
  Vec3 Position;  // iceCameraWC
  Vec3 Direction; // iceViewDirectionWC, unit
};

// TwoSidedExitPoint, as iceExitPointDirection in vtkIceExitPointFS.glsl: the direction leaving
// the ice for the eye vector e meeting its front at `position` with normal nFront. `backHere` is
// the back texel under the fragment, `backUnder(point)` the texel under a world point.
// `pathLength` (when given) receives the distance from the front to the exit point (0 where no
// back face is known).
template <typename BackUnder>
Vec3 ExitPointDirection(const Vec3& e, const Vec3& position, const Vec3& nFront, double eta,
  const BackTexel& backHere, const View& view, const BackUnder& backUnder,
  double* pathLength = nullptr)
{
  const Vec3 t = Refract(e, nFront, eta);
  double ignored = 0.0;
  double& s = pathLength ? *pathLength : ignored;
  s = 0.0;
  if (backHere.Depth <= 0.0)
  {
    return t;
  }
  const double depthPerDistance = std::max(glm::dot(t, view.Direction), 0.05);
  const double frontDepth = glm::dot(position - view.Position, view.Direction);
  s = std::max(backHere.Depth - frontDepth, 0.0) / depthPerDistance;
  BackTexel back = backHere;
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 exitPoint = position + s * t;
    const BackTexel under = backUnder(exitPoint);
    if (under.Depth <= 0.0)
    {
      break;
    }
    back = under;
    s = std::max(
      s + (back.Depth - glm::dot(exitPoint - view.Position, view.Direction)) / depthPerDistance,
      0.0);
  }
  return Refract(t, -glm::normalize(back.Normal), 1.0 / eta);
}

// Distances along the unit e from `origin` to where the line meets an axis-aligned ellipsoid
// (near and far, near <= far); false when it misses.
inline bool IntersectEllipsoid(const Vec3& origin, const Vec3& e, const Vec3& center,
  const Vec3& radii, double& tNear, double& tFar)
{
  // In the ellipsoid's unit-sphere space the surface is |p| = 1.
  const Vec3 o = (origin - center) / radii;
  const Vec3 d = e / radii;
  const double a = glm::dot(d, d);
  const double b = glm::dot(o, d);
  const double disc = b * b - a * (glm::dot(o, o) - 1.0);
  if (disc < 0.0)
  {
    return false;
  }
  tNear = (-b - std::sqrt(disc)) / a;
  tFar = (-b + std::sqrt(disc)) / a;
  return true;
}

// The outward unit normal of the ellipsoid at its surface point p: the gradient of
// |(p - c) / r|^2.
inline Vec3 EllipsoidNormal(const Vec3& p, const Vec3& center, const Vec3& radii)
{
  return glm::normalize((p - center) / (radii * radii));
}

// The truth the approximations are measured against: exact double refraction of the eye ray
// (from `origin` along the unit e) through a solid axis-aligned ellipsoid (a sphere when the
// radii are equal). Refracted at the entry (eq 2), the ray meets the surface again and refracts
// out with 1 / eta. False when the ray misses, or when the exit is a total internal reflection
// (possible in an ellipsoid, not in a sphere: the light would go on inside; no approximation
// here follows it, so no truth is claimed there).
inline bool EllipsoidDoubleRefraction(const Vec3& origin, const Vec3& e, const Vec3& center,
  const Vec3& radii, double eta, Vec3& entryNormal, Vec3& exitDirection)
{
  double tNear;
  double tFar;
  if (!IntersectEllipsoid(origin, e, center, radii, tNear, tFar))
  {
    return false;
  }
  const Vec3 entry = origin + tNear * e;
  entryNormal = EllipsoidNormal(entry, center, radii);
  const Vec3 t = Refract(e, entryNormal, eta);
  // From inside, the far root along t is the exit (the near one, about 0, the entry).
  IntersectEllipsoid(entry, t, center, radii, tNear, tFar);
  const Vec3 exitNormal = EllipsoidNormal(entry + tFar * t, center, radii);
  const double cosine = glm::dot(-exitNormal, t);
  if (1.0 - (1.0 / (eta * eta)) * (1.0 - cosine * cosine) < 0.0)
  {
    return false;
  }
  exitDirection = Refract(t, -exitNormal, 1.0 / eta);
  return true;
}
// GGX's distribution of micro-normals at cos(theta_h) = nDotH, alpha2 = roughness^4
// (iceGgxDistribution in vtkIcePrefilterFS.glsl).
inline double GgxDistribution(double nDotH, double alpha2)
{
  const double d = nDotH * nDotH * (alpha2 - 1.0) + 1.0;
  return alpha2 / (3.14159265358979323846 * d * d);
}

// One texel of an environment cube map: its world direction, solid angle and colour.
struct EnvironmentTexel
{
  Vec3 Direction;
  double SolidAngle;
  Vec3 Colour;
};

// The environment through a surface of `roughness` around the unit direction n, the view taken
// along n (what vtkIcePrefilterFS.glsl estimates with few samples): the integral over every
// texel l of colour(l) D(h) (n . l), h halfway between n and l, divided by the same integral of 1.
// The truth the prefiltered environment is measured against.
template <typename Texels>
Vec3 PrefilteredEnvironment(const Vec3& n, double roughness, const Texels& texels)
{
  if (roughness <= 0.0)
  {
    roughness = 1.0e-3;
  }
  const double alpha2 = std::pow(roughness, 4.0);
  Vec3 sum(0.0);
  double weight = 0.0;
  for (const EnvironmentTexel& texel : texels)
  {
    const double nDotL = glm::dot(n, texel.Direction);
    if (nDotL > 0.0)
    {
      const double w = GgxDistribution(glm::dot(n, glm::normalize(n + texel.Direction)), alpha2) *
        nDotL * texel.SolidAngle;
      sum += w * texel.Colour;
      weight += w;
    }
  }
  return weight > 0.0 ? sum / weight : Vec3(0.0);
}
}

#endif
