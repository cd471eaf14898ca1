// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Without an environment texture the ice still renders, using the built-in sky, and the mapper
// warns exactly once (not every frame), or not at all with WarnWithoutEnvironment off. A 2D
// environment texture is a panorama: drawn, no warning (TestIcePanoramaEnvironment checks how).
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>

namespace
{
// `expected`: the start of the one warning expected, or nullptr for none.
bool CheckCase(const char* name, vtkTexture* environment, const char* expected, bool warn = true)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetWarnWithoutEnvironment(warn);
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  const IceTest::Image image = IceTest::Capture(window);
  const unsigned char* middle = image.At(100, 100);
  const bool drawn = middle[0] + middle[1] + middle[2] > 150;
  const bool warnedOnce = expected
    ? recorder->Warnings.size() == 1 && recorder->Warnings[0].find(expected) != std::string::npos
    : recorder->Warnings.empty();
  std::cout << name << ": " << recorder->Warnings.size() << " warning(s)"
            << (recorder->Warnings.empty() ? std::string() : ": " + recorder->Warnings[0])
            << "; centre pixel " << int(middle[0]) << "," << int(middle[1]) << "," << int(middle[2])
            << "\n";
  return drawn && warnedOnce && recorder->Errors.empty();
}
}

int TestIceNoEnvironment(int, char*[])
{
  bool ok = CheckCase("no environment", nullptr, "has no environment texture");

  vtkNew<vtkImageData> flat;
  flat->SetDimensions(4, 4, 1);
  flat->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  flat->GetPointData()->GetScalars()->Fill(200);
  vtkNew<vtkTexture> texture2D;
  texture2D->SetInputData(flat);
  ok = CheckCase("2D environment", texture2D, nullptr) && ok;
  ok = CheckCase("no environment, WarnWithoutEnvironment off", nullptr, nullptr, false) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
