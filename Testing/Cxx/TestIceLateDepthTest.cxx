// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// llvmpipe's depth test after the ice surface's shader (vtkIceLateDepthTest), one behaviour per
// test, on ice-render's teapot with the full look of ice-bench (bumps, 2 cracks, 19 air planes):
// - compiled-in: drawn into a multisampled window on llvmpipe, the scene's surface program
//   carries the store that asks for the late test, the sub-passes' programs (single-sampled
//   targets) do not; on any other renderer no program does;
// - single-sampled: into a window without multisampling no program carries it;
// - same-picture: the picture with it is the picture without it (VTKICE_LATE_DEPTH_TEST=0), bit
//   for bit.
#include "IceScene.h"
#include "IceTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkIceMapper.h"
#include "vtkIceProperty.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"

#include "vtkIceVTKCompat.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using IceTest::Expect;

// The fragment shaders VTK compiled or updated for the ice's mapper during the scene's renders.
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkCallbackCommand> Record;
  std::vector<std::string> Fragments;

  explicit Scene(int samples)
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel("teapot", error);
    vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
    vtkActor* ice = IceScene::Populate(this->Renderer, model, environment);
    auto* mapper = vtkIceMapper::SafeDownCast(ice->GetMapper());
    mapper->GetIceProperty()->SetNumberOfCracks(2);
    mapper->GetIceProperty()->SetNumberOfAirPlanes(19);
    this->Window->SetSize(400, 300);
    this->Window->SetMultiSamples(samples);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Record->SetClientData(&this->Fragments);
    this->Record->SetCallback([](vtkObject*, unsigned long, void* list, void* data) {
      vtkShader* fragment = static_cast<vtkShaderProgram*>(data)->GetFragmentShader();
      static_cast<std::vector<std::string>*>(list)->push_back(
        fragment ? fragment->GetSource() : std::string());
    });
    mapper->AddObserver(vtkCommand::UpdateShaderEvent, this->Record);
  }

  bool OnLlvmpipe()
  {
    this->Window->MakeCurrent();
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer && std::strncmp(renderer, "llvmpipe", 8) == 0;
  }
};

bool Carries(const std::string& fragment)
{
  return fragment.find("buffer IceLateDepthTest") != std::string::npos;
}

// The scene's surface programs read what vtkIcePass's frame gives them; the sub-passes' do not.
bool InScene(const std::string& fragment)
{
  return fragment.find("#define ICE_FRAME_") != std::string::npos;
}

bool CompiledIn()
{
  Scene scene(4);
  scene.Window->Render();
  const bool llvmpipe = scene.OnLlvmpipe();
  int scenePrograms = 0;
  int sceneCarrying = 0;
  int subPassCarrying = 0;
  for (const std::string& fragment : scene.Fragments)
  {
    scenePrograms += InScene(fragment) ? 1 : 0;
    sceneCarrying += InScene(fragment) && Carries(fragment) ? 1 : 0;
    subPassCarrying += !InScene(fragment) && Carries(fragment) ? 1 : 0;
  }
  bool ok = Expect(scenePrograms > 0,
    "the scene's surface was drawn (" + std::to_string(scene.Fragments.size()) + " programs)");
  ok = Expect(subPassCarrying == 0, "no sub-pass program carries the late test") && ok;
  if (llvmpipe)
  {
    return Expect(sceneCarrying == scenePrograms,
             "llvmpipe, 4 samples: the scene's surface carries the late test") &&
      ok;
  }
  return Expect(sceneCarrying == 0, "not llvmpipe: no program carries the late test") && ok;
}

bool SingleSampled()
{
  Scene scene(0);
  scene.Window->Render();
  int carrying = 0;
  for (const std::string& fragment : scene.Fragments)
  {
    carrying += Carries(fragment) ? 1 : 0;
  }
  return Expect(!scene.Fragments.empty() && carrying == 0,
    "no multisampling: none of " + std::to_string(scene.Fragments.size()) +
      " programs carries the late test");
}

bool SamePicture()
{
  Scene scene(4);
  scene.Window->Render();
  const IceTest::Image late = IceTest::Capture(scene.Window);
  bool lateCompiled = false;
  for (const std::string& fragment : scene.Fragments)
  {
    lateCompiled = lateCompiled || Carries(fragment);
  }
  scene.Fragments.clear();
  setenv("VTKICE_LATE_DEPTH_TEST", "0", 1);
  scene.Window->Render();
  const IceTest::Image early = IceTest::Capture(scene.Window);
  unsetenv("VTKICE_LATE_DEPTH_TEST");
  bool earlyCompiled = true;
  for (const std::string& fragment : scene.Fragments)
  {
    earlyCompiled = earlyCompiled && !Carries(fragment);
  }
  bool ok = Expect(!scene.OnLlvmpipe() || lateCompiled, "the first picture with the late test");
  ok = Expect(!scene.Fragments.empty() && earlyCompiled,
         "the second without it (VTKICE_LATE_DEPTH_TEST=0)") &&
    ok;
  const size_t differing = IceTest::CountDiffering(late, early, 0);
  return Expect(late.Width == 400 && early.Width == 400 && differing == 0,
           "the same picture bit for bit (" + std::to_string(differing) + " pixels differ)") &&
    ok;
}
}

int TestIceLateDepthTest(int argc, char* argv[])
{
  const IceTest::Cases cases = { { "compiled-in", CompiledIn },
    { "single-sampled", SingleSampled }, { "same-picture", SamePicture } };
  return IceTest::RunCases("TestIceLateDepthTest", argc, argv, cases);
}
