// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceTestResources.h"

#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkIceVTKCompat.h"

#include <dlfcn.h>
#include <malloc.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace IceTest
{
namespace
{
const char* ErrorName(GLenum code)
{
  switch (code)
  {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "unknown GL error";
  }
}

// glIsTexture is OpenGL 1.1, which programs call directly in libOpenGL rather than through
// GLEW. With the osmesa back end only the functions libIceHeadless routes reach the OSMesa
// context, so take glIsTexture from glXGetProcAddressARB as GLEW does for everything newer: the
// first definition in the process, libIceHeadless's (routed) when the program loads it first,
// else glvnd's, which serves GLX and EGL contexts alike.
using IsTextureFunction = GLboolean (*)(GLuint);
IsTextureFunction IsTexture()
{
#if VTKICE_GL_LOADER_GLAD
  // glad (VTK >= 9.4): every GL function, 1.1 included, is the pointer VTK loaded for its context.
  return glIsTexture;
#else
  using GetProcAddress = void (*(*)(const GLubyte*))();
  static IsTextureFunction function = [] {
    auto get = reinterpret_cast<GetProcAddress>(dlsym(RTLD_DEFAULT, "glXGetProcAddressARB"));
    auto found = get
      ? reinterpret_cast<IsTextureFunction>(get(reinterpret_cast<const GLubyte*>("glIsTexture")))
      : nullptr;
    return found ? found : &glIsTexture;
  }();
  return function;
#endif
}

// The largest name any census has seen: names freed since then may be reused below it.
GLuint HighestNameSeen = 0;

class CountingOutputWindow : public vtkOutputWindow
{
public:
  static CountingOutputWindow* New();
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override
  {
    ++this->Errors;
    this->Last = text ? text : "";
    if (!this->Quiet)
    {
      this->Superclass::DisplayErrorText(text);
    }
  }
  void DisplayWarningText(const char* text) override
  {
    ++this->Warnings;
    this->Last = text ? text : "";
    if (!this->Quiet)
    {
      this->Superclass::DisplayWarningText(text);
    }
  }
  void DisplayGenericWarningText(const char* text) override
  {
    ++this->Warnings;
    this->Last = text ? text : "";
    if (!this->Quiet)
    {
      this->Superclass::DisplayGenericWarningText(text);
    }
  }
  int Errors = 0;
  int Warnings = 0;
  bool Quiet = false;
  std::string Last;
};
vtkStandardNewMacro(CountingOutputWindow);

vtkSmartPointer<CountingOutputWindow> Counter;
vtkSmartPointer<vtkOutputWindow> PreviousOutput;
vtkLogger::Verbosity PreviousVerbosity = vtkLogger::VERBOSITY_INFO;
}

void MessageCounter::Install(bool quiet)
{
  PreviousOutput = vtkOutputWindow::GetInstance();
  Counter = vtkSmartPointer<CountingOutputWindow>::New();
  Counter->Quiet = quiet;
  vtkOutputWindow::SetInstance(Counter);
  if (quiet)
  {
    // VTK also logs errors and warnings to stderr through vtkLogger.
    PreviousVerbosity = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
}

void MessageCounter::Uninstall()
{
  if (Counter && Counter->Quiet)
  {
    vtkLogger::SetStderrVerbosity(PreviousVerbosity);
  }
  vtkOutputWindow::SetInstance(PreviousOutput);
  PreviousOutput = nullptr;
}

int MessageCounter::Errors() const
{
  return Counter ? Counter->Errors : 0;
}

int MessageCounter::Warnings() const
{
  return Counter ? Counter->Warnings : 0;
}

std::string MessageCounter::Last() const
{
  return Counter ? Counter->Last : std::string();
}

std::string TakeGLErrors(vtkRenderWindow* window)
{
  window->MakeCurrent();
  std::string errors;
  // glGetError returns each recorded error once; a context records a handful at most.
  for (int i = 0; i < 32; ++i)
  {
    const GLenum code = glGetError();
    if (code == GL_NO_ERROR)
    {
      break;
    }
    errors += (errors.empty() ? "" : ", ") + std::string(ErrorName(code));
  }
  return errors;
}

std::string GLCensus::Describe() const
{
  std::ostringstream text;
  text << this->Total() << " (" << this->Textures << " textures, " << this->Buffers << " buffers, "
       << this->Framebuffers << " framebuffers, " << this->Renderbuffers << " renderbuffers, "
       << this->VertexArrays << " vertex arrays, " << this->Programs << " programs, "
       << this->Shaders << " shaders, " << this->Queries << " queries)";
  return text.str();
}

GLCensus TakeGLCensus(vtkRenderWindow* window)
{
  window->MakeCurrent();
  GLCensus census;
  const IsTextureFunction isTexture = IsTexture();
  const GLuint margin = 4096;
  GLuint limit = std::max(HighestNameSeen, margin) + margin;
  for (GLuint name = 1; name <= limit; ++name)
  {
    bool used = false;
    auto count = [&used](GLboolean exists, int& counter) {
      if (exists)
      {
        ++counter;
        used = true;
      }
    };
    count(isTexture(name), census.Textures);
    count(glIsBuffer(name), census.Buffers);
    count(glIsFramebuffer(name), census.Framebuffers);
    count(glIsRenderbuffer(name), census.Renderbuffers);
    count(glIsVertexArray(name), census.VertexArrays);
    count(glIsProgram(name), census.Programs);
    count(glIsShader(name), census.Shaders);
    count(glIsQuery(name), census.Queries);
    if (used)
    {
      HighestNameSeen = std::max(HighestNameSeen, name);
      limit = std::max(limit, name + margin);
    }
  }
  return census;
}

long ResidentKiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, 6, "VmRSS:") == 0)
    {
      return std::stol(line.substr(6));
    }
  }
  return 0;
}

long HeapInUseKiB()
{
  const struct mallinfo2 info = mallinfo2();
  return static_cast<long>((info.uordblks + info.hblkhd) / 1024);
}
}
