// What differs between the VTK versions VTK Ice builds against, in one place.
#ifndef vtkIceVTKCompat_h
#define vtkIceVTKCompat_h

#include "vtkVersionMacros.h"

namespace vtkIceVTKCompat
{
// Since VTK 9.2, vtkSkybox's cube projection (with its default floor) and VTK's image-based
// lighting look a cube map up at (x, y, -z) for the world direction (x, y, z); 9.1 used (x, y, z).
// A static cube-map environment is sampled the same way, so ice lines up with the skybox.
constexpr bool CubeMapLookupFlipsZ = VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0);
}

#endif
