// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceMapper::MirroredEnvironment: ice whose points are reflected in the plane y = 0, seen by a
// camera in that plane, shows the picture of the ice itself upside down, as a reflection does (the
// environment looked up at y-mirrored directions too, through the surface and the trace). Without
// it the reflected ice shows the environment's other half.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkReverseSense.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
// The picture of the teapot (reflected in y = 0 and so looked up, or not) from a camera in that
// plane, against a black background, in the sky (a sky above, a ground below).
IceTest::Image Render(bool reflected, bool mirroredLookups)
{
  vtkNew<vtkIceTeapotSource> teapot;
  vtkNew<vtkTransform> reflect;
  reflect->Scale(1.0, reflected ? -1.0 : 1.0, 1.0);
  vtkNew<vtkTransformPolyDataFilter> transformed;
  transformed->SetInputConnection(teapot->GetOutputPort());
  transformed->SetTransform(reflect);
  vtkNew<vtkReverseSense> turned; // a reflection turns the cells inside out
  turned->SetInputConnection(transformed->GetOutputPort());
  turned->SetReverseCells(reflected);
  turned->ReverseNormalsOff();

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(turned->GetOutputPort());
  mapper->SetMirroredEnvironment(mirroredLookups);
  IceTest::UseCleanOptics(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetEnvironmentTexture(
    IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64));
  vtkNew<vtkIcePass> pass;
  renderer->SetPass(pass);
  renderer->AddActor(ice);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.5, 0.0, 4.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 160);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->Render();
  return IceTest::Capture(window);
}

// The mean over the pixels of `a` and `b` turned upside down of their largest channel
// difference, /255.
double MeanFlippedDifference(const IceTest::Image& a, const IceTest::Image& b)
{
  double sum = 0.0;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      sum += IceTest::PixelDifference(a.At(x, y), b.At(x, b.Height - 1 - y));
    }
  }
  return sum / (static_cast<double>(a.Width) * a.Height);
}
}

int TestIceMirroredEnvironment(int, char*[])
{
  const IceTest::Image ice = Render(false, false);
  const double mirrored = MeanFlippedDifference(ice, Render(true, true));
  const double unmirrored = MeanFlippedDifference(ice, Render(true, false));
  bool ok = IceTest::Expect(mirrored < 0.5,
    "with MirroredEnvironment the reflected teapot is the teapot's picture upside down (mean " +
      std::to_string(mirrored) + "/255)");
  // The measure tells the two apart: without the mirrored lookups the image differs.
  ok = IceTest::Expect(unmirrored > 10.0 * std::max(mirrored, 0.5),
         "without it the reflected teapot shows other directions (mean " +
           std::to_string(unmirrored) + "/255)") &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
