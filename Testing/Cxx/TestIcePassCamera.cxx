// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIcePass never touches the user's camera: ten renders of an unchanged view of the full ice
// (two-sided refraction, cracks and air, so the back-face pass runs, and the depth-interval pass
// with the paper's interior passes, and the dynamic cube map) fire no ModifiedEvent on the camera
// and leave its MTime and clipping range as they were.
// Interactors, linked views and ParaView re-render on camera events.
#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

namespace
{
void Count(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
}

bool Run(int interiorMethod)
{
  vtkNew<vtkIceBlockSource> block;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInteriorMethod(interiorMethod);
  mapper->SetInputConnection(block->GetOutputPort());
  mapper->GetIceProperty()->SetNumberOfCracks(4);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(5);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ice);
  vtkNew<vtkIcePass> icePass;
  vtkNew<vtkIceCubeMapPass> cubeMapPass;
  icePass->SetCubeMapPass(cubeMapPass);
  renderer->SetPass(icePass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(160, 120);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.0, 1.5, 4.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  // A clipping range wider than the ice's depths: a pass fitting near and far changes it.
  camera->SetClippingRange(0.1, 100.0);
  window->Render();

  int modified = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetCallback(Count);
  counter->SetClientData(&modified);
  camera->AddObserver(vtkCommand::ModifiedEvent, counter);
  const vtkMTimeType mtime = camera->GetMTime();
  for (int frame = 0; frame < 10; ++frame)
  {
    window->Render();
  }
  double clipping[2];
  camera->GetClippingRange(clipping);
  const bool paper = interiorMethod == vtkIceMapper::InteriorPaperPasses;
  const bool passesRan = icePass->GetBackfaceNormalPass()->GetNumberOfGeometryPasses() >= 10 &&
    (!paper || icePass->GetDepthIntervalPass()->GetNumberOfGeometryPasses() >= 20);
  const bool ok = modified == 0 && camera->GetMTime() == mtime && clipping[0] == 0.1 &&
    clipping[1] == 100.0 && passesRan;
  std::cout << (ok ? "ok   " : "FAIL ") << "10 renders with the full ice ("
            << (paper ? "paper passes" : "screen space") << "): " << modified
            << " camera ModifiedEvents, MTime " << mtime << " -> " << camera->GetMTime()
            << ", clipping range " << clipping[0] << ", " << clipping[1] << "\n";
  return ok;
}
}

int TestIcePassCamera(int, char*[])
{
  const bool paper = Run(vtkIceMapper::InteriorPaperPasses);
  const bool screen = Run(vtkIceMapper::InteriorScreenSpace);
  return paper && screen ? EXIT_SUCCESS : EXIT_FAILURE;
}
