// The look of the ice's interior (cracks and air), in one place for both ways of drawing it: the
// paper's passes (vtkIceInterior's crack and air mappers) and the single pass
// (vtkIceSinglePassInterior). The constants are handed to the GLSL of both as #defines; the
// shading functions they share are in glsl/vtkIceInteriorLookFS.glsl.
#ifndef vtkIceInteriorLook_h
#define vtkIceInteriorLook_h

#include <sstream>
#include <string>

namespace vtkIceInteriorLook
{
// The cracks' highlight: VTK's specular term of this power (specular 1, white).
constexpr double CrackSpecularPower = 40.0;
// How far the crack sheets' normals tilt with the noise fixed to them.
constexpr double CrackBumpStrength = 0.6;
// Noise cells across the ice's extent on the crack sheets (their bump frequency times the extent).
constexpr double CrackBumpCells = 8.0;

inline double CrackBumpFrequency(double extent)
{
  return CrackBumpCells / extent;
}

// What an interior debug view shows, as the shaders' debug uniforms read it.
enum Debug
{
  DebugNone = 0,
  DebugCracks = 1, // cracks solid red (the paper's Figure 5)
  DebugAir = 2     // air solid green where a bubble covers
};

// The constants above as GLSL #defines, for the snippets that include vtkIceInteriorLook.glsl.
inline std::string Defines()
{
  std::ostringstream defines;
  defines.precision(9);
  defines << std::showpoint << "#define ICE_CRACK_SPECULAR_POWER " << CrackSpecularPower << "\n"
          << "#define ICE_DEBUG_CRACKS " << static_cast<int>(DebugCracks) << "\n"
          << "#define ICE_DEBUG_AIR " << static_cast<int>(DebugAir) << "\n";
  return defines.str();
}
}

#endif
