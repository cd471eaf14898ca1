// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceHeadlessRenderWindow.h"

#include "IceHeadlessContext.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkIceVTKCompat.h"

vtkStandardNewMacro(vtkIceHeadlessRenderWindow);

vtkIceHeadlessRenderWindow::vtkIceHeadlessRenderWindow()
{
  // There is no default framebuffer to show the image in: Frame() leaves it in VTK's display
  // framebuffer, where ReadPixels (front or back) finds it.
  this->FrameBlitMode = vtkOpenGLRenderWindow::NoBlit;
  this->SetOffScreenRendering(1);
  this->SetWindowName("VTK Ice (headless)");
}

vtkIceHeadlessRenderWindow::~vtkIceHeadlessRenderWindow()
{
  this->Finalize();
}

void vtkIceHeadlessRenderWindow::SetBackend(IceHeadless::Backend backend)
{
  if (backend != IceHeadless::Backend::EGL && backend != IceHeadless::Backend::OSMesa)
  {
    vtkErrorMacro(<< "a headless render window renders with egl or osmesa, not "
                  << IceHeadless::BackendName(backend));
    return;
  }
  if (backend != this->Backend)
  {
    this->Finalize();
    this->Backend = backend;
    this->ContextError.clear();
    this->Modified();
  }
}

bool vtkIceHeadlessRenderWindow::CreateContext()
{
  if (this->Context)
  {
    return true;
  }
  if (!this->ContextError.empty())
  {
    return false;
  }
  std::string error;
  this->Context = this->Backend == IceHeadless::Backend::OSMesa
    ? IceHeadless::Detail::CreateOSMesaContext(error)
    : IceHeadless::Detail::CreateEGLContext(error);
  if (!this->Context)
  {
    this->ContextError =
      std::string(IceHeadless::BackendName(this->Backend)) + " back end unavailable: " + error;
    vtkErrorMacro(<< this->ContextError);
    return false;
  }
  this->ContextDescription = this->Context->Describe();
  return true;
}

void vtkIceHeadlessRenderWindow::Initialize()
{
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
}

void vtkIceHeadlessRenderWindow::OpenGLInit()
{
  if (!this->CreateContext() || !this->Context->MakeCurrent())
  {
    return;
  }
  this->Superclass::OpenGLInit();
}

#if VTKICE_GL_LOADER_GLAD
namespace
{
vtkOpenGLRenderWindow::VTKOpenGLAPIProc LoadFromContext(void* context, const char* name)
{
  const auto lookup = static_cast<IceHeadless::Detail::Context*>(context)->GetProcAddress();
  return reinterpret_cast<vtkOpenGLRenderWindow::VTKOpenGLAPIProc>(lookup(name));
}
}

// VTK >= 9.4 loads every GL function (1.1 included) with glad through the loader it is given:
// the context's own, so no call goes through libGL (GLX) and no routing is needed for OSMesa.
void vtkIceHeadlessRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized && this->Context)
  {
    this->SetOpenGLSymbolLoader(&LoadFromContext, this->Context.get());
  }
  this->Superclass::OpenGLInitContext();
}
#else
// Debian's GLEW is built for GLX only. glewInit() first loads the GL entry points
// (glewContextInit, through glXGetProcAddressARB: glvnd's stubs reach the current EGL context,
// and IceHeadlessGL.cxx sends them to OSMesa) and then runs glxewInit(), which needs a current
// GLX display and returns GLEW_ERROR_NO_GLX_DISPLAY. VTK 9.1's OpenGLInitContext treats every
// result but GLEW_OK as fatal ("GLEW could not be initialized") and never marks the window
// initialised. With EGL or OSMesa the GL entry points are loaded by then and GLX is not used, so
// GLEW_ERROR_NO_GLX_DISPLAY means success here. This override is the only place VTK Ice calls
// glewInit; it does what the superclass does after a successful glewInit.
void vtkIceHeadlessRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized)
  {
    const GLenum result = glewInit();
    if (result != GLEW_OK && result != GLEW_ERROR_NO_GLX_DISPLAY)
    {
      vtkErrorMacro(<< "GLEW could not be initialized: "
                    << reinterpret_cast<const char*>(glewGetErrorString(result)));
      return;
    }
    if (!GLEW_VERSION_3_2)
    {
      vtkErrorMacro(<< "the " << IceHeadless::BackendName(this->Backend)
                    << " context has no OpenGL 3.2");
      return;
    }
    this->GlewInitValid = true;
    this->Initialized = true;

    GLfloat range[2] = { 1.0f, 1.0f };
    this->MaximumHardwareLineWidth = 1.0f;
    glGetFloatv(
      this->LineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE, range);
    if (glGetError() == GL_NO_ERROR)
    {
      this->MaximumHardwareLineWidth = range[1];
    }
  }
  // Initialized: the superclass only records the context creation time.
  this->Superclass::OpenGLInitContext();
}
#endif

void vtkIceHeadlessRenderWindow::Finalize()
{
  if (this->Context)
  {
    if (this->Context->MakeCurrent())
    {
      this->ReleaseGraphicsResources(this);
    }
    this->Context.reset();
  }
  this->Initialized = false;
}

void vtkIceHeadlessRenderWindow::MakeCurrent()
{
  if (this->Context)
  {
    this->Context->MakeCurrent();
  }
}

bool vtkIceHeadlessRenderWindow::IsCurrent()
{
  return this->Context && this->Context->IsCurrent();
}

void vtkIceHeadlessRenderWindow::ReleaseCurrent()
{
  if (this->IsCurrent())
  {
    this->Context->ReleaseCurrent();
  }
}

int vtkIceHeadlessRenderWindow::SupportsOpenGL()
{
  return this->CreateContext() ? 1 : 0;
}

vtkTypeBool vtkIceHeadlessRenderWindow::IsDirect()
{
  return 1;
}

int vtkIceHeadlessRenderWindow::GetColorBufferSizes(int* rgba)
{
  GLint bound = 0;
  if (this->Initialized && rgba)
  {
    this->MakeCurrent();
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    if (bound == 0)
    {
      // No default framebuffer to query: VTK renders into its RGBA8 render framebuffer.
      rgba[0] = rgba[1] = rgba[2] = rgba[3] = 8;
      return 32;
    }
  }
  return this->Superclass::GetColorBufferSizes(rgba);
}

void vtkIceHeadlessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << IceHeadless::BackendName(this->Backend) << "\n";
  os << indent << "Context: "
     << (this->Context ? this->ContextDescription
                       : (this->ContextError.empty() ? "(none yet)" : this->ContextError))
     << "\n";
}
