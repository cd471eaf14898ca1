// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Glistening ice and snow on the teapot in the sky environment, lit by the sky's sun:
// SnowAmount 0 (ice: the environment refracted and reflected, a soft highlight, rim light and
// glints), 0.5 and 1 (snow: white and diffuse, bluish in the shadow, rim light and glints).
// Checked against a reviewed baseline (Documentation/glistening-ice-snow.png); the numbers behind
// it are checked in TestIceGlistening.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkTexture.h"

int TestIceGlisteningSnow(int argc, char* argv[])
{
  vtkSmartPointer<vtkTexture> sky = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 256);
  vtkNew<vtkIceTeapotSource> teapot;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(900, 300);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  const double amounts[3] = { 0.0, 0.5, 1.0 };
  vtkNew<vtkIceMapper> mappers[3];
  vtkNew<vtkActor> actors[3];
  vtkNew<vtkRenderer> renderers[3];
  vtkNew<vtkSkybox> skyboxes[3];
  vtkNew<vtkLight> suns[3];
  for (int i = 0; i < 3; ++i)
  {
    mappers[i]->SetInputConnection(teapot->GetOutputPort());
    IceTest::UseCleanOptics(mappers[i]); // the glistening alone on the paper's ice
    mappers[i]->GetIceProperty()->GlisteningOn();
    mappers[i]->GetIceProperty()->SetSnowAmount(amounts[i]);
    mappers[i]->GetIceProperty()->SetGlisteningScale(0.02);
    actors[i]->SetMapper(mappers[i]);
    renderers[i]->AddActor(actors[i]);
    renderers[i]->SetEnvironmentTexture(sky);
    skyboxes[i]->SetTexture(sky);
    renderers[i]->AddActor(skyboxes[i]);
    // The sky's sun (vtkIceCubeMapSource) is in direction (0.45, 0.55, -0.70).
    suns[i]->SetLightTypeToSceneLight();
    suns[i]->SetPosition(0.45, 0.55, -0.70);
    suns[i]->SetFocalPoint(0.0, 0.0, 0.0);
    renderers[i]->AddLight(suns[i]);
    renderers[i]->SetViewport(i / 3.0, 0.0, (i + 1) / 3.0, 1.0);
    vtkCamera* camera = renderers[i]->GetActiveCamera();
    camera->SetPosition(3.4, 1.0, -1.0); // the sun behind the camera, on its right
    camera->SetFocalPoint(0.0, 0.1, 0.0);
    camera->SetViewAngle(32.0);
    renderers[i]->ResetCameraClippingRange();
    window->AddRenderer(renderers[i]);
  }
  window->Render();
  return IceTest::CheckImage(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
