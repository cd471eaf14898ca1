// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A scene without ice renders pixel for pixel the same with vtkIcePass as without it: opaque,
// lit actors, a translucent actor and a skybox; with order-independent translucency and with
// depth peeling.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>

namespace
{
void AddActor(vtkRenderer* renderer, vtkAlgorithm* source, double x, double r, double g, double b,
  double opacity)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetPosition(x, 0.0, 0.0);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetOpacity(opacity);
  actor->GetProperty()->SetSpecular(0.5);
  renderer->AddActor(actor);
}

IceTest::Image RenderScene(bool withIcePass, bool depthPeeling)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetUseDepthPeeling(depthPeeling);
  vtkSmartPointer<vtkTexture> sky = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(sky);
  renderer->AddActor(skybox);
  vtkNew<vtkConeSource> cone;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkCubeSource> cube;
  AddActor(renderer, cone, -1.5, 1.0, 0.3, 0.2, 1.0);
  AddActor(renderer, sphere, 0.0, 0.2, 0.8, 0.3, 1.0);
  AddActor(renderer, cube, 1.5, 0.3, 0.4, 1.0, 0.5);
  vtkNew<vtkIcePass> icePass;
  if (withIcePass)
  {
    renderer->SetPass(icePass);
  }
  vtkNew<vtkRenderWindow> window;
  window->SetSize(240, 160);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();
  return IceTest::Capture(window);
}
}

int TestIcePassNoIce(int, char*[])
{
  bool ok = true;
  for (bool depthPeeling : { false, true })
  {
    const IceTest::Image plain = RenderScene(false, depthPeeling);
    const IceTest::Image withPass = RenderScene(true, depthPeeling);
    size_t different = 0;
    for (size_t i = 0; i < plain.RGB.size(); ++i)
    {
      different += plain.RGB[i] != withPass.RGB[i] ? 1 : 0;
    }
    std::cout << (depthPeeling ? "depth peeling: " : "order-independent translucency: ")
              << different << " of " << plain.RGB.size()
              << " channel values differ between the scene with and without vtkIcePass\n";
    ok = ok && different == 0;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
