// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceMapper::MirroredEnvironment, as ice-render's melt pool uses it: the ice's mirror image
// (IceScene::AddMirrorImage, the model reflected about its foot), seen by a camera in the plane of
// its foot, is the picture of the ice itself upside down, as a reflection is (the environment
// looked up at y-mirrored directions, through the surface and the trace). Without it the image
// shows the environment's other half.
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace
{
// The picture of the teapot (or of its mirror image, its environment looked up mirrored or not)
// from a camera in the plane of its foot, against a black background, in the sky (a sky above, a
// ground below).
IceTest::Image Render(bool mirrorImage, bool mirroredLookups)
{
  vtkNew<vtkIceTeapotSource> teapot;
  teapot->Update();
  vtkPolyData* model = teapot->GetOutput();
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64));
  vtkNew<vtkIcePass> pass;
  renderer->SetPass(pass);
  vtkIceMapper* mapper = nullptr;
  if (mirrorImage)
  {
    mapper = vtkIceMapper::SafeDownCast(IceScene::AddMirrorImage(renderer, model)->GetMapper());
  }
  else
  {
    vtkNew<vtkIceMapper> ice;
    ice->SetInputData(model);
    vtkNew<vtkActor> actor;
    actor->SetMapper(ice);
    renderer->AddActor(actor);
    mapper = ice;
  }
  mapper->SetMirroredEnvironment(mirroredLookups);
  IceTest::UseCleanOptics(mapper);
  const double foot = model->GetBounds()[2];
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.5, foot, 4.0);
  camera->SetFocalPoint(0.0, foot, 0.0);
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
    "with MirroredEnvironment the mirror image is the teapot's picture upside down (mean " +
      std::to_string(mirrored) + "/255)");
  // The measure tells the two apart: without the mirrored lookups the image differs.
  ok = IceTest::Expect(unmirrored > 10.0 * std::max(mirrored, 0.5),
         "without it the mirror image shows other directions (mean " +
           std::to_string(unmirrored) + "/255)") &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
