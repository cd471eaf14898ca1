// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The default ice-render scene rendered through one back end (--backend x|egl|osmesa), against
// the reviewed X render (the TestIceTeapot baseline): VTK's image comparison plus the strict one.
// Then pixel checks that the ice itself is drawn (hiding the teapot changes the pixels inside its
// projected bounds, and only there), and that a resized window renders the same picture again.
// Returns 125 (skipped) for x when DISPLAY is not set.
#include "IceHeadless.h"
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "vtkIceHeadlessRenderWindow.h"

#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace
{
// The window pixels covered by the projection of `actor`'s bounding box, widened by `margin`.
void ProjectedBounds(vtkRenderer* renderer, vtkActor* actor, int margin, int box[4])
{
  const double* bounds = actor->GetBounds();
  box[0] = box[2] = 1 << 30;
  box[1] = box[3] = -(1 << 30);
  for (int corner = 0; corner < 8; ++corner)
  {
    renderer->SetWorldPoint(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)], 1.0);
    renderer->WorldToDisplay();
    const double* display = renderer->GetDisplayPoint();
    box[0] = std::min(box[0], static_cast<int>(display[0]) - margin);
    box[1] = std::max(box[1], static_cast<int>(display[0]) + margin);
    box[2] = std::min(box[2], static_cast<int>(display[1]) - margin);
    box[3] = std::max(box[3], static_cast<int>(display[1]) + margin);
  }
}

bool Same(const IceTest::Image& a, const IceTest::Image& b)
{
  return a.Width == b.Width && a.Height == b.Height && a.RGB == b.RGB;
}
}

int TestIceBackend(int argc, char* argv[])
{
  std::string name;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], "--backend") == 0)
    {
      name = argv[i + 1];
    }
  }
  IceHeadless::Backend backend;
  if (!IceHeadless::ParseBackend(name, backend) || backend == IceHeadless::Backend::Auto)
  {
    std::cerr << "usage: TestIceBackend --backend x|egl|osmesa\n";
    return EXIT_FAILURE;
  }
  if (backend == IceHeadless::Backend::X && !std::getenv("DISPLAY"))
  {
    std::cout << "x: DISPLAY is not set, skipped\n";
    return 125;
  }
  const std::string error = IceHeadless::Install(backend);
  if (!error.empty())
  {
    std::cerr << error << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "back end " << IceHeadless::InstalledDescription() << "\n";

  std::string loadError;
  vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel("teapot", loadError);
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", loadError);
  if (!model || !environment)
  {
    std::cerr << loadError << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  vtkActor* ice = IceScene::Populate(renderer, model, environment);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();

  // vtkRenderWindow::New() gives the back end's window.
  bool ok = true;
  auto* headless = vtkIceHeadlessRenderWindow::SafeDownCast(window);
  if (backend == IceHeadless::Backend::X)
  {
    ok = !headless && window->IsA("vtkXOpenGLRenderWindow");
  }
  else
  {
    const std::string expected = backend == IceHeadless::Backend::EGL ? "EGL" : "OSMesa";
    ok = headless && headless->GetBackend() == backend &&
      headless->GetContextDescription().compare(0, expected.size(), expected) == 0;
    const char* device = std::getenv("VTKICE_EGL_DEVICE");
    if (ok && backend == IceHeadless::Backend::EGL && device && *device)
    {
      ok = headless->GetContextDescription().find("EGL device " + std::string(device)) == 0;
    }
  }
  std::cout << (ok ? "ok   " : "FAIL ") << "window " << window->GetClassName()
            << (headless ? ", context " + headless->GetContextDescription() : std::string())
            << "\n";

  // The same picture as the X render.
  ok = IceTest::CheckImage(argc, argv, window) && ok;

  // The ice is drawn: hiding it changes many pixels inside its projected bounds, none outside.
  const IceTest::Image withIce = IceTest::Capture(window);
  ice->VisibilityOff();
  window->Render();
  const IceTest::Image withoutIce = IceTest::Capture(window);
  ice->VisibilityOn();
  int box[4];
  ProjectedBounds(renderer, ice, 2, box);
  size_t inside = 0;
  size_t changedInside = 0;
  size_t changedOutside = 0;
  for (int y = 0; y < withIce.Height; ++y)
  {
    for (int x = 0; x < withIce.Width; ++x)
    {
      const int d = IceTest::PixelDifference(withIce.At(x, y), withoutIce.At(x, y));
      if (x >= box[0] && x <= box[1] && y >= box[2] && y <= box[3])
      {
        ++inside;
        changedInside += d > 8 ? 1 : 0;
      }
      else
      {
        changedOutside += d > 0 ? 1 : 0;
      }
    }
  }
  const double fraction = inside ? static_cast<double>(changedInside) / inside : 0.0;
  // Measured on llvmpipe: 25.5 % of 47 827 pixels (the bounds include air around the teapot).
  const bool drawn = changedInside >= 5000 && fraction >= 0.15 && changedOutside == 0;
  std::cout << (drawn ? "ok   " : "FAIL ") << "ice drawn: " << 100.0 * fraction << "% of the "
            << inside << " pixels in its projected bounds change by more than 8/255 without it, "
            << changedOutside << " pixels outside change\n";
  ok = drawn && ok;

  // Resizing: a smaller frame, then the original size gives the original picture again.
  window->SetSize(211, 157);
  window->Render();
  const IceTest::Image small = IceTest::Capture(window);
  window->SetSize(400, 300);
  window->Render();
  const bool resized =
    small.Width == 211 && small.Height == 157 && Same(IceTest::Capture(window), withIce);
  std::cout << (resized ? "ok   " : "FAIL ") << "resized to " << small.Width << "x" << small.Height
            << " and back to 400x300: the same picture\n";
  ok = resized && ok;

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
