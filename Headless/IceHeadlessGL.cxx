// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Routing of VTK's GL calls to OSMesa.
//
// Debian's VTK links libGL/libOpenGL (glvnd) and a GLX-only GLEW. glvnd sends GL calls to the
// context made current through GLX or EGL; an OSMesa context is neither, so VTK's calls would
// reach glvnd's no-op dispatch. VTK reaches GL in two ways, and this file defines both, so that
// a program that links this library before VTK resolves them here (the dynamic linker binds each
// symbol to the first library in the global scope that defines it):
//   - the GL 1.1 functions that the VTK 9.1 OpenGL libraries import directly (the list below;
//     Script.TestHeadlessGLSymbols checks that it covers every one of them);
//   - glXGetProcAddressARB, through which GLEW loads every other entry point.
// Normally both forward to glvnd (found with RTLD_NEXT). After RouteGLTo(OSMesaGetProcAddress)
// they go to OSMesa instead (GLX's own glX* functions still go to glvnd).
#include "IceHeadlessContext.h"

#include <GL/gl.h>

#include <dlfcn.h>

#include <atomic>
#include <cstring>

// clang-format off
#define ICE_GL_FUNCTIONS(F)                                                                    \
  F(void, glBindTexture, (GLenum a, GLuint b), (a, b))                                         \
  F(void, glClear, (GLbitfield a), (a))                                                        \
  F(void, glClearColor, (GLclampf a, GLclampf b, GLclampf c, GLclampf d), (a, b, c, d))        \
  F(void, glClearDepth, (GLclampd a), (a))                                                     \
  F(void, glClearStencil, (GLint a), (a))                                                      \
  F(void, glColorMask, (GLboolean a, GLboolean b, GLboolean c, GLboolean d), (a, b, c, d))     \
  F(void, glCopyTexImage2D,                                                                    \
    (GLenum a, GLint b, GLenum c, GLint d, GLint e, GLsizei f, GLsizei g, GLint h),            \
    (a, b, c, d, e, f, g, h))                                                                  \
  F(void, glCullFace, (GLenum a), (a))                                                         \
  F(void, glDeleteTextures, (GLsizei a, const GLuint* b), (a, b))                              \
  F(void, glDepthFunc, (GLenum a), (a))                                                        \
  F(void, glDepthMask, (GLboolean a), (a))                                                     \
  F(void, glDisable, (GLenum a), (a))                                                          \
  F(void, glDrawArrays, (GLenum a, GLint b, GLsizei c), (a, b, c))                             \
  F(void, glDrawElements, (GLenum a, GLsizei b, GLenum c, const GLvoid* d), (a, b, c, d))      \
  F(void, glEnable, (GLenum a), (a))                                                           \
  F(void, glFinish, (void), ())                                                                \
  F(void, glFlush, (void), ())                                                                 \
  F(void, glGenTextures, (GLsizei a, GLuint* b), (a, b))                                       \
  F(void, glGetBooleanv, (GLenum a, GLboolean* b), (a, b))                                     \
  F(void, glGetDoublev, (GLenum a, GLdouble* b), (a, b))                                       \
  F(GLenum, glGetError, (void), ())                                                            \
  F(void, glGetFloatv, (GLenum a, GLfloat* b), (a, b))                                         \
  F(void, glGetIntegerv, (GLenum a, GLint* b), (a, b))                                         \
  F(const GLubyte*, glGetString, (GLenum a), (a))                                              \
  F(void, glGetTexImage, (GLenum a, GLint b, GLenum c, GLenum d, GLvoid* e), (a, b, c, d, e))  \
  F(void, glGetTexLevelParameteriv, (GLenum a, GLint b, GLenum c, GLint* d), (a, b, c, d))     \
  F(GLboolean, glIsEnabled, (GLenum a), (a))                                                   \
  F(void, glLineWidth, (GLfloat a), (a))                                                       \
  F(void, glPixelStorei, (GLenum a, GLint b), (a, b))                                          \
  F(void, glPointSize, (GLfloat a), (a))                                                       \
  F(void, glReadBuffer, (GLenum a), (a))                                                       \
  F(void, glReadPixels,                                                                        \
    (GLint a, GLint b, GLsizei c, GLsizei d, GLenum e, GLenum f, GLvoid* g),                   \
    (a, b, c, d, e, f, g))                                                                     \
  F(void, glScissor, (GLint a, GLint b, GLsizei c, GLsizei d), (a, b, c, d))                   \
  F(void, glTexEnvi, (GLenum a, GLenum b, GLint c), (a, b, c))                                 \
  F(void, glTexImage1D,                                                                        \
    (GLenum a, GLint b, GLint c, GLsizei d, GLint e, GLenum f, GLenum g, const GLvoid* h),     \
    (a, b, c, d, e, f, g, h))                                                                  \
  F(void, glTexImage2D,                                                                        \
    (GLenum a, GLint b, GLint c, GLsizei d, GLsizei e, GLint f, GLenum g, GLenum h,            \
      const GLvoid* i),                                                                        \
    (a, b, c, d, e, f, g, h, i))                                                               \
  F(void, glTexParameterf, (GLenum a, GLenum b, GLfloat c), (a, b, c))                         \
  F(void, glTexParameterfv, (GLenum a, GLenum b, const GLfloat* c), (a, b, c))                 \
  F(void, glTexParameteri, (GLenum a, GLenum b, GLint c), (a, b, c))                           \
  F(void, glTexSubImage2D,                                                                     \
    (GLenum a, GLint b, GLint c, GLint d, GLsizei e, GLsizei f, GLenum g, GLenum h,            \
      const GLvoid* i),                                                                        \
    (a, b, c, d, e, f, g, h, i))                                                               \
  F(void, glViewport, (GLint a, GLint b, GLsizei c, GLsizei d), (a, b, c, d))
// clang-format on

namespace
{
using IceHeadless::Detail::ProcAddress;
using Proc = void (*)();

enum : int
{
#define ICE_GL_INDEX(type, name, parameters, arguments) Index_##name,
  ICE_GL_FUNCTIONS(ICE_GL_INDEX)
#undef ICE_GL_INDEX
    FunctionCount
};

const char* const FunctionNames[FunctionCount] = {
#define ICE_GL_NAME(type, name, parameters, arguments) #name,
  ICE_GL_FUNCTIONS(ICE_GL_NAME)
#undef ICE_GL_NAME
};

// The definition that would be used without this library: the next one in the symbol scope
// (glvnd's), or libOpenGL's if this library is not in the global scope at all.
void* NextDefinition(const char* name)
{
  void* address = dlsym(RTLD_NEXT, name);
  if (!address)
  {
    static void* const openGL = dlopen("libOpenGL.so.0", RTLD_LAZY | RTLD_LOCAL);
    static void* const glx = dlopen("libGLX.so.0", RTLD_LAZY | RTLD_LOCAL);
    address = openGL ? dlsym(openGL, name) : nullptr;
    address = (!address && glx) ? dlsym(glx, name) : address;
  }
  return address;
}

struct NativeTable
{
  void* Functions[FunctionCount];
  void* GetProcAddress;
  NativeTable()
  {
    for (int i = 0; i < FunctionCount; ++i)
    {
      this->Functions[i] = NextDefinition(FunctionNames[i]);
    }
    this->GetProcAddress = NextDefinition("glXGetProcAddressARB");
  }
};

const NativeTable& Native()
{
  static const NativeTable table;
  return table;
}

// OSMesa's entry points, filled before Route is set.
void* Routed[FunctionCount];
std::atomic<ProcAddress> Route{ nullptr };

void* Target(int index)
{
  return Route.load(std::memory_order_acquire) ? Routed[index] : Native().Functions[index];
}

Proc GetProcAddress(const GLubyte* name)
{
  const ProcAddress route = Route.load(std::memory_order_acquire);
  const char* text = reinterpret_cast<const char*>(name);
  if (route && text && std::strncmp(text, "glX", 3) != 0)
  {
    return route(text);
  }
  auto native = reinterpret_cast<Proc (*)(const GLubyte*)>(Native().GetProcAddress);
  return native ? native(name) : nullptr;
}

// Marks this library's own address for GLRoutingActive.
void Anchor()
{
}
}

extern "C"
{
#define ICE_GL_DEFINE(type, name, parameters, arguments)                                           \
  __attribute__((visibility("default"))) type name parameters                                      \
  {                                                                                                \
    return reinterpret_cast<type(*) parameters>(Target(Index_##name)) arguments;                   \
  }
  ICE_GL_FUNCTIONS(ICE_GL_DEFINE)
#undef ICE_GL_DEFINE

  __attribute__((visibility("default"))) Proc glXGetProcAddressARB(const GLubyte* name)
  {
    return GetProcAddress(name);
  }

  __attribute__((visibility("default"))) Proc glXGetProcAddress(const GLubyte* name)
  {
    return GetProcAddress(name);
  }
}

namespace IceHeadless
{
namespace Detail
{
bool RouteGLTo(ProcAddress getProcAddress, std::string& error)
{
  if (getProcAddress && getProcAddress != Route.load(std::memory_order_acquire))
  {
    for (int i = 0; i < FunctionCount; ++i)
    {
      Routed[i] = reinterpret_cast<void*>(getProcAddress(FunctionNames[i]));
      if (!Routed[i])
      {
        error = std::string("the GL library has no ") + FunctionNames[i];
        return false;
      }
    }
  }
  Route.store(getProcAddress, std::memory_order_release);
  return true;
}

bool GLRoutingActive(std::string& error)
{
  Dl_info self;
  if (!dladdr(reinterpret_cast<void*>(&Anchor), &self))
  {
    error = "cannot locate the IceHeadless library in memory";
    return false;
  }
  // The global scope, where the dynamic linker looks first when it binds VTK's GL imports
  // (RTLD_DEFAULT would also search this library's own dependencies: in a process that loaded
  // it later, e.g. Python importing vtkice, it would find itself and be wrong).
  static void* const global = dlopen(nullptr, RTLD_LAZY);
  for (const char* name : { "glClear", "glXGetProcAddressARB" })
  {
    Dl_info found;
    void* address = global ? dlsym(global, name) : nullptr;
    if (!address || !dladdr(address, &found) || found.dli_fbase != self.dli_fbase)
    {
      error = std::string("the program resolves ") + name + " to " +
        (address && found.dli_fname ? found.dli_fname : "nothing") +
        ", not to libIceHeadless: link VTKIce::Headless before VTK (see headless.md)";
      return false;
    }
  }
  for (int i = 0; i < FunctionCount; ++i)
  {
    if (!Native().Functions[i])
    {
      error = std::string("no GL library defines ") + FunctionNames[i];
      return false;
    }
  }
  return true;
}
}
}
