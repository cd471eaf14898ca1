// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The dynamic cube map keeps HDR light: through ice tinted 0.2, an environment of float texels
// at 4.0 looks the same whether the ice samples the environment directly (static) or the cube
// map vtkIceCubeMapPass renders of the scene around it (dynamic), and clearly brighter than an
// environment at 1.0. An 8-bit cube map clamped the sky to 1: 188/255 dynamic against 234
// static.
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <cmath>
#include <iostream>

namespace
{
vtkSmartPointer<vtkTexture> Sky(float value)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->CubeMapOn();
  for (int face = 0; face < 6; ++face)
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(8, 8, 1);
    vtkNew<vtkFloatArray> texels;
    texels->SetNumberOfComponents(3);
    texels->SetNumberOfTuples(64);
    texels->Fill(value);
    image->GetPointData()->SetScalars(texels);
    texture->SetInputData(face, image);
  }
  texture->InterpolateOn();
  texture->SetColorModeToDirectScalars(); // floats as colours, values above 1 kept
  return texture;
}

// Mean of the red channel over the ice's central square, in 0..255.
double RenderIce(bool dynamic, float skyValue)
{
  vtkSmartPointer<vtkTexture> sky = Sky(skyValue);
  vtkNew<vtkRenderer> renderer;
  IceScene::AddEnvironment(renderer, sky);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->GetIceProperty()->SetIceColor(0.2, 0.2, 0.2);
  // The light through the ice alone: the air's and the cracks' white would add its own.
  IceTest::UseCleanOptics(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);

  vtkNew<vtkIcePass> icePass;
  vtkNew<vtkIceCubeMapPass> cubeMapPass;
  cubeMapPass->SetFaceSize(64);
  if (dynamic)
  {
    icePass->SetCubeMapPass(cubeMapPass);
  }
  renderer->SetPass(icePass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(120, 120);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 2.5);
  renderer->ResetCameraClippingRange();
  window->Render();

  const IceTest::Image image = IceTest::Capture(window);
  double sum = 0.0;
  int count = 0;
  for (int y = 45; y < 75; ++y)
  {
    for (int x = 45; x < 75; ++x, ++count)
    {
      sum += image.At(x, y)[0];
    }
  }
  return sum / count;
}
}

int TestIceCubeMapHDR(int, char*[])
{
  const double staticBright = RenderIce(false, 4.0f);
  const double dynamicBright = RenderIce(true, 4.0f);
  const double staticUnit = RenderIce(false, 1.0f);
  const double dynamicUnit = RenderIce(true, 1.0f);
  const bool ok = std::abs(dynamicBright - staticBright) <= 2.0 &&
    std::abs(dynamicUnit - staticUnit) <= 2.0 && staticBright >= staticUnit + 40.0;
  std::cout << (ok ? "ok   " : "FAIL ") << "ice tinted 0.2, mean red: sky of 4.0: static "
            << staticBright << "/255, dynamic " << dynamicBright << "/255; sky of 1.0: static "
            << staticUnit << "/255, dynamic " << dynamicUnit << "/255\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
