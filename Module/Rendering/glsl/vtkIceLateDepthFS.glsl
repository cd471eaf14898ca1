// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A store to memory that never happens (vtkIceLateDepthTest): a shader that may write memory
// takes llvmpipe's depth test after it, which skips the 8-pixel blocks no sample covers.
//ICE::Extension
#extension GL_ARB_shader_storage_buffer_object : require
//ICE::Dec
layout(std430) buffer IceLateDepthTest
{
  float iceLateDepthTestUnused;
};
//ICE::Impl
  if (gl_FragCoord.x < -1.0)
  {
    iceLateDepthTestUnused = 0.0;
  }
