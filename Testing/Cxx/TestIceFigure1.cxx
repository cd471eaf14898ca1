// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The paper's Figure 1 setting: an ice block with cracks, air and a bumpy surface in a small
// landscape, dynamic cube map and two-sided refraction (the defaults), against a reviewed
// baseline.
#include "IceScene.h"
#include "IceTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iostream>

int TestIceFigure1(int argc, char* argv[])
{
  std::string error;
  vtkSmartPointer<vtkPolyData> block = IceScene::LoadModel("block", error);
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  if (!block || !environment)
  {
    std::cerr << error << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  IceScene::Populate(renderer, block, environment);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(3.4, 1.9, 5.6);
  camera->SetFocalPoint(0.0, -0.1, 0.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 480);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();
  return IceTest::CheckImage(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
