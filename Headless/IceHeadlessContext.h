// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Internal to IceHeadless: the OpenGL contexts of the EGL and OSMesa back ends, and the routing
// of VTK's GL calls to OSMesa (IceHeadlessGL.cxx).
#ifndef IceHeadlessContext_h
#define IceHeadlessContext_h

#include <memory>
#include <string>

namespace IceHeadless
{
namespace Detail
{
// A GL loader's lookup of a function by name: eglGetProcAddress, OSMesaGetProcAddress.
using ProcAddress = void (*(*)(const char*))();

// An OpenGL >= 3.2 core context without a window or default framebuffer: VTK renders into its
// own framebuffer objects.
class Context
{
public:
  virtual ~Context() = default;
  virtual bool MakeCurrent() = 0;
  virtual bool IsCurrent() const = 0;
  virtual void ReleaseCurrent() = 0;
  // e.g. "EGL device 0 (/dev/dri/renderD128), NVIDIA A100, OpenGL 4.6"
  virtual std::string Describe() const = 0;
  // Where VTK's GL loader finds the functions of this context (glad, VTK >= 9.4).
  virtual ProcAddress GetProcAddress() const = 0;
};

// nullptr and a one-line `error` when the back end cannot give a context.
std::unique_ptr<Context> CreateEGLContext(std::string& error);
std::unique_ptr<Context> CreateOSMesaContext(std::string& error);

// X: DISPLAY is set, the display opens and has GLX.
bool ProbeX(std::string& error, std::string& description);

// Checks the context just made current: OpenGL >= 3.2, reads "RENDERER, OpenGL M.m".
bool CheckVersion(std::string& error, std::string& description);

// Routing of GL calls (IceHeadlessGL.cxx). The VTK libraries call the GL 1.1 functions and
// glXGetProcAddressARB through libGL (glvnd), which only reaches GLX and EGL contexts. This
// library defines the same symbols; with `getProcAddress` set they reach OSMesa, with nullptr
// they forward to glvnd. False (and `error`) when `getProcAddress` lacks one of the functions.
bool RouteGLTo(ProcAddress getProcAddress, std::string& error);
// Whether the process resolves VTK's GL symbols to this library (it must come before libGL and
// libOpenGL in the global symbol scope, i.e. be linked before VTK).
bool GLRoutingActive(std::string& error);
}
}

#endif
