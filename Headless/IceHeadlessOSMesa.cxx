// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The OSMesa back end: Mesa's software renderer (llvmpipe) without X or EGL. libOSMesa is loaded
// at run time (VTKICE_OSMESA_LIBRARY, default libOSMesa.so.8 from Debian's libosmesa6), so
// programs run where it is not installed; the GL calls of VTK reach it through IceHeadlessGL.cxx.
#include "IceHeadlessContext.h"

#if VTKICE_HAVE_OSMESA
#include <GL/osmesa.h>

#include <dlfcn.h>

#include <cstdlib>
#include <memory>
#include <type_traits>
#include <vector>

namespace IceHeadless
{
namespace Detail
{
namespace
{
struct Library
{
  std::string Path;
  void* Handle = nullptr;
  decltype(&OSMesaCreateContextAttribs) CreateContextAttribs = nullptr;
  decltype(&OSMesaDestroyContext) DestroyContext = nullptr;
  decltype(&OSMesaMakeCurrent) MakeCurrent = nullptr;
  decltype(&OSMesaGetCurrentContext) GetCurrentContext = nullptr;
  decltype(&OSMesaGetProcAddress) GetProcAddress = nullptr;
};

// The loaded library; loaded once per path and never unloaded (Mesa does not support that).
// The list is never destroyed either: OSMesa contexts may outlive static destruction, and a
// destroyed list would leave its libraries unreachable (LeakSanitizer reported them).
const Library* Load(std::string& error)
{
  static auto* const loaded = new std::vector<std::unique_ptr<Library>>();
  const char* configured = std::getenv("VTKICE_OSMESA_LIBRARY");
  const std::string path = configured && *configured ? configured : "libOSMesa.so.8";
  for (const auto& library : *loaded)
  {
    if (library->Path == path)
    {
      return library.get();
    }
  }
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
  {
    const char* reason = dlerror();
    error = (reason ? std::string(reason) : "cannot load " + path) +
      " (Debian: apt-get install libosmesa6)";
    return nullptr;
  }
  auto library = std::make_unique<Library>();
  library->Path = path;
  library->Handle = handle;
  auto symbol = [&](const char* name, auto& function) {
    function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(handle, name));
    return function != nullptr;
  };
  if (!symbol("OSMesaCreateContextAttribs", library->CreateContextAttribs) ||
    !symbol("OSMesaDestroyContext", library->DestroyContext) ||
    !symbol("OSMesaMakeCurrent", library->MakeCurrent) ||
    !symbol("OSMesaGetCurrentContext", library->GetCurrentContext) ||
    !symbol("OSMesaGetProcAddress", library->GetProcAddress))
  {
    error = path + " is not an OSMesa library with OSMesaCreateContextAttribs (Mesa >= 11.2)";
    dlclose(handle);
    return nullptr;
  }
  loaded->push_back(std::move(library));
  return loaded->back().get();
}

class OSMesaContextImpl : public Context
{
public:
  OSMesaContextImpl(const Library* library, OSMesaContext context)
    : Functions(library)
    , Handle(context)
  {
  }
  ~OSMesaContextImpl() override
  {
    if (this->IsCurrent())
    {
      this->ReleaseCurrent();
    }
    this->Functions->DestroyContext(this->Handle);
    if (!this->Functions->GetCurrentContext())
    {
      // No OSMesa context left current: GL calls go to glvnd again (X or EGL).
      RouteGLTo(nullptr, this->RouteError);
    }
  }
  bool MakeCurrent() override
  {
    if (!RouteGLTo(this->Functions->GetProcAddress, this->RouteError))
    {
      return false;
    }
    // VTK draws into its own framebuffer objects; this buffer only satisfies OSMesaMakeCurrent.
    return this->IsCurrent() ||
      this->Functions->MakeCurrent(this->Handle, this->Buffer, GL_UNSIGNED_BYTE, 1, 1);
  }
  bool IsCurrent() const override { return this->Functions->GetCurrentContext() == this->Handle; }
  void ReleaseCurrent() override
  {
    this->Functions->MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
  std::string Describe() const override
  {
    return "OSMesa (" + this->Functions->Path + "), " + this->Renderer;
  }
  ProcAddress GetProcAddress() const override
  {
    return reinterpret_cast<ProcAddress>(this->Functions->GetProcAddress);
  }
  std::string Renderer;
  std::string RouteError;

private:
  const Library* Functions;
  OSMesaContext Handle;
  unsigned char Buffer[4] = { 0, 0, 0, 0 };
};
}

std::unique_ptr<Context> CreateOSMesaContext(std::string& error)
{
  if (!GLRoutingActive(error))
  {
    return nullptr;
  }
  const Library* library = Load(error);
  if (!library)
  {
    return nullptr;
  }
  const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS,
    0, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
    OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  OSMesaContext handle = library->CreateContextAttribs(attributes, nullptr);
  if (!handle)
  {
    error = "OSMesaCreateContextAttribs gave no OpenGL 3.2 core context";
    return nullptr;
  }
  auto context = std::unique_ptr<OSMesaContextImpl>(new OSMesaContextImpl(library, handle));
  if (!context->MakeCurrent())
  {
    error = context->RouteError.empty() ? "OSMesaMakeCurrent failed" : context->RouteError;
    return nullptr;
  }
  if (!CheckVersion(error, context->Renderer))
  {
    return nullptr;
  }
  return context;
}
}
}
#else
namespace IceHeadless
{
namespace Detail
{
std::unique_ptr<Context> CreateOSMesaContext(std::string& error)
{
  error = "this build has no osmesa back end (built without GL/osmesa.h: Debian's libosmesa6-dev)";
  return nullptr;
}
}
}
#endif
