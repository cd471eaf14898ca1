// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render's command line: what to render, where, and the look (vtkIceLookTable's settings,
// presets).
#ifndef IceRenderOptions_h
#define IceRenderOptions_h

#include "vtkIceLookTable.h"

#include <string>
#include <vector>

namespace IceRenderOptions
{
struct Options
{
  std::string Model = "cube";
  // Empty: DefaultEnvironment().
  std::string Environment;
  std::string Output = "ice.png";
  std::string Backend; // empty: $VTKICE_BACKEND, else auto
  int Width = 1024;
  int Height = 768;
  bool Interactive = false;
  bool Static = false;
  bool Fit = false;
  bool PrintPreset = false;
  int Turntable = 0;         // frames around the model; 0: one image
  double TurntableRate = 24; // frames per second of the video
  // The look: the preset's settings, then the command line's (which override them).
  vtkIceLookTable::Assignments Look;
  std::vector<std::string> CameraGiven; // camera settings given, for --print-preset
};

// Returns -1 when the arguments are fine, otherwise the exit code (--help: 0; errors, with one
// line on standard error: 2).
int Parse(int argc, char* argv[], Options& options);

// The environment without --env: the forest panorama, or "sky" where Debian's blender-data is
// not installed.
std::string DefaultEnvironment();

// Whether the look should be tone mapped by default in `environment`: a photographed HDR
// panorama (a name of IceScene::Panoramas(), an .hdr or .exr file) and no curve in `look`.
bool WantsToneMapping(const std::string& environment, const vtkIceLookTable::Assignments& look);

// Prints "ice-render: MESSAGE" on standard error (made printable) and returns `code`.
int Fail(const std::string& message, int code);

// The file of a preset: FILE as given, or NAME of a shipped preset (clear, glacier, frosted,
// snow) in the installed share/vtkice/presets or the source tree. Empty when there is none.
std::string FindPreset(const std::string& preset);
}

#endif
