// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
in vec3 iceNormalMC;
uniform mat4 iceMCWCMatrix;       // model (VBO shift/scale included) to world
uniform mat3 iceNormalMCWCMatrix; // model to world for normals
uniform mat4 iceVBOToModelMatrix; // undoes the VBO shift/scale: true model coordinates
uniform vec3 iceCameraWC;
uniform vec3 iceViewDirectionWC; // unit direction of projection
uniform int iceParallelProjection;
out vec3 icePositionWCVSOutput;
out vec3 iceNormalWCVSOutput;
out vec3 icePositionMCVSOutput;
out vec3 iceNormalModelVSOutput;
// Unit eye vector e, from the eye to a point: the same direction of projection for every point
// under parallel projection.
vec3 iceEyeVectorWC(vec3 positionWC)
{
  return iceParallelProjection != 0 ? iceViewDirectionWC : normalize(positionWC - iceCameraWC);
}
//ICE::Impl
  icePositionWCVSOutput = (iceMCWCMatrix * vertexMC).xyz;
  iceNormalWCVSOutput = iceNormalMCWCMatrix * iceNormalMC;
  icePositionMCVSOutput = (iceVBOToModelMatrix * vertexMC).xyz;
  iceNormalModelVSOutput = iceNormalMC;
