// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceHeadless.h"

#include "IceHeadlessContext.h"
#include "vtkIceHeadlessRenderWindow.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkVersionMacros.h"

#include <GL/gl.h>

#include <cstdio>
#include <cstdlib>

namespace IceHeadless
{
namespace
{
Backend InstalledBackend = Backend::X;
std::string InstalledText;

vtkObject* CreateHeadlessWindow()
{
  vtkIceHeadlessRenderWindow* window = vtkIceHeadlessRenderWindow::New();
  window->SetBackend(InstalledBackend);
  return window;
}

// Overrides vtkRenderWindow with vtkIceHeadlessRenderWindow of the installed back end.
class HeadlessFactory : public vtkObjectFactory
{
public:
  static HeadlessFactory* New() { VTK_STANDARD_NEW_BODY(HeadlessFactory); }
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "VTK Ice headless render windows"; }

protected:
  HeadlessFactory()
  {
    this->RegisterOverride("vtkRenderWindow", "vtkIceHeadlessRenderWindow",
      "EGL or OSMesa render window without a window system", 0, CreateHeadlessWindow);
  }
};

// Headless windows on or off for vtkRenderWindow::New(). vtkObjectFactory asks the factories in
// the order they were registered, and VTK's OpenGL factory (vtkXOpenGLRenderWindow) is
// registered first, so its override is disabled while ours is on.
void UseHeadlessWindows(bool on)
{
  static vtkSmartPointer<HeadlessFactory> factory;
  if (on && !factory)
  {
    factory = vtkSmartPointer<HeadlessFactory>::New();
    vtkObjectFactory::RegisterFactory(factory);
  }
  if (!factory)
  {
    return;
  }
  vtkObjectFactory::SetAllEnableFlags(on ? 0 : 1, "vtkRenderWindow");
  factory->SetEnableFlag(on ? 1 : 0, "vtkRenderWindow", "vtkIceHeadlessRenderWindow");
}
}

bool ParseBackend(const std::string& name, Backend& backend)
{
  for (Backend candidate : { Backend::Auto, Backend::X, Backend::EGL, Backend::OSMesa })
  {
    if (name == BackendName(candidate))
    {
      backend = candidate;
      return true;
    }
  }
  return false;
}

const char* BackendName(Backend backend)
{
  switch (backend)
  {
    case Backend::X:
      return "x";
    case Backend::EGL:
      return "egl";
    case Backend::OSMesa:
      return "osmesa";
    case Backend::Auto:
    default:
      return "auto";
  }
}

bool Available(Backend backend, std::string& error, std::string* description)
{
  std::string text;
  bool ok = false;
  if (backend == Backend::X)
  {
    ok = Detail::ProbeX(error, text);
  }
  else if (backend == Backend::EGL || backend == Backend::OSMesa)
  {
    // A context is created, checked and destroyed; windows create their own.
    auto context = backend == Backend::EGL ? Detail::CreateEGLContext(error)
                                           : Detail::CreateOSMesaContext(error);
    ok = context != nullptr;
    text = ok ? context->Describe() : "";
  }
  else
  {
    error = "auto is not a back end";
  }
  if (ok && description)
  {
    *description = text;
  }
  return ok;
}

std::string Install(Backend backend)
{
  std::string description;
  if (backend == Backend::Auto)
  {
    std::string errors;
    for (Backend candidate : { Backend::X, Backend::EGL, Backend::OSMesa })
    {
      std::string error;
      if (Available(candidate, error, &description))
      {
        backend = candidate;
        break;
      }
      errors += std::string(errors.empty() ? "" : "; ") + BackendName(candidate) + ": " + error;
    }
    if (backend == Backend::Auto)
    {
      return "no rendering back end works (" + errors + ")";
    }
  }
  else
  {
    std::string error;
    if (!Available(backend, error, &description))
    {
      return std::string(BackendName(backend)) + " back end unavailable: " + error;
    }
  }
  InstalledBackend = backend;
  InstalledText = std::string(BackendName(backend)) + ": " + description;
  UseHeadlessWindows(backend != Backend::X);
  return std::string();
}

std::string Install(const std::string& name)
{
  std::string text = name;
  if (text.empty())
  {
    const char* environment = std::getenv("VTKICE_BACKEND");
    text = environment && *environment ? environment : "auto";
  }
  Backend backend = Backend::Auto;
  if (!ParseBackend(text, backend))
  {
    return "unknown back end '" + text + "'" + (name.empty() ? " in VTKICE_BACKEND" : "") +
      " (expected auto, x, egl or osmesa)";
  }
  return Install(backend);
}

Backend Installed()
{
  return InstalledBackend;
}

std::string InstalledDescription()
{
  return InstalledText.empty() ? "x: VTK's default render window" : InstalledText;
}

namespace Detail
{
bool CheckVersion(std::string& error, std::string& description)
{
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  int major = 0;
  int minor = 0;
  if (!version || std::sscanf(version, "%d.%d", &major, &minor) != 2)
  {
    error = "the context gives no OpenGL version";
    return false;
  }
  description = std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " +
    std::to_string(major) + "." + std::to_string(minor);
  if (major < 3 || (major == 3 && minor < 2))
  {
    error = "OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
      " is older than 3.2 (" + description + ")";
    return false;
  }
  return true;
}
}
}
