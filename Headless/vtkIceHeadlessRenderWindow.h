// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A render window without a window system: a vtkGenericOpenGLRenderWindow that owns an EGL or
// OSMesa context (IceHeadless::Backend::EGL, the default, or OSMesa). The context has no
// default framebuffer; VTK renders into its own framebuffer objects, so the window is always
// offscreen, any size, and resizes with SetSize. Read images back as usual
// (vtkWindowToImageFilter, GetPixelData).
//
// IceHeadless::Install makes vtkRenderWindow::New() return these; they can also be created
// directly. The context is created at the first render (or CreateContext()); a back end that is
// not available gives one VTK error and nothing is rendered.
#ifndef vtkIceHeadlessRenderWindow_h
#define vtkIceHeadlessRenderWindow_h

#include "IceHeadless.h"

#include "vtkGenericOpenGLRenderWindow.h"

#include <memory>
#include <string>

namespace IceHeadless
{
namespace Detail
{
class Context;
}
}

class vtkIceHeadlessRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkIceHeadlessRenderWindow* New();
  vtkTypeMacro(vtkIceHeadlessRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // EGL (default) or OSMesa; takes effect when the context is (re)created.
  void SetBackend(IceHeadless::Backend backend);
  IceHeadless::Backend GetBackend() const { return this->Backend; }

  // Creates the context if there is none; false when the back end is not available
  // (GetContextError says why; the error is reported once, not retried).
  bool CreateContext();
  const std::string& GetContextError() const { return this->ContextError; }
  // e.g. "EGL surfaceless Mesa platform, llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5".
  const std::string& GetContextDescription() const { return this->ContextDescription; }

  void Initialize() override;
  void OpenGLInit() override;
  void Finalize() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  void ReleaseCurrent() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  int GetColorBufferSizes(int* rgba) override;

protected:
  vtkIceHeadlessRenderWindow();
  ~vtkIceHeadlessRenderWindow() override;

  // Loads the GL functions from the context: GLEW (VTK < 9.4) or glad (see the .cxx).
  void OpenGLInitContext() override;

private:
  vtkIceHeadlessRenderWindow(const vtkIceHeadlessRenderWindow&) = delete;
  void operator=(const vtkIceHeadlessRenderWindow&) = delete;

  IceHeadless::Backend Backend = IceHeadless::Backend::EGL;
  std::unique_ptr<IceHeadless::Detail::Context> Context;
  std::string ContextError;
  std::string ContextDescription;
};

#endif
