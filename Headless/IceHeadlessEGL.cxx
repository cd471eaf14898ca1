// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The EGL back end: an OpenGL 3.2+ core context without a surface (EGL_KHR_surfaceless_context).
//
// Displays are tried in this order, the first that gives a context wins:
//   1. hardware devices of the EGL device platform (EGL_EXT_platform_device), e.g. NVIDIA GPUs,
//      whose driver has no surfaceless platform, or DRM render nodes;
//   2. Mesa's surfaceless platform (EGL_MESA_platform_surfaceless);
//   3. software devices of the device platform (EGL_MESA_device_software).
// VTKICE_EGL_DEVICE=N uses device N only.
#include "IceHeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

namespace IceHeadless
{
namespace Detail
{
namespace
{
std::string ErrorName(EGLint code)
{
  switch (code)
  {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
    {
      std::ostringstream text;
      text << "EGL error 0x" << std::hex << code;
      return text.str();
    }
  }
}

bool HasExtension(const char* extensions, const char* name)
{
  if (!extensions)
  {
    return false;
  }
  const size_t length = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + length, name))
  {
    const bool starts = p == extensions || p[-1] == ' ';
    const bool ends = p[length] == '\0' || p[length] == ' ';
    if (starts && ends)
    {
      return true;
    }
  }
  return false;
}

// A display that gave a context once, with its config. Displays are never terminated: an EGL
// display is one per platform and device in the process, shared by every window, and
// eglTerminate would end them all.
struct Display
{
  EGLDisplay Handle = EGL_NO_DISPLAY;
  EGLConfig Config = nullptr;
  std::string Name;
};

struct Candidate
{
  std::string Name;
  EGLenum Platform;
  void* Native;
};

class EGLContextImpl : public Context
{
public:
  EGLContextImpl(const Display& display, EGLContext context)
    : Owner(display)
    , Handle(context)
  {
  }
  ~EGLContextImpl() override
  {
    if (this->IsCurrent())
    {
      this->ReleaseCurrent();
    }
    eglDestroyContext(this->Owner.Handle, this->Handle);
  }
  bool MakeCurrent() override
  {
    std::string unused;
    RouteGLTo(nullptr, unused);
    if (this->IsCurrent())
    {
      return true;
    }
    eglBindAPI(EGL_OPENGL_API);
    return eglMakeCurrent(this->Owner.Handle, EGL_NO_SURFACE, EGL_NO_SURFACE, this->Handle) ==
      EGL_TRUE;
  }
  bool IsCurrent() const override { return eglGetCurrentContext() == this->Handle; }
  void ReleaseCurrent() override
  {
    eglMakeCurrent(this->Owner.Handle, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  std::string Describe() const override { return this->Owner.Name + ", " + this->Renderer; }
  ProcAddress GetProcAddress() const override
  {
    return reinterpret_cast<ProcAddress>(&eglGetProcAddress);
  }
  std::string Renderer;

private:
  Display Owner;
  EGLContext Handle;
};

std::map<std::string, Display>& Displays()
{
  static std::map<std::string, Display> displays;
  return displays;
}

// Creates a context on `display` (initialising it first if needed), makes it current and checks
// the OpenGL version.
std::unique_ptr<EGLContextImpl> TryDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay,
  const Candidate& candidate, std::string& error)
{
  auto known = Displays().find(candidate.Name);
  Display display;
  if (known != Displays().end())
  {
    display = known->second;
  }
  else
  {
    display.Name = candidate.Name;
    display.Handle = getPlatformDisplay(candidate.Platform, candidate.Native, nullptr);
    EGLint major = 0;
    EGLint minor = 0;
    if (display.Handle == EGL_NO_DISPLAY)
    {
      error = candidate.Name + ": no display (" + ErrorName(eglGetError()) + ")";
      return nullptr;
    }
    if (!eglInitialize(display.Handle, &major, &minor))
    {
      error = candidate.Name + ": eglInitialize failed (" + ErrorName(eglGetError()) + ")";
      return nullptr;
    }
    if (!HasExtension(
          eglQueryString(display.Handle, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
    {
      error = candidate.Name + ": no EGL_KHR_surfaceless_context";
      return nullptr;
    }
    const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
      EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
      EGL_NONE };
    EGLint count = 0;
    if (!eglChooseConfig(display.Handle, configAttributes, &display.Config, 1, &count) || count < 1)
    {
      error = candidate.Name + ": no RGBA8 desktop OpenGL config";
      return nullptr;
    }
  }

  if (!eglBindAPI(EGL_OPENGL_API))
  {
    error = candidate.Name + ": no desktop OpenGL (eglBindAPI failed)";
    return nullptr;
  }
  const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
  EGLContext handle =
    eglCreateContext(display.Handle, display.Config, EGL_NO_CONTEXT, contextAttributes);
  if (handle == EGL_NO_CONTEXT)
  {
    error = candidate.Name + ": no OpenGL 3.2 core context (" + ErrorName(eglGetError()) + ")";
    return nullptr;
  }
  auto context = std::unique_ptr<EGLContextImpl>(new EGLContextImpl(display, handle));
  if (!context->MakeCurrent())
  {
    error = candidate.Name + ": eglMakeCurrent failed (" + ErrorName(eglGetError()) + ")";
    return nullptr;
  }
  std::string versionError;
  if (!CheckVersion(versionError, context->Renderer))
  {
    error = candidate.Name + ": " + versionError;
    return nullptr;
  }
  Displays()[candidate.Name] = display;
  return context;
}

bool ParseDevice(const char* text, int& device)
{
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 0 || value > 1000)
  {
    return false;
  }
  device = static_cast<int>(value);
  return true;
}
}

std::unique_ptr<Context> CreateEGLContext(std::string& error)
{
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!clientExtensions || !getPlatformDisplay ||
    !HasExtension(clientExtensions, "EGL_EXT_platform_base"))
  {
    error = "the EGL library has no platform displays (EGL_EXT_platform_base)";
    return nullptr;
  }

  // The devices of the EGL device platform.
  std::vector<EGLDeviceEXT> devices;
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryDeviceString =
    reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLint deviceCount = 0;
  if (HasExtension(clientExtensions, "EGL_EXT_platform_device") && queryDevices &&
    queryDeviceString && queryDevices(0, nullptr, &deviceCount) && deviceCount > 0)
  {
    devices.resize(deviceCount);
    queryDevices(deviceCount, devices.data(), &deviceCount);
    devices.resize(deviceCount);
  }
  auto deviceCandidate = [&](int index) {
    const char* extensions = queryDeviceString(devices[index], EGL_EXTENSIONS);
    std::string name = "EGL device " + std::to_string(index);
    if (HasExtension(extensions, "EGL_EXT_device_drm"))
    {
      const char* file = queryDeviceString(devices[index], EGL_DRM_DEVICE_FILE_EXT);
      name += std::string(" (") + (file ? file : "DRM") + ")";
    }
    else if (HasExtension(extensions, "EGL_MESA_device_software"))
    {
      name += " (Mesa software)";
    }
    return Candidate{ name, EGL_PLATFORM_DEVICE_EXT, devices[index] };
  };
  auto isSoftware = [&](int index) {
    return HasExtension(
      queryDeviceString(devices[index], EGL_EXTENSIONS), "EGL_MESA_device_software");
  };

  std::vector<Candidate> candidates;
  const char* chosen = std::getenv("VTKICE_EGL_DEVICE");
  if (chosen && *chosen)
  {
    int index = 0;
    if (!ParseDevice(chosen, index))
    {
      error = std::string("VTKICE_EGL_DEVICE='") + chosen + "' is not a device index";
      return nullptr;
    }
    if (index >= static_cast<int>(devices.size()))
    {
      error = "EGL device " + std::to_string(index) + " does not exist (VTKICE_EGL_DEVICE; " +
        (devices.empty() ? std::string("no EGL devices")
                         : "devices 0 to " + std::to_string(devices.size() - 1)) +
        ")";
      return nullptr;
    }
    candidates.push_back(deviceCandidate(index));
  }
  else
  {
    for (int i = 0; i < static_cast<int>(devices.size()); ++i)
    {
      if (!isSoftware(i))
      {
        candidates.push_back(deviceCandidate(i));
      }
    }
    if (HasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
    {
      candidates.push_back(Candidate{
        "EGL surfaceless Mesa platform", EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY });
    }
    for (int i = 0; i < static_cast<int>(devices.size()); ++i)
    {
      if (isSoftware(i))
      {
        candidates.push_back(deviceCandidate(i));
      }
    }
  }
  if (candidates.empty())
  {
    error = "no EGL device and no surfaceless platform";
    return nullptr;
  }

  std::string errors;
  for (const Candidate& candidate : candidates)
  {
    std::string candidateError;
    if (auto context = TryDisplay(getPlatformDisplay, candidate, candidateError))
    {
      return context;
    }
    errors += (errors.empty() ? "" : "; ") + candidateError;
  }
  error = errors;
  return nullptr;
}
}
}
