// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIcePass::MeasureStepTimes: off, every step reads -1; on, the steps that ran in the frame
// measured last have a time (milliseconds, >= 0) and those that did not run read -1; without its
// cube-map pass the cube-map step reads -1 again. The scene: a cracked ice block with the paper's
// passes for its interior, two-sided refraction and a dynamic cube map, so every step but the
// depth interval before the scene runs.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iostream>
#include <string>

namespace
{
const char* const StepNames[vtkIcePass::NumberOfSteps] = { "cube map", "depth interval",
  "back faces", "scene", "interior" };

// Renders `frames` frames, each finished on the GPU, so that the last but one is measured.
void RenderFinished(vtkRenderWindow* window, int frames)
{
  for (int i = 0; i < frames; ++i)
  {
    window->Render();
    window->WaitForCompletion();
  }
}

// Checks each step's time against `ran` (a time >= 0) or not (-1).
bool ExpectSteps(
  vtkIcePass* pass, const bool ran[vtkIcePass::NumberOfSteps], const std::string& when)
{
  bool ok = true;
  for (int step = 0; step < vtkIcePass::NumberOfSteps; ++step)
  {
    const double time = pass->GetStepTime(step);
    const bool measured = time >= 0.0;
    ok = IceTest::Expect(measured == ran[step] && (measured || time == -1.0),
           when + ": " + StepNames[step] + (ran[step] ? " measured" : " reads -1") + " (" +
             std::to_string(time) + " ms)") &&
      ok;
  }
  return ok;
}
}

int TestIcePassStepTimes(int, char*[])
{
  IceTest::MessageCounter messages;
  messages.Install();
  vtkNew<vtkIceBlockSource> block;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(block->GetOutputPort());
  mapper->GetIceProperty()->SetNumberOfCracks(3);
  mapper->SetInteriorMethodToPaperPasses();
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ice);
  renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64));
  vtkNew<vtkIcePass> pass;
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  cubeMaps->SetUpdateModeToEveryFrame();
  cubeMaps->SetFaceSize(64);
  pass->SetCubeMapPass(cubeMaps);
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 160);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.5, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);

  bool ok = IceTest::Expect(!pass->GetMeasureStepTimes(), "MeasureStepTimes is off by default");
  RenderFinished(window, 2);
  const bool none[vtkIcePass::NumberOfSteps] = { false, false, false, false, false };
  ok = ExpectSteps(pass, none, "off") && ok;

  pass->MeasureStepTimesOn();
  RenderFinished(window, 3);
  const bool all[vtkIcePass::NumberOfSteps] = { true, false, true, true, true };
  ok = ExpectSteps(pass, all, "on") && ok;

  pass->SetCubeMapPass(nullptr);
  RenderFinished(window, 3);
  const bool withoutCubeMaps[vtkIcePass::NumberOfSteps] = { false, false, true, true, true };
  ok = ExpectSteps(pass, withoutCubeMaps, "without the cube-map pass") && ok;

  const std::string errors = IceTest::TakeGLErrors(window);
  ok = IceTest::Expect(errors.empty(), "no OpenGL error " + errors) && ok;
  const int said = messages.Errors() + messages.Warnings();
  ok = IceTest::Expect(said == 0, "no VTK error or warning (" + std::to_string(said) + ")") && ok;
  messages.Uninstall();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
