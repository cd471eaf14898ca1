// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Colour by array, as any VTK mapper: with ScalarVisibility and point scalars the mapped colour
// tints the ice point by point (refraction stays); with ScalarVisibility off the ice keeps
// IceColor, and off is the default (input scalars tint only when asked to). The sphere's
// elevation runs from blue (bottom) to red (top) through the lookup table.
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkElevationFilter.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include "vtkIceCubeMapSource.h"

#include <iostream>

namespace
{
struct Region
{
  double Red = 0;
  double Blue = 0;
  double Spread = 0; // standard deviation of the green channel: the environment still shows
};

// Mean red and blue of the pixels of rows [y0, y1) within the central columns.
Region Measure(const IceTest::Image& image, int y0, int y1)
{
  Region region;
  double green = 0;
  double green2 = 0;
  int count = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = 120; x < 180; ++x)
    {
      const unsigned char* p = image.At(x, y);
      region.Red += p[0];
      region.Blue += p[2];
      green += p[1];
      green2 += double(p[1]) * p[1];
      ++count;
    }
  }
  region.Red /= count;
  region.Blue /= count;
  green /= count;
  region.Spread = std::sqrt(std::max(0.0, green2 / count - green * green));
  return region;
}
}

int TestIceColorByArray(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0.0, -0.5, 0.0);
  elevation->SetHighPoint(0.0, 0.5, 0.0);

  vtkNew<vtkLookupTable> table;
  table->SetHueRange(0.667, 0.0); // blue to red
  table->SetTableRange(0.0, 1.0);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(0.0, 1.0);
  IceTest::UseCleanOptics(mapper);
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);

  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ice);
  renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 128));
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 2.6);
  renderer->ResetCameraClippingRange();

  // As made: the elevation scalars do not tint.
  const bool offByDefault = !mapper->GetScalarVisibility();
  window->Render();
  const IceTest::Image asMade = IceTest::Capture(window);
  mapper->ScalarVisibilityOff();
  window->Render();
  const IceTest::Image plain = IceTest::Capture(window);
  mapper->ScalarVisibilityOn();
  window->Render();
  const IceTest::Image tinted = IceTest::Capture(window);

  // Rows from the bottom: the sphere spans about 60..240.
  const Region plainTop = Measure(plain, 190, 220);
  const Region plainBottom = Measure(plain, 80, 110);
  const Region top = Measure(tinted, 190, 220);
  const Region bottom = Measure(tinted, 80, 110);
  std::cout << "top: red " << top.Red << " blue " << top.Blue << " (plain " << plainTop.Red << ", "
            << plainTop.Blue << "), green spread " << top.Spread << "\n"
            << "bottom: red " << bottom.Red << " blue " << bottom.Blue << " (plain "
            << plainBottom.Red << ", " << plainBottom.Blue << "), green spread " << bottom.Spread
            << "\n";
  bool ok = true;
  const auto check = [&ok](bool condition, const char* what) {
    std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
    ok = ok && condition;
  };
  check(offByDefault && IceTest::CountDiffering(plain, asMade, 0) == 0,
    "a new mapper keeps IceColor on input with scalars (ScalarVisibility off by default)");
  check(top.Red - top.Blue > plainTop.Red - plainTop.Blue + 40, "the top is tinted red");
  check(bottom.Blue - bottom.Red > plainBottom.Blue - plainBottom.Red + 40,
    "the bottom is tinted blue");
  check(top.Spread > 3.0 && bottom.Spread > 3.0, "the tinted ice still shows its environment");
  check(recorder->Errors.empty() && recorder->Warnings.empty(), "no error or warning");

  mapper->ScalarVisibilityOff();
  window->Render();
  const IceTest::Image again = IceTest::Capture(window);
  check(IceTest::CountDiffering(plain, again, 0) == 0, "ScalarVisibility off gives IceColor again");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
