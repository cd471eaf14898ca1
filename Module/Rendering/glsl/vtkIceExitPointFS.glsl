// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Exit
// Where a ray inside the ice leaves it, found in image space from the back faces' view depth
// (vtkIceBackfaceNormalPass's target, iceBackNormals): for TwoSidedExitPoint's exit and for the
// length of the screen-space interior's refracted ray.
uniform mat4 iceWCDCMatrix; // world to normalised device coordinates

// The back-face texel under the point whose clip coordinates are `clip`.
vec4 iceBackUnder(vec4 clip)
{
  ivec2 size = textureSize(iceBackNormals, 0);
  vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size);
  return texelFetch(iceBackNormals, clamp(ivec2(floor(window)), ivec2(0), size - 1), 0);
}

// The distance along the unit ray t from positionWC (on a front face) to the back face it
// leaves through, backHere the back texel under positionWC (its alpha > 0). It starts as the
// straight-through thickness under this pixel and is corrected a few times: it grows by how far
// the back face under the current exit estimate lies beyond it in view depth (the back face taken
// as locally facing the camera). `back` receives the back texel at the exit.
float iceExitDistance(vec3 positionWC, vec3 t, vec4 backHere, out vec4 back)
{
  float depthPerDistance = max(dot(t, iceViewDirectionWC), 0.05);
  float frontDepth = dot(positionWC - iceCameraWC, iceViewDirectionWC);
  float s = max(backHere.a - frontDepth, 0.0) / depthPerDistance;
  back = backHere;
  // Clip coordinates are linear along the ray: two products instead of one per step.
  vec4 clipStart = iceWCDCMatrix * vec4(positionWC, 1.0);
  vec4 clipStep = iceWCDCMatrix * vec4(t, 0.0);
  for (int i = 0; i < 3; ++i)
  {
    vec3 exitPoint = positionWC + s * t;
    vec4 under = iceBackUnder(clipStart + s * clipStep);
    if (under.a <= 0.0)
    {
      break; // past the ice's outline in the image: keep the last estimate
    }
    back = under;
    s = max(s + (back.a - dot(exitPoint - iceCameraWC, iceViewDirectionWC)) / depthPerDistance, 0.0);
  }
  return s;
}
//ICE::Dec
// Two-sided refraction through the exit point (TwoSidedExitPoint), beyond the paper's eq 1: the
// eye ray is refracted at the front surface (eq 2), followed through the ice to where it leaves
// (iceExitDistance), and refracted again there, ice to air.
// Mirrored on the CPU by vtkIceOpticsReference::ExitPointDirection: change both together.

// The direction leaving the ice for the eye vector e meeting its front surface at positionWC
// with normal nFront; eta = n_air / n_ice. At the exit, the refracted ray t refracts about the
// back normal with 1 / eta; where it cannot (total internal reflection) it is reflected back into
// the ice and leaves as is. s, the path from the front to the exit point, is handed out for the
// absorption.
vec3 iceExitPointDirection(vec3 e, vec3 positionWC, vec3 nFront, float eta, vec4 backHere,
  out float s)
{
  vec3 t = iceRefract(e, nFront, eta);
  s = 0.0;
  if (backHere.a <= 0.0)
  {
    return t;
  }
  vec4 back;
  s = iceExitDistance(positionWC, t, backHere, back);
  return iceRefract(t, -normalize(back.rgb), 1.0 / eta);
}
//ICE::Impl
    refractedDirection = iceExitPointDirection(e, icePositionWCVSOutput, nFront,
      iceRefractionRatio, texelFetch(iceBackNormals, iceScreenTexel(), 0), iceExitPathLength);
