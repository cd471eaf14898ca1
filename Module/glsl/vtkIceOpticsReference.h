// CPU reference of the ice optics in vtkIceOptics.glsl and vtkIceSurface*.glsl, written with GLM
// in double precision. Tests evaluate it per pixel and compare with what the GPU rendered, so the
// two must stay equation for equation the same. Vectors are in world space; e runs from the
// camera to the surface point.
#ifndef vtkIceOpticsReference_h
#define vtkIceOpticsReference_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

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

struct Material
{
  double RefractionRatio = 1.0003 / 1.3091;
  double FresnelPower = 3.0;
  double BackNormalWeight = 0.33;
  Vec3 Tint = Vec3(1.0);
};

// Colour of an ice surface point. `environment(direction)` returns the environment's colour.
// Pass nBack = nullptr for one-sided refraction.
template <typename Environment>
Vec3 Shade(const Vec3& e, const Vec3& nFront, const Vec3* nBack, const Material& material,
  const Environment& environment)
{
  const Vec3 nRefract = nBack ? BlendNormals(nFront, *nBack, material.BackNormalWeight) : nFront;
  const Vec3 refracted = environment(Refract(e, nRefract, material.RefractionRatio));
  const Vec3 reflected = environment(Reflect(e, nFront));
  const double f = std::min(1.0, std::max(0.0, Fresnel(e, nFront, material.FresnelPower)));
  return material.Tint * (refracted + (reflected - refracted) * f);
}
}

#endif
