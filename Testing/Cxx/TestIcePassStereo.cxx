// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Stereo with vtkIcePass: set before the first render, a red-blue stereo window without ice draws
// pixel for pixel what it draws without the pass (it used to equal StereoRenderOff: both eyes
// from the middle); switched on after the first render and off again, it follows; and with ice
// the two eyes differ (the ice is drawn for each eye).
#include "IceTestUtilities.h"
#include "vtkIcePass.h"
#include "vtkIceMapper.h"
#include "vtkIceCubeMapSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
// Renders one frame per entry of `stereoFrames` (the window's stereo setting for it) and returns
// the last one.
IceTest::Image Render(bool withPass, const std::vector<bool>& stereoFrames, bool ice)
{
  vtkNew<vtkRenderer> renderer;
  vtkSmartPointer<vtkTexture> environment =
    IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 64);
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkConeSource> cone;
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  renderer->AddActor(coneActor);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> iceMapper;
  iceMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> iceActor;
  iceActor->SetMapper(iceMapper);
  iceActor->SetPosition(0.0, 0.0, 1.0);
  iceActor->SetVisibility(ice);
  renderer->AddActor(iceActor);
  vtkNew<vtkIcePass> icePass;
  if (withPass)
  {
    renderer->SetPass(icePass);
  }
  vtkNew<vtkRenderWindow> window;
  window->SetSize(160, 120);
  window->SetOffScreenRendering(1);
  window->SetStereoTypeToRedBlue();
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.5, 4.0);
  camera->SetEyeAngle(6.0);
  renderer->ResetCameraClippingRange();
  for (const bool stereo : stereoFrames)
  {
    window->SetStereoRender(stereo);
    window->Render();
  }
  return IceTest::Capture(window);
}

size_t Differing(const IceTest::Image& a, const IceTest::Image& b)
{
  size_t count = 0;
  for (size_t p = 0; p < a.RGB.size() / 3; ++p)
  {
    count += IceTest::PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]) > 0 ? 1 : 0;
  }
  return count;
}

bool Check(bool ok, const std::string& message)
{
  std::cout << (ok ? "ok   " : "FAIL ") << message << "\n";
  return ok;
}
}

int TestIcePassStereo(int, char*[])
{
  const IceTest::Image mono = Render(false, { false }, false);
  const IceTest::Image plain = Render(false, { true }, false);
  const IceTest::Image withPass = Render(true, { true }, false);
  bool ok = Check(Differing(plain, mono) > 500,
    "red-blue stereo differs from mono on " + std::to_string(Differing(plain, mono)) + " pixels");
  ok = Check(Differing(withPass, plain) == 0,
         "with vtkIcePass: " + std::to_string(Differing(withPass, plain)) +
           " pixels differ from stereo without the pass") &&
    ok;
  const IceTest::Image switchedOn = Render(true, { false, true }, false);
  const IceTest::Image switchedOff = Render(true, { false, true, false }, false);
  ok = Check(Differing(switchedOn, plain) == 0 && Differing(switchedOff, mono) == 0,
         "stereo switched on after the first render, and off again: " +
           std::to_string(Differing(switchedOn, plain)) + " and " +
           std::to_string(Differing(switchedOff, mono)) + " pixels differ without the pass") &&
    ok;
  const IceTest::Image iceMono = Render(true, { false }, true);
  const IceTest::Image iceStereo = Render(true, { true }, true);
  ok = Check(Differing(iceStereo, iceMono) > 500,
         "ice in red-blue stereo differs from mono on " +
           std::to_string(Differing(iceStereo, iceMono)) + " pixels") &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
