// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The ice passes skip work that does not show, without changing a pixel: the depth-interval pass
// runs only when something reads it, the back-face pass only for two-sided ice; a moving camera
// modifies no mapper; the back-normal and depth-interval textures are cleared only where the ice is
// or was, and cracks are scissored to the ice, so ice moving across the screen (partly off it, and
// with the camera inside its bounds) renders exactly what a fresh window renders, and leaves the
// textures as a fresh window does.
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkPixelBufferObject.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <iostream>
#include <string>

namespace
{
using IceTest::Expect;

// A cracked ice block whose cracks also bend the refraction: every texture the passes clear
// by region is read.
struct Scene
{
  vtkNew<vtkIceBlockSource> Block;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Ice;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;

  Scene()
  {
    this->Mapper->SetInputConnection(this->Block->GetOutputPort());
    this->Mapper->GetIceProperty()->SetNumberOfCracks(4);
    this->Mapper->GetPaperInterior()->CracksPerturbRefractionOn();
    this->Ice->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Ice);
    this->Renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 128));
    this->Renderer->SetBackground(0.1, 0.1, 0.1);
    this->Renderer->SetPass(this->Pass);
    this->Window->SetSize(240, 200);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.5, 6.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetClippingRange(0.05, 20.0);
  }

  IceTest::Image RenderAt(const double position[3])
  {
    this->Ice->SetPosition(position[0], position[1], position[2]);
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }
};

// The texels of a float texture of the passes.
std::vector<float> Texels(vtkTextureObject* texture)
{
  std::vector<float> values;
  vtkPixelBufferObject* buffer = texture ? texture->Download() : nullptr;
  if (!buffer)
  {
    return values;
  }
  const size_t count = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() *
    static_cast<size_t>(texture->GetComponents());
  const float* data = static_cast<const float*>(buffer->MapPackedBuffer());
  values.assign(data, data + count);
  buffer->UnmapPackedBuffer();
  buffer->Delete();
  return values;
}

// Texels that differ between two downloads (all of them when the sizes differ).
size_t Differing(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return std::max<size_t>(std::max(a.size(), b.size()), 1);
  }
  size_t count = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    count += a[i] != b[i] ? 1 : 0;
  }
  return count;
}

bool DepthIntervalOnlyWhenRead()
{
  Scene scene;
  bool ok = true;
  auto passesPerFrame = [&]() {
    scene.Window->Render();
    const vtkIdType before = scene.Pass->GetDepthIntervalPass()->GetNumberOfGeometryPasses();
    scene.Window->Render();
    const vtkIdType passes =
      scene.Pass->GetDepthIntervalPass()->GetNumberOfGeometryPasses() - before;
    std::cout << "depth-interval geometry passes per frame: " << passes << "\n";
    return passes;
  };
  scene.Mapper->GetPaperInterior()->CracksPerturbRefractionOff();
  scene.Mapper->GetIceProperty()->SetNumberOfCracks(0);
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
  ok =
    Expect(passesPerFrame() == 0, "no cracks, no air, no debug view: no depth-interval pass") && ok;
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(19);
  scene.Mapper->SetInteriorMethodToPaperPasses();
  ok =
    Expect(passesPerFrame() == 2, "air in the paper's passes: the depth-interval pass runs") && ok;
  scene.Mapper->SetInteriorMethodToScreenSpace();
  ok = Expect(passesPerFrame() == 0, "air, screen-space interior: no depth-interval pass") && ok;
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
  scene.Mapper->SetDebugView(vtkIceMapper::DebugBackDepth);
  ok = Expect(passesPerFrame() == 2, "a depth debug view: the depth-interval pass runs") && ok;
  scene.Mapper->SetDebugView(vtkIceMapper::DebugOff);
  scene.Mapper->GetIceProperty()->SetNumberOfCracks(2);
  ok =
    Expect(passesPerFrame() == 0, "cracks, screen-space interior: no depth-interval pass") && ok;
  scene.Mapper->SetInteriorMethodToPaperPasses();
  ok =
    Expect(passesPerFrame() == 2, "cracks in the paper's passes: the depth-interval pass runs") &&
    ok;
  return ok;
}

bool BackfaceNormalsOnlyWhenNeeded()
{
  Scene scene;
  scene.Mapper->SetInteriorMethodToScreenSpace();
  auto passesPerFrame = [&]() {
    scene.Window->Render();
    const vtkIdType before = scene.Pass->GetBackfaceNormalPass()->GetNumberOfGeometryPasses();
    scene.Window->Render();
    return scene.Pass->GetBackfaceNormalPass()->GetNumberOfGeometryPasses() - before;
  };
  bool ok = Expect(passesPerFrame() == 1, "two-sided ice: the back-face pass runs once a frame");
  const IceTest::Image twoSided = IceTest::Capture(scene.Window);
  scene.Mapper->TwoSidedRefractionOff();
  ok =
    Expect(passesPerFrame() == 1, "one-sided ice with cracks: the back-face pass runs (depth)") &&
    ok;
  scene.Mapper->GetIceProperty()->SetNumberOfCracks(0);
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
  ok =
    Expect(passesPerFrame() == 0, "one-sided ice without cracks or air: no back-face pass") && ok;
  scene.Mapper->GetIceProperty()->SetNumberOfCracks(4);
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(19);
  scene.Mapper->SetInteriorMethodToPaperPasses();
  ok = Expect(passesPerFrame() == 0, "one-sided ice, paper passes: no back-face pass") && ok;
  scene.Mapper->SetInteriorMethodToScreenSpace();
  scene.Mapper->TwoSidedRefractionOn();
  const IceTest::Image twoSidedAgain = IceTest::Capture(scene.Window);
  ok = Expect(IceTest::CountDiffering(twoSided, twoSidedAgain, 0) == 0, "two-sided again") && ok;
  scene.Mapper->TwoSidedRefractionOff();
  const IceTest::Image oneSided = IceTest::Capture(scene.Window);
  const size_t differing = IceTest::CountDiffering(twoSided, oneSided, 2);
  ok = Expect(differing > 100,
         "and the ice refracts otherwise without the back faces (" + std::to_string(differing) +
           " pixels differ by more than 2/255)") &&
    ok;
  return ok;
}

// The pass is one of the ice prop's render passes only while it renders a frame: it hands its
// textures to the programs it built code into, and nothing of the frame stays on the prop or
// the mapper.
// Whether `pass` is among the render passes VTK lists on `prop` (vtkOpenGLRenderPass::PreRender
// puts a pass there for the frame it draws the prop in).
bool AmongRenderPasses(vtkProp* prop, vtkObjectBase* pass)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  for (int i = 0; keys && i < vtkOpenGLRenderPass::RenderPasses()->Length(keys); ++i)
  {
    if (vtkOpenGLRenderPass::RenderPasses()->Get(keys, i) == pass)
    {
      return true;
    }
  }
  return false;
}

bool PassHoldsTheFrame()
{
  Scene scene;
  struct Observation
  {
    vtkActor* Ice;
    vtkIcePass* Pass;
    int Binds = 0;
    int WithPass = 0;
    int SamplingBackNormals = 0;
    int SubPassDeclaring = 0; // sub-pass programs whose source names the pass's back normals
    std::string Log;          // every bind, printed when the count is wrong
  } seen{ scene.Ice, scene.Pass };
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&seen);
  observer->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* observation = static_cast<Observation*>(clientData);
    ++observation->Binds;
    observation->WithPass += AmongRenderPasses(observation->Ice, observation->Pass);
    auto* program = static_cast<vtkShaderProgram*>(callData);
    const bool sampling = program->IsUniformUsed("iceBackNormals");
    observation->SamplingBackNormals += sampling;
    std::string passes;
    bool subPass = false;
    vtkInformation* keys = observation->Ice->GetPropertyKeys();
    for (int i = 0; keys && i < vtkOpenGLRenderPass::RenderPasses()->Length(keys); ++i)
    {
      vtkObjectBase* pass = vtkOpenGLRenderPass::RenderPasses()->Get(keys, i);
      passes += std::string(" ") + pass->GetClassName();
      subPass = subPass || !vtkIcePass::SafeDownCast(pass);
    }
    // The source, not only the active uniforms: Mesa drops a sampler whose result is unused,
    // NVIDIA's driver kept it (the depth-interval program sampled the back normals there). The
    // surface's code for the frame's inputs is in every program, compiled only where the frame
    // defines its input (vtkIceFrame::Defines): a sub-pass's program must define none.
    const bool declaring =
      program->GetFragmentShader()->GetSource().find("#define ICE_FRAME_") != std::string::npos;
    observation->SubPassDeclaring += subPass && declaring;
    observation->Log += "     program " + std::to_string(program->GetHandle()) +
      (sampling ? " samples iceBackNormals" : (declaring ? " defines a frame input" : "")) +
      "; passes:" + passes + "\n";
  });
  scene.Mapper->AddObserver(vtkCommand::UpdateShaderEvent, observer);
  scene.Window->Render();
  bool ok = Expect(seen.Binds > 0 && seen.WithPass == seen.Binds,
    "every ice program bound in the frame sees the pass among the prop's render passes (" +
      std::to_string(seen.WithPass) + " of " + std::to_string(seen.Binds) + ")");
  if (seen.SamplingBackNormals != 1 || seen.SubPassDeclaring != 0)
  {
    std::cout << seen.Log;
  }
  ok = Expect(seen.SamplingBackNormals == 1,
         "the pass built its back-face sampling into the surface program drawn in the scene "
         "(not into the programs of its own sub-passes): " +
           std::to_string(seen.SamplingBackNormals) + " bound") &&
    ok;
  ok = Expect(seen.SubPassDeclaring == 0,
         "no program of a sub-pass defines a frame input (its back-face sampling compiled out): " +
           std::to_string(seen.SubPassDeclaring) + " bound") &&
    ok;
  ok = Expect(!AmongRenderPasses(scene.Ice, scene.Pass),
         "after the frame the prop has no ice pass among its render passes") &&
    ok;
  return ok;
}

// What the pass hands the mapper every frame (textures, the fitted depth range) are shader
// inputs: a moving camera must not modify the mapper, or VTK rebuilds its buffers and shaders
// every frame.
bool CameraMotionModifiesNothing()
{
  Scene scene;
  scene.Window->Render();
  const vtkMTimeType before = scene.Mapper->GetMTime();
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(10.0);
    scene.Renderer->GetActiveCamera()->Dolly(1.05);
    scene.Window->Render();
  }
  return Expect(scene.Mapper->GetMTime() == before,
    "a moving camera leaves the ice mapper unmodified (MTime " + std::to_string(before) + " -> " +
      std::to_string(scene.Mapper->GetMTime()) + ")");
}

bool MovingIce(int debugView)
{
  // Across the screen, partly off its left and bottom edges, then around the camera (the
  // camera inside the ice's bounds: the whole viewport is cleared), then back.
  const double positions[][3] = { { -1.5, 0.5, 0.0 }, { 1.8, -0.4, 0.5 }, { -3.2, -2.3, 0.0 },
    { 0.0, 0.5, 5.6 }, { 0.3, 0.0, -1.0 } };
  Scene moving;
  moving.Mapper->SetDebugView(debugView);
  bool ok = true;
  for (const auto& position : positions)
  {
    const IceTest::Image reused = moving.RenderAt(position);
    Scene fresh;
    fresh.Mapper->SetDebugView(debugView);
    const IceTest::Image expected = fresh.RenderAt(position);
    // Not only the picture: the textures too, where nothing reads them (outside the ice) and
    // where cleared by region they must hold their clear values as in a fresh window.
    moving.Window->MakeCurrent();
    const std::vector<float> movedNormals =
      Texels(moving.Pass->GetBackfaceNormalPass()->GetNormalTexture());
    const std::vector<float> movedInterval =
      Texels(moving.Pass->GetDepthIntervalPass()->GetDepthTexture());
    fresh.Window->MakeCurrent();
    const size_t normals =
      Differing(movedNormals, Texels(fresh.Pass->GetBackfaceNormalPass()->GetNormalTexture()));
    const size_t interval =
      Differing(movedInterval, Texels(fresh.Pass->GetDepthIntervalPass()->GetDepthTexture()));
    ok = Expect(normals == 0 && interval == 0,
           "textures after the move equal a fresh window's (" + std::to_string(normals) +
             " back-normal and " + std::to_string(interval) + " depth-interval texels differ)") &&
      ok;
    int largest = 0;
    for (int y = 0; y < reused.Height; ++y)
    {
      for (int x = 0; x < reused.Width; ++x)
      {
        largest = std::max(largest, IceTest::PixelDifference(reused.At(x, y), expected.At(x, y)));
      }
    }
    ok = Expect(largest == 0,
           std::string(debugView ? "unclipped cracks: " : "") + "ice moved to (" +
             std::to_string(position[0]) + ", " + std::to_string(position[1]) + ", " +
             std::to_string(position[2]) + ") renders as in a fresh window (largest " +
             "difference " + std::to_string(largest) + "/255)") &&
      ok;
  }
  return ok;
}

}

int TestIcePassWork(int, char*[])
{
  bool ok = DepthIntervalOnlyWhenRead();
  ok = CameraMotionModifiesNothing() && ok;
  ok = BackfaceNormalsOnlyWhenNeeded() && ok;
  ok = PassHoldsTheFrame() && ok;
  ok = MovingIce(vtkIceMapper::DebugOff) && ok;
  // Unclipped cracks read the depth interval outside the ice too (at their own depth where
  // there is no ice): what the ice left behind must be cleared.
  ok = MovingIce(vtkIceMapper::DebugCracksUnclipped) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
