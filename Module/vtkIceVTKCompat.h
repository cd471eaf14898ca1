// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// What differs between the VTK versions VTK Ice builds against, in one place.
#ifndef vtkIceVTKCompat_h
#define vtkIceVTKCompat_h

#include "vtkVersionMacros.h"

// VTK 9.4 replaced GLEW by glad: the header that declares the OpenGL functions VTK loaded.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#define VTKICE_GL_LOADER_GLAD 1
#else
#include "vtk_glew.h"
#define VTKICE_GL_LOADER_GLAD 0
#endif

namespace vtkIceVTKCompat
{
// Since VTK 9.2, vtkSkybox's cube projection (with its default floor) and VTK's image-based
// lighting look a cube map up at (x, y, -z) for the world direction (x, y, z); 9.1 used (x, y, z).
// A static cube-map environment is sampled the same way, so ice lines up with the skybox.
constexpr bool CubeMapLookupFlipsZ = VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0);

// The world direction that shows the cube-map texel of OpenGL direction `dir` in this VTK (the
// inverse of the lookup above, which is its own inverse).
inline void CubeMapTexelToWorld(double dir[3])
{
  if (CubeMapLookupFlipsZ)
  {
    dir[2] = -dir[2];
  }
}

// VTK 9.6's vtkSkybox sets its sampler to the unit of a texture that failed to load (-1):
// GL_INVALID_VALUE, which VTK reports where it checks GL errors (measured: Debian's 9.6.2).
constexpr bool SkyboxDrawsUnloadedTextureCleanly = VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 6, 0);
}

#endif
