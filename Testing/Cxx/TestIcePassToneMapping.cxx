// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkToneMappingPass around vtkIcePass (ice-render's tone mapping, a PyVista plotter's) keeps the
// translucent geometry behind the opaque: a translucent ground under an opaque cube renders as
// with VTK's own vtkRenderStepsPass in the same tone mapping, and the cube's middle stays the
// cube's colour. The order-independent pass used there took its depth from the tone mapping's
// framebuffer by a blit that failed, and the ground covered the cube.
#include "IceTestUtilities.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkToneMappingPass.h"

#include <cstdlib>
#include <iostream>

namespace
{
IceTest::Image Render(vtkRenderPass* inner)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.5);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkPolyDataMapper> cubeMapper;
  cubeMapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> opaque;
  opaque->SetMapper(cubeMapper);
  opaque->GetProperty()->SetColor(1.0, 0.0, 0.0);
  opaque->GetProperty()->LightingOff();
  renderer->AddActor(opaque);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3.0, -0.5, 3.0);
  plane->SetPoint1(3.0, -0.5, 3.0);
  plane->SetPoint2(-3.0, -0.5, -3.0);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(planeMapper);
  ground->GetProperty()->SetOpacity(0.8);
  renderer->AddActor(ground);

  vtkNew<vtkToneMappingPass> toneMapping;
  toneMapping->SetToneMappingType(vtkToneMappingPass::Clamp);
  toneMapping->SetDelegatePass(inner);
  renderer->SetPass(toneMapping);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(160, 160);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.0, 1.5, 3.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  window->Render();
  IceTest::Image image = IceTest::Capture(window);
  renderer->SetPass(nullptr);
  toneMapping->ReleaseGraphicsResources(window);
  return image;
}
}

int TestIcePassToneMapping(int, char*[])
{
  vtkNew<vtkRenderStepsPass> steps;
  const IceTest::Image expected = Render(steps);
  vtkNew<vtkIcePass> icePass;
  const IceTest::Image actual = Render(icePass);
  size_t differing = 0;
  for (size_t p = 0; p < expected.RGB.size() / 3; ++p)
  {
    differing += IceTest::PixelDifference(&expected.RGB[3 * p], &actual.RGB[3 * p]) > 0 ? 1 : 0;
  }
  const unsigned char* middle = actual.At(actual.Width / 2, actual.Height / 2);
  const bool red = middle[0] >= 250 && middle[1] <= 5 && middle[2] <= 5;
  std::cout << (differing == 0 ? "ok   " : "FAIL ") << differing
            << " pixels differ from vtkRenderStepsPass in the same tone mapping\n"
            << (red ? "ok   " : "FAIL ") << "the opaque cube's middle is " << int(middle[0]) << ","
            << int(middle[1]) << "," << int(middle[2]) << " (its colour: 255,0,0)\n";
  return differing == 0 && red ? EXIT_SUCCESS : EXIT_FAILURE;
}
