// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The look of an ice scene as named settings: every vtkIceMapper and vtkIceCubeMapPass parameter,
// the tone curve and exposure (vtkToneMappingPass) and the camera, each with the library's own
// range. One table serves ice-render's command-line options (--NAME VALUE), the preset files
// (NAME = VALUE, vtkIceLookPreset.cxx), --print-preset, the interactive viewer and, through the
// wrapped vtkIceLook, Python (the web viewer).
// Not wrapped: Python reaches it through vtkIceLook.
#ifndef vtkIceLookTable_h
#define vtkIceLookTable_h

#include "LookIceModule.h" // For export macro

#include <string>
#include <utility>
#include <vector>

class vtkCamera;
class vtkIceCubeMapPass;
class vtkIceMapper;
class vtkIcePass;
class vtkToneMappingPass;

namespace vtkIceLookTable
{
// What the settings act on. CubeMaps is the scene's cube-map pass, set on Pass while the dynamic
// environment is on.
struct Target
{
  vtkIceMapper* Mapper = nullptr;
  vtkIcePass* Pass = nullptr;
  vtkIceCubeMapPass* CubeMaps = nullptr;
  vtkCamera* Camera = nullptr;
  // Around the ice pass, for "tone-mapping" and "exposure"; may be null, and they are refused.
  vtkToneMappingPass* ToneMapping = nullptr;
};

// Puts `pass` in the state of "no tone mapping" (tone-mapping none, exposure 0): VTK's Clamp.
LOOKICE_EXPORT void ResetToneMapping(vtkToneMappingPass* pass);
// Whether the look `pass` holds needs it in the render passes: not when it only clamps.
LOOKICE_EXPORT bool AsksForToneMapping(vtkToneMappingPass* pass);

enum class Kind
{
  Number,  // a decimal number
  Integer, // a whole number
  Switch,  // on or off (on the command line: --NAME, --no-NAME)
  Choice,  // one of a few names
  Vector   // three numbers: x,y,z
};

struct Setting
{
  const char* Name;
  Kind Type;
  const char* Help;
  bool Camera; // a camera setting: printed in a preset only when it was given
  // Another setting's value in other units (eta: 1 / ior): left out of written presets.
  const char* SynonymOf = nullptr;
};

// Every setting, in the order --help and --print-preset list them.
LOOKICE_EXPORT const std::vector<Setting>& Settings();
LOOKICE_EXPORT const Setting* Find(const std::string& name);

// The names a Choice accepts, in the order of the library's enum.
LOOKICE_EXPORT const std::vector<std::string>& Choices(const std::string& name);

// The library's range of a Number or Integer setting ("[0, 1]"), empty for others.
LOOKICE_EXPORT std::string Range(const std::string& name);

// The library's range of a Number or Integer setting as numbers; false for others.
LOOKICE_EXPORT bool Bounds(const std::string& name, double& low, double& high);

// The value of `name` in ice-render's scene when nothing sets it: the library's defaults, the
// dynamic cube map on. Empty for the camera settings (the scene places the camera to frame the
// model).
LOOKICE_EXPORT std::string Default(const std::string& name);

// Sets `name` to `value` on `target`. Returns an empty string, or why the value is refused (with
// the library's range or the accepted names): values out of range are refused, not clamped.
LOOKICE_EXPORT std::string Apply(
  const Target& target, const std::string& name, const std::string& value);

// The current value of `name` on `target`, as Apply reads it.
LOOKICE_EXPORT std::string Value(const Target& target, const std::string& name);

// A list of assignments: a preset's, then the command line's, applied in order.
using Assignments = std::vector<std::pair<std::string, std::string>>;

// Reads a preset file: "NAME = VALUE" lines, '#' starts a comment. Returns an empty string or
// the first problem (with the file's line number); nothing is applied here.
LOOKICE_EXPORT std::string ReadPreset(const std::string& path, Assignments& assignments);

// The effective settings of `target` as a preset: every look setting, and of the camera settings
// those named in `cameraGiven` (the camera is the scene's otherwise).
LOOKICE_EXPORT std::string WritePreset(
  const Target& target, const std::vector<std::string>& cameraGiven);

// Applies `assignments` in order, stopping at the first refused one (returned).
LOOKICE_EXPORT std::string ApplyAll(const Target& target, const Assignments& assignments);

// Checks `assignments` against a scratch mapper and cube-map pass (before any scene exists).
LOOKICE_EXPORT std::string Check(const Assignments& assignments);
}

#endif // vtkIceLookTable_h
