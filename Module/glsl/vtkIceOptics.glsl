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

// Beer-Lambert absorption with glTF KHR_materials_volume's meaning: white light that has travelled
// the attenuation distance in the ice has the attenuation colour. inverseDistance is 1 / that
// distance (0: the ice absorbs nothing). The colour is kept above 0 so its logarithm exists.
vec3 iceTransmittance(float pathLength, vec3 attenuationColor, float inverseDistance)
{
  return pow(clamp(attenuationColor, 1.0e-4, 1.0), vec3(pathLength * inverseDistance));
}

// The eye ray's path through the ice, from the front surface at view depth frontDepth to the back
// face behind it at backDepth (0: none, no path). View depth grows by e . viewDirection per unit
// of the ray; the floor keeps a ray grazing the view plane finite.
float iceEyePathLength(vec3 e, vec3 viewDirection, float frontDepth, float backDepth)
{
  return backDepth > 0.0 ? max(backDepth - frontDepth, 0.0) / max(dot(e, viewDirection), 0.05)
                         : 0.0;
}
