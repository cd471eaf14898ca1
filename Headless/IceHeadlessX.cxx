// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The X back end needs no code of its own (VTK's vtkXOpenGLRenderWindow): this only checks that
// the display of DISPLAY opens and has GLX.
#include "IceHeadlessContext.h"

#include <GL/glx.h>
#include <X11/Xlib.h>

#include <cstdlib>

namespace IceHeadless
{
namespace Detail
{
bool ProbeX(std::string& error, std::string& description)
{
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    error = "DISPLAY is not set";
    return false;
  }
  ::Display* display = XOpenDisplay(name);
  if (!display)
  {
    error = std::string("cannot open display '") + name + "'";
    return false;
  }
  int errorBase = 0;
  int eventBase = 0;
  const bool glx = glXQueryExtension(display, &errorBase, &eventBase);
  XCloseDisplay(display);
  if (!glx)
  {
    error = std::string("display '") + name + "' has no GLX extension";
    return false;
  }
  description = std::string("X display ") + name + " (GLX)";
  return true;
}
}
}
