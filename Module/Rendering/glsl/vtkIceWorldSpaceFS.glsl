// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Uniforms
// The camera and the prop's matrices, for the ice surface's program and for the screen-space
// interior's quad (vtkIceScreenInterior), which has no vertex outputs.
uniform mat3 iceNormalMCWCMatrix;
uniform mat4 iceWCMCMatrix; // world to (true) model coordinates: the actor's matrix inverted
uniform mat4 iceVCWCMatrix; // view to world, for VTK's light uniforms (view space)
uniform vec3 iceCameraWC;
uniform vec3 iceViewDirectionWC; // unit direction of projection
uniform int iceParallelProjection;
uniform ivec2 iceViewportOrigin; // window position of texel (0, 0) of viewport-sized textures

// Unit eye vector e, from the eye to a point: the same direction of projection for every point
// under parallel projection.
vec3 iceEyeVectorWC(vec3 positionWC)
{
  return iceParallelProjection != 0 ? iceViewDirectionWC : normalize(positionWC - iceCameraWC);
}

uniform vec4 iceDepthToWindow; // the camera projection's P22, P23, parallel (0/1), unused

// Window depth of a view depth for the current camera.
float iceWindowDepth(float viewDepth)
{
  float ndc = iceDepthToWindow.z > 0.5 ? -iceDepthToWindow.x * viewDepth + iceDepthToWindow.y
                                        : (iceDepthToWindow.y - iceDepthToWindow.x * viewDepth) / viewDepth;
  return 0.5 * ndc + 0.5;
}

// Texel of a viewport-sized texture under this fragment.
ivec2 iceScreenTexel()
{
  return ivec2(gl_FragCoord.xy) - iceViewportOrigin;
}
//ICE::Dec
in vec3 icePositionWCVSOutput;
in vec3 iceNormalWCVSOutput;
in vec3 icePositionMCVSOutput;   // model coordinates: stable under camera and actor motion
in vec3 iceNormalModelVSOutput;

// Distance of this fragment in front of the camera along the view direction (-z in view space).
float iceViewDepth()
{
  return dot(icePositionWCVSOutput - iceCameraWC, iceViewDirectionWC);
}
