// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Glistening ice on a large plane, near and far: on the left the ground at the viewer's feet, each
// crack cell a facet of several pixels, some glinting; on the right the plane to the horizon
// towards a low sun, single-pixel glints along the sun's path all the way to the horizon. Checked
// against a reviewed baseline (Documentation/glistening-near-far.png); the numbers behind it are
// checked in TestIceGlistening.
#include "IceGlisteningScene.h"

int TestIceGlisteningPlane(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 300);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);

  IceGlistening::Plane near(window, 50.0);
  near.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  near.Look(0.4, 50.0);
  near.SetSun(50.0, 0.0);

  IceGlistening::Plane far(window, 4.0);
  far.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  far.SetSun(14.0, 12.0);

  window->Render();
  return IceTest::CheckImage(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
