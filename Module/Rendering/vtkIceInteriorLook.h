// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The look of the ice's interior (cracks and air), in one place for both ways of drawing it: the
// paper's passes (vtkIceInterior's crack and air mappers) and the screen-space interior
// (vtkIceInteriorTable). The constants are handed to the GLSL of both as #defines; the
// shading functions they share are in glsl/vtkIceInteriorLookFS.glsl.
#ifndef vtkIceInteriorLook_h
#define vtkIceInteriorLook_h

#include <sstream>
#include <string>

namespace vtkIceInteriorLook
{
// The cracks' highlight: VTK's specular term of this power (specular 1, white).
constexpr double CrackSpecularPower = 40.0;
// The cracks as sheets (the screen-space interior, vtkIceProperty::CrackReflection): how much of
// the bumps' tilt the mirror keeps, the share of a crack's radius along its outline that scatters
// white, and how white per unit of CrackReflection.
constexpr double CrackMirrorBumps = 0.08;
constexpr double CrackEdgeWidth = 0.025;
constexpr double CrackEdge = 1.25;
// How far the crack sheets' normals tilt with the noise fixed to them.
constexpr double CrackBumpStrength = 0.6;
// Noise cells across the ice's extent on the crack sheets (their bump frequency times the extent).
constexpr double CrackBumpCells = 24.0;

// The milky core (vtkIceProperty::MilkyCoreRadius): the optical depth of a ray through its centre
// at Milkiness 1 (the core covers 1 - exp(-depth) of what is behind it), the colour its air
// scatters and the share of the air planes' bubbles left at its rim.
constexpr double CoreOpticalDepth = 4.0;
constexpr double CoreColour[3] = { 0.88, 0.92, 0.95 };
constexpr double CoreRimAir = 0.3;
// The core's shape: a plume, as water freezing from the faces inwards leaves its air last in a
// column below the middle (an ice cube's cloud is seldom a ball). Its radii against
// MilkyCoreRadius: CoreHeight along the model's y axis, CoreWidth across; its centre CoreDrop of
// the half height below the middle.
constexpr double CoreHeight = 1.3;
constexpr double CoreWidth = 0.8;
constexpr double CoreDrop = 0.12;

// The bubbles (vtkIceProperty::BubbleDensity): one may sit in each cell of a grid fixed to the ice,
// BubbleCells cells across its extent; the core's radius where there is no core; the share of
// the grid's columns that hold a vertical stream; how much a bubble fades per extent of ice in
// front of it.
constexpr double BubbleCells = 56.0;
constexpr double BubbleCoreRadius = 0.6;
constexpr double BubbleStreams = 0.03;
// The largest share of the cells that hold a bubble of the cloud, even where it is densest.
constexpr double BubbleFull = 0.6;
constexpr double BubbleDepthFade = 2.0;
// A few larger bubbles, one at most in each cell of a grid BubbleLargeCells times coarser, in this
// share of its cells at the cloud's densest: the fine grid's bubbles must fit its cells, so a
// single grid showed bubbles of nearly one size.
constexpr double BubbleLargeCells = 7.0;
constexpr double BubbleLargeShare = 0.35;

// The density of the core's air (iceCoreDensity) that gives a ray through its centre the optical
// depth CoreOpticalDepth * milkiness: the density's integral along that ray is sqrt(pi).
inline double CoreDensity(double milkiness)
{
  return CoreOpticalDepth * milkiness / 1.772453850905516;
}

// The core's frame for ice of these (model) bounds: its centre, and the scale per axis from model
// coordinates to the frame where the core's radius is 1.
inline void CoreFrame(const double bounds[6], double radius, double centre[3], double scale[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const double half = 0.5 * (bounds[2 * axis + 1] - bounds[2 * axis]);
    const double coreRadius = half * radius * (axis == 1 ? CoreHeight : CoreWidth);
    centre[axis] =
      0.5 * (bounds[2 * axis] + bounds[2 * axis + 1]) - (axis == 1 ? CoreDrop * half : 0.0);
    scale[axis] = 1.0 / (coreRadius > 1.0e-12 ? coreRadius : 1.0e-12);
  }
}

// CoreFrame as the shaders' float uniforms.
inline void CoreFrame(const double bounds[6], double radius, float centre[3], float scale[3])
{
  double c[3];
  double s[3];
  CoreFrame(bounds, radius, c, s);
  for (int axis = 0; axis < 3; ++axis)
  {
    centre[axis] = static_cast<float>(c[axis]);
    scale[axis] = static_cast<float>(s[axis]);
  }
}

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
          << "#define ICE_CORE_COLOUR vec3(" << CoreColour[0] << ", " << CoreColour[1] << ", "
          << CoreColour[2] << ")\n"
          << "#define ICE_CORE_RIM_AIR " << CoreRimAir << "\n"
          << "#define ICE_BUBBLE_STREAMS " << BubbleStreams << "\n"
          << "#define ICE_BUBBLE_FULL " << BubbleFull << "\n"
          << "#define ICE_BUBBLE_LARGE_CELLS " << BubbleLargeCells << "\n"
          << "#define ICE_BUBBLE_LARGE_SHARE " << BubbleLargeShare << "\n"
          << "#define ICE_CRACK_MIRROR_BUMPS " << CrackMirrorBumps << "\n"
          << "#define ICE_CRACK_EDGE_WIDTH " << CrackEdgeWidth << "\n"
          << "#define ICE_CRACK_EDGE " << CrackEdge << "\n"
          << "#define ICE_DEBUG_CRACKS " << static_cast<int>(DebugCracks) << "\n"
          << "#define ICE_DEBUG_AIR " << static_cast<int>(DebugAir) << "\n";
  return defines.str();
}
}

#endif
