// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A back end that cannot be used fails with one clear line, and a working back end is still
// used afterwards. Unavailability is real, not simulated: X without DISPLAY, an EGL device index
// that does not exist (VTKICE_EGL_DEVICE), an OSMesa library that does not exist
// (VTKICE_OSMESA_LIBRARY), and all three at once for auto.
#include "IceHeadless.h"
#include "IceTestUtilities.h"
#include "vtkIceHeadlessRenderWindow.h"

#include "vtkNew.h"
#include "vtkRenderer.h"

#include <cstdlib>
#include <iostream>

namespace
{
// One line per check, as IceTest::Expect prints it, with the error the back end gave: it starts
// with `start`, holds `contains` and is one line.
bool ExpectError(const std::string& what, const std::string& error, const std::string& start,
  const std::string& contains = std::string())
{
  const bool ok = error.compare(0, start.size(), start) == 0 &&
    error.find(contains) != std::string::npos && error.find('\n') == std::string::npos;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << (error.empty() ? "(no error)" : error)
            << "\n";
  return ok;
}
}

int TestIceBackendUnavailable(int, char*[])
{
  bool ok = true;
  const IceHeadless::Backend before = IceHeadless::Installed();

  unsetenv("DISPLAY");
  setenv("VTKICE_EGL_DEVICE", "99", 1);
  setenv("VTKICE_OSMESA_LIBRARY", "/nonexistent/libOSMesa.so.8", 1);
  ok = ExpectError("x without DISPLAY", IceHeadless::Install("x"),
         "x back end unavailable: DISPLAY is not set") &&
    ok;
  ok = ExpectError("egl with a device that does not exist", IceHeadless::Install("egl"),
         "egl back end unavailable: EGL device 99 does not exist") &&
    ok;
#if VTKICE_HEADLESS_OSMESA
  ok = ExpectError("osmesa without its library", IceHeadless::Install("osmesa"),
         "osmesa back end unavailable: ", "/nonexistent/libOSMesa.so.8") &&
    ok;
#else
  ok = ExpectError("osmesa in a build without it", IceHeadless::Install("osmesa"),
         "osmesa back end unavailable: this build has no osmesa back end") &&
    ok;
#endif
  ok = ExpectError("auto with none of them", IceHeadless::Install("auto"),
         "no rendering back end works (x: DISPLAY is not set; egl: EGL device 99", "; osmesa: ") &&
    ok;
  ok =
    ExpectError("unknown name", IceHeadless::Install("vulkan"), "unknown back end 'vulkan'") && ok;
  const bool unchanged = IceHeadless::Installed() == before;
  std::cout << (unchanged ? "ok   " : "FAIL ") << "failed installs leave the back end at "
            << IceHeadless::BackendName(IceHeadless::Installed()) << "\n";
  ok = unchanged && ok;

  // A headless window whose back end is unavailable: one VTK error, nothing rendered, no crash.
  {
    vtkNew<IceTest::MessageRecorder> messages;
    vtkNew<vtkIceHeadlessRenderWindow> window;
    messages->Watch(window);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    window->SetSize(64, 48);
    window->Render();
    window->Render();
    const bool once = messages->Errors.size() == 1 && window->SupportsOpenGL() == 0 &&
      !window->IsCurrent() && messages->Errors.size() == 1;
    std::cout << (once ? "ok   " : "FAIL ")
              << "window on an unavailable back end: " << messages->Errors.size() << " error(s)\n";
    ok = once && ok;
    ok = ExpectError("its error", messages->Errors.empty() ? "" : messages->Errors[0],
           "egl back end unavailable: EGL device 99 does not exist") &&
      ok;
  }

  // The environment fixed, the same process renders.
  unsetenv("VTKICE_EGL_DEVICE");
  const std::string fixed = IceHeadless::Install("egl");
  std::cout << (fixed.empty() ? "ok   " : "FAIL ") << "egl after the fix: "
            << (fixed.empty() ? IceHeadless::InstalledDescription() : fixed) << "\n";
  ok = fixed.empty() && ok;
  vtkNew<vtkIceHeadlessRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 0.5, 0.0);
  window->AddRenderer(renderer);
  window->SetSize(64, 48);
  window->Render();
  const IceTest::Image image = IceTest::Capture(window);
  const unsigned char orange[3] = { 255, 128, 0 };
  const bool rendered = image.Width == 64 && image.Height == 48 &&
    IceTest::PixelDifference(image.At(10, 10), orange) <= 1;
  std::cout << (rendered ? "ok   " : "FAIL ") << "renders with egl afterwards\n";
  return rendered && ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
