// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceRenderOptions.h"

#include "IceHeadless.h"
#include "vtkIceModelFileChecks.h"
#include "IceOutputFile.h"
#include "IceScene.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sys/stat.h>
#include <string>
#include <unistd.h>
#include <vector>

// The looks in Examples/Presets, as --help and a refused --preset name them.
#define VTKICE_SHIPPED_PRESETS "clear, ice-cube, lake, glacier, frosted, snow, paper"
// The look ice-render starts from: what a user recognises as ice. --preset replaces it.
#define VTKICE_DEFAULT_PRESET "ice-cube"

namespace IceRenderOptions
{
namespace
{
const char* const Usage =
  "usage: ice-render [--model cube|teapot|block|sphere|FILE] [--env NAME|sky|test|PATH]\n"
  "                  [--size WxH]"
  " [--out FILE] [--static] [--interactive] [--turntable N [--rate FPS]]\n"
  "                  [--preset NAME|FILE] [--print-preset] [look and camera options]\n"
  "                  [--backend auto|x|egl|osmesa]\n"
  "Renders a model as ice (default: an ice cube on the ground in the forest panorama, the\n"
  VTKICE_DEFAULT_PRESET " look, tone mapped) to ice.png.\n"
  "  --model  cube, teapot, block, sphere or a .vtp/.vtk/.stl/.obj/.ply file; default cube\n"
  "  --env    a photographed HDR panorama of Debian's blender-data by name: city, courtyard,\n"
  "           forest (default), interior, night, studio, sunrise, sunset (the ice on a ground\n"
  "           with its shadow; --tone-mapping filmic unless the look names a curve); sky (the\n"
  "           small landscape; the default where blender-data is missing), test, a folder with\n"
  "           cube faces px nx py ny pz nz (any image type), a cross image (4:3 or 3:4) or an\n"
  "           equirectangular panorama (2:1; .hdr/.exr too)\n"
  "  --size   image size WxH, each in [16, 8192], default 1024x768\n"
  "  --out    output image, .png or .jpg (default ice.png); replaced only once the new image\n"
  "           is complete: a failed or interrupted run leaves the old file as it was\n"
  "  --static     no landscape and no dynamic cube map: the ice sees the environment map only\n"
  "  --interactive  a window: trackball camera, keys for the effects (h shows them)\n"
  "  --turntable N  N images around the model, OUT-0001.png ... (and OUT.mp4 with ffmpeg);\n"
  "                 N in [1, 3600]\n"
  "  --rate FPS     frames per second of the turntable's video, in [1, 240], default 24\n"
  "  --preset     a look: a shipped one (" VTKICE_SHIPPED_PRESETS ")\n"
  "               or a file of NAME = VALUE lines, default " VTKICE_DEFAULT_PRESET "; settings it\n"
  "               does not name have the library's defaults; options on the command line\n"
  "               override it\n"
  "  --print-preset  print the effective look as a preset and exit\n"
  "  --fit        frame the ice: the camera keeps its direction and moves to show it whole\n"
  "  --backend  x (X display), egl or osmesa (no X needed); default $VTKICE_BACKEND or auto:\n"
  "             x when DISPLAY works, else egl, else osmesa\n"
  "Look and camera (switches: --NAME on, --no-NAME off; --one-sided is --no-two-sided):\n";

bool ParseSize(const std::string& text, int& width, int& height)
{
  char x = 0;
  char extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) == 3 && x == 'x' &&
    width >= 16 && height >= 16 && width <= 8192 && height <= 8192;
}

bool ParseInteger(const std::string& text, int low, int high, int& value)
{
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || !end || *end != '\0' || parsed < low || parsed > high)
  {
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

// The default preset's settings; empty where it cannot be read (the library's defaults then).
vtkIceLookTable::Assignments DefaultLook()
{
  vtkIceLookTable::Assignments look;
  const std::string path = FindPreset(VTKICE_DEFAULT_PRESET);
  if (path.empty() || !vtkIceLookTable::ReadPreset(path, look).empty())
  {
    look.clear();
  }
  return look;
}

void PrintUsage()
{
  std::cout << Usage;
  const vtkIceLookTable::Assignments look = DefaultLook();
  for (const vtkIceLookTable::Setting& setting : vtkIceLookTable::Settings())
  {
    std::string syntax = std::string("--") + setting.Name;
    switch (setting.Type)
    {
      case vtkIceLookTable::Kind::Number:
      case vtkIceLookTable::Kind::Integer:
        syntax += " " + vtkIceLookTable::Range(setting.Name);
        break;
      case vtkIceLookTable::Kind::Switch:
        syntax += ", --no-" + std::string(setting.Name);
        break;
      case vtkIceLookTable::Kind::Choice:
      {
        std::string names;
        for (const std::string& n : vtkIceLookTable::Choices(setting.Name))
        {
          names += (names.empty() ? "" : "|") + n;
        }
        syntax += " " + names;
        break;
      }
      case vtkIceLookTable::Kind::Vector:
        syntax += " X,Y,Z";
        break;
    }
    std::string initial = vtkIceLookTable::Default(setting.Name);
    for (const auto& assignment : look)
    {
      if (assignment.first == setting.Name)
      {
        initial = assignment.second;
      }
    }
    syntax += initial.empty() ? ", default: framing the model" : ", default " + initial;
    if (std::string(setting.Name) == "cube-map")
    {
      syntax += " (off with --static)";
    }
    std::cout << "  " << syntax << "\n      " << setting.Help << "\n";
  }
}

// The options ice-render knows, without their dashes.
std::vector<std::string> OptionNames()
{
  std::vector<std::string> names = { "model", "env", "size", "out", "static", "interactive",
    "turntable", "rate", "preset", "print-preset", "fit", "backend", "help", "one-sided" };
  for (const vtkIceLookTable::Setting& setting : vtkIceLookTable::Settings())
  {
    names.push_back(setting.Name);
    if (setting.Type == vtkIceLookTable::Kind::Switch)
    {
      names.push_back(std::string("no-") + setting.Name);
    }
  }
  return names;
}

// Edits (insert, delete, replace, swap two neighbours) between `a` and `b`.
size_t EditDistance(const std::string& a, const std::string& b)
{
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i)
  {
    for (size_t j = 0; j <= b.size(); ++j)
    {
      if (i == 0 || j == 0)
      {
        d[i][j] = i + j;
        continue;
      }
      d[i][j] = std::min(
        { d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1) });
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
      {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// " (did you mean --NAME?)" for the known option nearest to `arg` when it is near enough to be
// a typo (a third of its letters, at least two), else "".
std::string Suggestion(const std::string& arg)
{
  if (arg.empty() || arg[0] != '-')
  {
    return std::string();
  }
  const std::string typed = arg.substr(
    arg.find_first_not_of('-') == std::string::npos ? arg.size() : arg.find_first_not_of('-'));
  const auto equals = typed.find('=');
  if (equals != std::string::npos)
  {
    const std::string name = typed.substr(0, equals);
    const std::vector<std::string> names = OptionNames();
    const std::vector<std::string> valued = { "model", "env", "size", "out", "backend", "preset",
      "turntable", "rate" };
    const vtkIceLookTable::Setting* setting = vtkIceLookTable::Find(name);
    if ((setting && setting->Type != vtkIceLookTable::Kind::Switch) ||
      std::find(valued.begin(), valued.end(), name) != valued.end())
    {
      return " (the value follows a space: --" + name + " " + typed.substr(equals + 1) + ")";
    }
    if (std::find(names.begin(), names.end(), name) != names.end())
    {
      return " (--" + name + " takes no value)";
    }
  }
  std::string best;
  size_t bestDistance = std::max<size_t>(2, typed.size() / 3) + 1;
  for (const std::string& name : OptionNames())
  {
    const size_t distance = EditDistance(typed, name);
    if (distance < bestDistance)
    {
      best = name;
      bestDistance = distance;
    }
  }
  return best.empty() || typed.empty() ? std::string() : " (did you mean --" + best + "?)";
}

// Whether `path` is a regular file.
bool IsFile(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}
}

//------------------------------------------------------------------------------
std::string DefaultEnvironment()
{
  // Silently: the lanes and scripts without the package keep their one-line messages, and
  // --help says which environment the default is where it is missing.
  return std::ifstream(IceScene::PanoramaFolder() + "/forest.exr").good() ? "forest" : "sky";
}

bool WantsToneMapping(const std::string& environment, const vtkIceLookTable::Assignments& look)
{
  for (const auto& setting : look)
  {
    if (setting.first == "tone-mapping")
    {
      return false;
    }
  }
  if (IceScene::IsPanorama(environment))
  {
    return true;
  }
  std::string ext = environment.size() > 4 ? environment.substr(environment.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".hdr" || ext == ".exr";
}

int Fail(const std::string& message, int code)
{
  // Arguments and file names are echoed: terminal escapes in them are not passed on.
  std::cerr << "ice-render: " << vtkIceModelFileChecks::Printable(message, 2000) << "\n";
  return code;
}

//------------------------------------------------------------------------------
std::string FindPreset(const std::string& preset)
{
  if (IsFile(preset))
  {
    return preset;
  }
  if (preset.empty() || preset.find('/') != std::string::npos)
  {
    return std::string();
  }
  std::vector<std::string> folders;
  char exe[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if (length > 0)
  {
    exe[length] = '\0';
    const std::string bin = std::string(exe).substr(0, std::string(exe).rfind('/'));
    folders.push_back(bin + "/../share/vtkice/presets");
  }
  folders.push_back(VTKICE_PRESET_SOURCE_DIR);
  for (const std::string& folder : folders)
  {
    const std::string path = folder + "/" + preset + ".ice";
    if (IsFile(path))
    {
      return path;
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
int Parse(int argc, char* argv[], Options& options)
{
  vtkIceLookTable::Assignments preset = DefaultLook();
  vtkIceLookTable::Assignments given;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    std::string text;
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        return false;
      }
      out = argv[++i];
      return true;
    };
    // Settings of the look and the camera.
    const std::string name = arg.compare(0, 2, "--") == 0 ? arg.substr(2) : std::string();
    const bool negated = name.compare(0, 3, "no-") == 0;
    const vtkIceLookTable::Setting* setting =
      vtkIceLookTable::Find(negated ? name.substr(3) : name);
    if (arg == "--one-sided")
    {
      given.emplace_back("two-sided", "off");
      continue;
    }
    if (setting && setting->Type == vtkIceLookTable::Kind::Switch)
    {
      given.emplace_back(setting->Name, negated ? "off" : "on");
      continue;
    }
    if (setting && !negated)
    {
      if (!value(text))
      {
        return Fail("option " + arg + " needs a value (see --help)", 2);
      }
      const std::string problem = vtkIceLookTable::Check({ { setting->Name, text } });
      if (!problem.empty())
      {
        // "bad NAME ..." as an option.
        return Fail(problem.compare(0, 4, "bad ") == 0 ? "bad --" + problem.substr(4) : problem, 2);
      }
      given.emplace_back(setting->Name, text);
      if (setting->Camera)
      {
        options.CameraGiven.push_back(setting->Name);
      }
      continue;
    }
    if (arg == "--help" || arg == "-h")
    {
      PrintUsage();
      return 0;
    }
    else if (arg == "--interactive")
    {
      options.Interactive = true;
    }
    else if (arg == "--static")
    {
      options.Static = true;
    }
    else if (arg == "--fit")
    {
      options.Fit = true;
    }
    else if (arg == "--print-preset")
    {
      options.PrintPreset = true;
    }
    else if (arg == "--model" || arg == "--env" || arg == "--out" || arg == "--size" ||
      arg == "--backend" || arg == "--preset" || arg == "--turntable" || arg == "--rate")
    {
      if (!value(text))
      {
        return Fail("option " + arg + " needs a value (see --help)", 2);
      }
      if (arg == "--model")
      {
        options.Model = text;
      }
      else if (arg == "--env")
      {
        options.Environment = text;
      }
      else if (arg == "--out")
      {
        if (IceOutputFile::ImageFormat(text).empty())
        {
          return Fail("bad --out '" + text + "' (the name must end in .png, .jpg or .jpeg)", 2);
        }
        options.Output = text;
      }
      else if (arg == "--backend")
      {
        IceHeadless::Backend backend;
        if (!IceHeadless::ParseBackend(text, backend))
        {
          return Fail("bad --backend '" + text + "' (expected auto, x, egl or osmesa)", 2);
        }
        options.Backend = text;
      }
      else if (arg == "--preset")
      {
        const std::string path = FindPreset(text);
        if (path.empty())
        {
          return Fail(
            "no preset '" + text + "' (a file, or one of the shipped " VTKICE_SHIPPED_PRESETS ")",
            2);
        }
        preset.clear();
        const std::string problem = vtkIceLookTable::ReadPreset(path, preset);
        if (!problem.empty())
        {
          return Fail(problem, 2);
        }
        for (const auto& assignment : preset)
        {
          if (vtkIceLookTable::Find(assignment.first)->Camera)
          {
            options.CameraGiven.push_back(assignment.first);
          }
        }
      }
      else if (arg == "--turntable")
      {
        if (!ParseInteger(text, 1, 3600, options.Turntable))
        {
          return Fail("bad --turntable '" + text + "' (frames, a whole number in [1, 3600])", 2);
        }
      }
      else if (arg == "--rate")
      {
        int rate = 0;
        if (!ParseInteger(text, 1, 240, rate))
        {
          return Fail(
            "bad --rate '" + text + "' (frames per second, a whole number in [1, 240])", 2);
        }
        options.TurntableRate = rate;
      }
      else if (!ParseSize(text, options.Width, options.Height))
      {
        return Fail("bad --size '" + text + "' (expected WxH, each 16..8192)", 2);
      }
    }
    else
    {
      const std::string suggestion = Suggestion(arg);
      return Fail("unknown argument '" + arg + "'" +
          (suggestion.empty() ? std::string(" (see --help)") : suggestion),
        2);
    }
  }
  if (options.Interactive && options.Turntable > 0)
  {
    return Fail("--interactive and --turntable exclude each other", 2);
  }
  options.Look = preset;
  options.Look.insert(options.Look.end(), given.begin(), given.end());
  return -1;
}
}
