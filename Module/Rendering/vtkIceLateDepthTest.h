// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Whether the ice surface drawn now takes its depth test after its shader, and the shader code
// that asks for it (glsl/vtkIceLateDepthFS.glsl). Inside the module.
//
// llvmpipe (Mesa's software rasterizer) shades a triangle's 4 x 4-pixel blocks in two 8-pixel
// halves. Into a single-sampled framebuffer it skips a half that no pixel of the triangle
// covers; into a multisampled one, with its usual depth test before the shader, it shades such
// halves too, and only a depth test after the shader (a shader that may write memory) brings
// the check back. The ice surface's shader costs many times VTK's, and the small triangles of a
// detailed mesh leave many halves uncovered: the teapot's surface shaded about four times
// over (Documentation/performance.md). The late test keeps each sample's own depth, so the
// picture is the same bit for bit. GPUs and single-sampled targets keep the early test.
#ifndef vtkIceLateDepthTest_h
#define vtkIceLateDepthTest_h

#include <string>

namespace vtkIceLateDepthTest
{
// For the framebuffer bound now, in the current context: multisampled, llvmpipe, storage
// buffers (OpenGL 4.3), and the environment variable VTKICE_LATE_DEPTH_TEST not "0".
bool Wanted();

// The fragment shader's extension line (right after its #version line), its declaration and
// its code (anywhere in main()).
std::string Extension();
std::string Declarations();
std::string Code();
}

#endif
