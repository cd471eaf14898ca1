// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The interior's look shared by the paper's passes and the screen-space interior (vtkIceInteriorLook.h
// defines the ICE_ constants before this).

// One air plane's bubble image seen through the ice: its colour (rgb) and coverage (a).
// Milkiness 0: sparse clear bubbles; 1: white and cloudy. The debug view shows solid green where
// a bubble covers.
vec4 iceAirLayer(vec4 bubble, float milkiness, bool debug)
{
  if (debug)
  {
    return vec4(0.0, 1.0, 0.0, bubble.a >= 0.2 ? 1.0 : 0.0);
  }
  return vec4(mix(bubble.rgb, vec3(1.0), milkiness),
    clamp(bubble.a * mix(0.45, 1.6, milkiness), 0.0, 1.0));
}

// How much of the colour behind the milky core its white hides: the core's air scatters white
// light, as much as its optical depth along the ray hides (never all of it).
float iceMilkyCoreCover(float opticalDepth)
{
  return 1.0 - exp(-opticalDepth);
}

// How much of an air plane's coverage shows at `u` (the core's frame) with the core's optical depth
// `inFront` between it and the eye: the air gathers in the core (its rim keeps ICE_CORE_RIM_AIR of
// the bubbles), and the core in front hides it.
float iceAirNearCore(vec3 u, float inFront)
{
  return mix(ICE_CORE_RIM_AIR, 1.0, exp(-dot(u, u))) * exp(-inFront);
}

// VTK's specular term of a light travelling along `travel` on a crack with normal n seen
// towards `toEye` (all world space): the cracks' highlight.
float iceCrackSpecular(vec3 n, vec3 toEye, vec3 travel)
{
  float df = max(0.0, dot(n, -travel));
  return sign(df) * pow(max(0.0, dot(reflect(travel, n), toEye)), ICE_CRACK_SPECULAR_POWER);
}
