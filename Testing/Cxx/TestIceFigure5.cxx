// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The paper's Figure 5 with the ice block: (a) front depth, (b) back depth, (c) a crack unclipped,
// (d) the crack clipped, cracks in red. Checked against a reviewed baseline; the numbers behind the
// views are checked in TestIceCracks.
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

int TestIceFigure5(int argc, char* argv[])
{
  const int views[4] = { vtkIceMapper::DebugFrontDepth, vtkIceMapper::DebugBackDepth,
    vtkIceMapper::DebugCracksUnclipped, vtkIceMapper::DebugCracksClipped };
  vtkSmartPointer<vtkTexture> sky = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 128);
  vtkNew<vtkIceBlockSource> block;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 200);
  window->SetOffScreenRendering(1);
  vtkNew<vtkIceMapper> mappers[4];
  vtkNew<vtkActor> actors[4];
  vtkNew<vtkIcePass> passes[4];
  vtkNew<vtkRenderer> renderers[4];
  for (int i = 0; i < 4; ++i)
  {
    mappers[i]->SetInputConnection(block->GetOutputPort());
    IceTest::UseCleanOptics(mappers[i]); // the depths and the cracks alone
    mappers[i]->GetIceProperty()->SetNumberOfCracks(2);
    mappers[i]->SetDebugView(views[i]);
    actors[i]->SetMapper(mappers[i]);
    renderers[i]->AddActor(actors[i]);
    renderers[i]->SetEnvironmentTexture(sky);
    renderers[i]->SetBackground(0.15, 0.15, 0.2);
    renderers[i]->SetPass(passes[i]);
    renderers[i]->SetViewport(0.25 * i, 0.0, 0.25 * (i + 1), 1.0);
    vtkCamera* camera = renderers[i]->GetActiveCamera();
    camera->SetPosition(2.5, 2.0, 4.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewAngle(40.0);
    renderers[i]->ResetCameraClippingRange();
    window->AddRenderer(renderers[i]);
  }
  window->Render();
  return IceTest::CheckImage(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
