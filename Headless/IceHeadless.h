// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Rendering back ends for programs and tests that use VTK Ice: an X display (VTK's own GLX
// windows), EGL (no X: the EGL device platform, e.g. NVIDIA GPUs, or Mesa's surfaceless
// platform) or OSMesa (Mesa's software renderer, no X and no EGL).
//
// One call selects the back end of a program:
//
//   const std::string error = IceHeadless::Install(name);   // "auto", "x", "egl", "osmesa"
//   if (!error.empty()) { std::cerr << "my-program: " << error << "\n"; return 1; }
//
// Every vtkRenderWindow created afterwards (vtkRenderWindow::New(), vtkNew<vtkRenderWindow>)
// renders through that back end: EGL and OSMesa give a vtkIceHeadlessRenderWindow, always
// offscreen, at any size. The core module VTKIce::RenderingIce knows nothing of this.
//
// Environment:
//   VTKICE_BACKEND         the back end Install("") selects (default auto)
//   VTKICE_EGL_DEVICE      use only this EGL device (an index of eglQueryDevicesEXT)
//   VTKICE_OSMESA_LIBRARY  the OSMesa library to load (default libOSMesa.so.8)
#ifndef IceHeadless_h
#define IceHeadless_h

#include <string>

namespace IceHeadless
{
enum class Backend
{
  Auto,
  X,
  EGL,
  OSMesa
};

// "auto", "x", "egl" or "osmesa"; false for anything else.
bool ParseBackend(const std::string& name, Backend& backend);
const char* BackendName(Backend backend);

// Makes `backend` the back end of every vtkRenderWindow created from now on. Auto picks X when
// DISPLAY names a display that can be opened and has GLX, else EGL, else OSMesa. A back end is
// tried for real (a context is created and must give OpenGL >= 3.2 core) before it is chosen.
// `name` is a back end name, or empty for $VTKICE_BACKEND (auto when unset).
// Returns an empty string on success, otherwise one line saying why no back end could be used.
// Use one back end per process: the EGL and OSMesa GL entry points cannot be mixed.
std::string Install(const std::string& name);
std::string Install(Backend backend);

// The back end chosen by the last successful Install (X when Install was never called).
Backend Installed();

// One line describing what the last successful Install found, e.g.
// "egl: EGL surfaceless Mesa platform, llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5".
std::string InstalledDescription();

// Whether `backend` can be used here; `error` says why not. Auto is never available.
bool Available(Backend backend, std::string& error, std::string* description = nullptr);
}

#endif
