// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's command line: the usage text and the checking of every option.
#include "IceBench.h"
#include "IceHeadless.h"
#include "vtkIceModelFileChecks.h"
#include "IceOutputFile.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace
{
const char* const Usage =
  "usage: ice-bench [--quick] [--frames N] [--csv FILE] [--plot FILE] [--markdown FILE]\n"
  "                 [--only TEXT] [--multisamples N] [--backend auto|x|egl|osmesa]\n"
  "Times ice against plain VTK (same scene, a vtkPolyDataMapper with Phong shading) at\n"
  "1024x768, offscreen, glFinish after every frame, and prints a table of medians and ratios.\n"
  "  --quick     a few configurations and frames (under a minute)\n"
  "  --frames N  timed frames per configuration (default 20, quick 4), after warm-up; in a\n"
  "              full run configurations slower than 200 ms a frame get fewer (at least 5)\n"
  "  --csv       the results as CSV (default ice-bench.csv; '' for none)\n"
  "  --plot      a PNG of ratios and scaling curves (default none)\n"
  "  --markdown  the tables and the machine as Markdown (default none)\n"
  "  --only      only the groups whose id contains TEXT (e.g. dynamic, cracks, objects, look);\n"
  "              tree: only the trace's tree and the cracks' grid, build times and sizes\n"
  "  --multisamples N  the window's multisampling (default: VTK's, 4 on llvmpipe)\n"
  "  --backend   x (X display), egl or osmesa (no X needed); default $VTKICE_BACKEND or auto\n";
}

int IceBench::Fail(const std::string& message, int code)
{
  // Arguments and file names are echoed: terminal escapes in them are not passed on.
  std::cerr << "ice-bench: " << vtkIceModelFileChecks::Printable(message, 2000) << "\n";
  return code;
}

int IceBench::Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      return 0;
    }
    if (arg == "--quick")
    {
      options.Quick = true;
      continue;
    }
    if (arg != "--frames" && arg != "--csv" && arg != "--plot" && arg != "--markdown" &&
      arg != "--only" && arg != "--multisamples" && arg != "--backend")
    {
      return Fail("unknown argument '" + arg + "' (see --help)", 2);
    }
    if (i + 1 >= argc)
    {
      return Fail("option " + arg + " needs a value (see --help)", 2);
    }
    const std::string value = argv[++i];
    if (arg == "--frames")
    {
      char extra = 0;
      if (std::sscanf(value.c_str(), "%d%c", &options.Frames, &extra) != 1 || options.Frames < 1 ||
        options.Frames > 10000)
      {
        return Fail("bad --frames '" + value + "' (expected 1..10000)", 2);
      }
    }
    else if (arg == "--multisamples")
    {
      char extra = 0;
      if (std::sscanf(value.c_str(), "%d%c", &options.MultiSamples, &extra) != 1 ||
        options.MultiSamples < 0 || options.MultiSamples > 16)
      {
        return Fail("bad --multisamples '" + value + "' (expected 0..16)", 2);
      }
    }
    else if (arg == "--csv")
    {
      options.Csv = value;
    }
    else if (arg == "--plot")
    {
      if (!value.empty() && IceOutputFile::ImageFormat(value).empty())
      {
        return Fail("bad --plot '" + value + "' (the name must end in .png, .jpg or .jpeg)", 2);
      }
      options.Plot = value;
    }
    else if (arg == "--markdown")
    {
      options.Markdown = value;
    }
    else if (arg == "--only")
    {
      options.Only = value;
    }
    else
    {
      IceHeadless::Backend backend;
      if (!IceHeadless::ParseBackend(value, backend))
      {
        return Fail("bad --backend '" + value + "' (expected auto, x, egl or osmesa)", 2);
      }
      options.Backend = value;
    }
  }
  return -1;
}
