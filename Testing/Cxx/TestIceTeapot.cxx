// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The default ice scene of ice-render (teapot, procedural sky) at 400x300, against a reviewed
// baseline: VTK's image comparison plus a strict numeric one.
#include "IceScene.h"
#include "IceTestUtilities.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iostream>

int TestIceTeapot(int argc, char* argv[])
{
  std::string error;
  vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel("teapot", error);
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  if (!model || !environment)
  {
    std::cerr << error << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  IceScene::Populate(renderer, model, environment);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();
  return IceTest::CheckImage(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
