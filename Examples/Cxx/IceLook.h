// The look of ice-render's scene as named settings: every vtkIceMapper and vtkIceCubeMapPass
// parameter and the camera, each with the library's own range. One table serves the command-line
// options (--NAME VALUE), the preset files (NAME = VALUE), --print-preset and the interactive
// viewer.
#ifndef IceLook_h
#define IceLook_h

#include <string>
#include <utility>
#include <vector>

class vtkCamera;
class vtkIceCubeMapPass;
class vtkIceMapper;
class vtkIcePass;

namespace IceLook
{
// What the settings act on. CubeMaps is the scene's cube-map pass, set on Pass while the dynamic
// environment is on.
struct Target
{
  vtkIceMapper* Mapper = nullptr;
  vtkIcePass* Pass = nullptr;
  vtkIceCubeMapPass* CubeMaps = nullptr;
  vtkCamera* Camera = nullptr;
};

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
};

// Every setting, in the order --help and --print-preset list them.
const std::vector<Setting>& Settings();
const Setting* Find(const std::string& name);

// The names a Choice accepts, in the order of the library's enum.
std::vector<std::string> Choices(const std::string& name);

// The library's range of a Number or Integer setting ("[0, 1]"), empty for others.
std::string Range(const std::string& name);

// The value of `name` in ice-render's scene when nothing sets it: the library's defaults, the
// dynamic cube map on. Empty for the camera settings (the scene places the camera to frame the
// model).
std::string Default(const std::string& name);

// Sets `name` to `value` on `target`. Returns an empty string, or why the value is refused (with
// the library's range or the accepted names): values out of range are refused, not clamped.
std::string Apply(const Target& target, const std::string& name, const std::string& value);

// The current value of `name` on `target`, as Apply reads it.
std::string Value(const Target& target, const std::string& name);

// A list of assignments: a preset's, then the command line's, applied in order.
using Assignments = std::vector<std::pair<std::string, std::string>>;

// Reads a preset file: "NAME = VALUE" lines, '#' starts a comment. Returns an empty string or
// the first problem (with the file's line number); nothing is applied here.
std::string ReadPreset(const std::string& path, Assignments& assignments);

// The effective settings of `target` as a preset: every look setting, and of the camera settings
// those named in `cameraGiven` (the camera is the scene's otherwise).
std::string WritePreset(const Target& target, const std::vector<std::string>& cameraGiven);

// Applies `assignments` in order, stopping at the first refused one (returned).
std::string ApplyAll(const Target& target, const Assignments& assignments);

// Checks `assignments` against a scratch mapper and cube-map pass (before any scene exists).
std::string Check(const Assignments& assignments);
}

#endif
