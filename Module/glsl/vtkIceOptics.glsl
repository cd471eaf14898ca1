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
