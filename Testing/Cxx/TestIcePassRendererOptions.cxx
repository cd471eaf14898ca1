// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIcePass keeps the renderer's own options: for each of UseHiddenLineRemoval, UseSSAO,
// UseFXAA, and depth peeling with MaximumNumberOfPeels and OcclusionRatio, a scene without ice
// renders pixel for pixel the same with the pass as without it, with the option off, switched on
// after the first render, and off again; and the option changes the picture (so that the
// comparison means something). With the pass, these options used to be ignored.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <functional>
#include <iostream>
#include <string>

namespace
{
void Add(vtkRenderer* renderer, vtkAlgorithm* source, const double position[3],
  const double color[3], double opacity, bool wireframe)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetPosition(position[0], position[1], position[2]);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetOpacity(opacity);
  if (wireframe)
  {
    actor->GetProperty()->SetRepresentationToWireframe();
  }
  renderer->AddActor(actor);
}

struct Scene
{
  explicit Scene(bool withPass)
  {
    vtkNew<vtkPlaneSource> ground;
    ground->SetOrigin(-3.0, -0.6, 2.0);
    ground->SetPoint1(3.0, -0.6, 2.0);
    ground->SetPoint2(-3.0, -0.6, -3.0);
    vtkNew<vtkCubeSource> cube;
    vtkNew<vtkConeSource> cone;
    cone->SetResolution(24);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    const double white[3] = { 0.9, 0.9, 0.9 };
    const double red[3] = { 0.9, 0.3, 0.2 };
    const double green[3] = { 0.3, 0.8, 0.3 };
    const double blue[3] = { 0.3, 0.4, 0.9 };
    const double origin[3] = { 0.0, 0.0, 0.0 };
    const double left[3] = { -1.1, 0.0, 0.0 };
    const double right[3] = { 1.1, 0.0, -0.3 };
    const double front[3] = { 0.3, 0.1, 0.9 };
    Add(this->Renderer, ground, origin, white, 1.0, false);
    Add(this->Renderer, cube, left, red, 1.0, false);
    Add(this->Renderer, cone, origin, green, 0.5, false);
    Add(this->Renderer, sphere, right, blue, 1.0, true); // wireframe: hidden line removal
    Add(this->Renderer, sphere, front, red, 0.4, false);
    // A stack of translucent sheets: more layers than one peel resolves.
    vtkNew<vtkPlaneSource> sheet;
    for (int i = 0; i < 6; ++i)
    {
      const double position[3] = { 0.15 * i - 0.4, 0.1 * i, 0.35 * i - 0.5 };
      const double color[3] = { 0.2 + 0.13 * i, 0.9 - 0.12 * i, 0.5 };
      Add(this->Renderer, sheet, position, color, 0.35, false);
    }
    if (withPass)
    {
      this->Renderer->SetPass(this->Pass);
    }
    this->Window->SetSize(200, 140);
    this->Window->SetMultiSamples(0); // VTK 9.1 peels only without multisampling
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->GetActiveCamera()->SetPosition(0.5, 1.5, 4.5);
    this->Renderer->ResetCameraClippingRange();
  }
  IceTest::Image Render()
  {
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
};

size_t Differing(const IceTest::Image& a, const IceTest::Image& b)
{
  size_t count = 0;
  for (size_t p = 0; p < a.RGB.size() / 3; ++p)
  {
    count += IceTest::PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]) > 0 ? 1 : 0;
  }
  return count;
}

bool CheckOption(const std::string& name, const std::function<void(vtkRenderer*, bool)>& set)
{
  Scene plain(false);
  Scene withPass(true);
  bool ok = true;
  IceTest::Image off;
  for (int frame = 0; frame < 3; ++frame)
  {
    const bool on = frame == 1;
    set(plain.Renderer, on);
    set(withPass.Renderer, on);
    const IceTest::Image expected = plain.Render();
    const size_t differing = Differing(expected, withPass.Render());
    std::string what = name + (on ? " on" : " off");
    if (frame == 0)
    {
      off = expected;
    }
    else if (on)
    {
      const size_t changed = Differing(expected, off);
      ok = changed > 50 && ok;
      what += " (changes " + std::to_string(changed) + " pixels)";
    }
    ok = differing == 0 && ok;
    std::cout << (differing == 0 ? "ok   " : "FAIL ") << what << ": " << differing
              << " pixels differ with vtkIcePass\n";
  }
  return ok;
}
}

// Ice in the scene under each option: drawn (its pixels differ from the scene without it), and
// no VTK error (the test fails on any). The pictures are written for a look.
bool IceUnderEachOption()
{
  bool ok = true;
  const std::function<void(vtkRenderer*)> options[] = {
    [](vtkRenderer* r) { r->SetUseHiddenLineRemoval(true); },
    [](vtkRenderer* r) {
      r->SetUseSSAO(true);
      r->SetSSAORadius(0.5);
      r->SetSSAOKernelSize(32);
    },
    [](vtkRenderer* r) { r->SetUseFXAA(true); },
    [](vtkRenderer* r) {
      r->SetUseDepthPeeling(true);
      r->SetMaximumNumberOfPeels(1);
    },
  };
  const char* names[] = { "hidden line removal", "SSAO", "FXAA", "depth peeling" };
  for (int i = 0; i < 4; ++i)
  {
    Scene scene(true);
    options[i](scene.Renderer);
    vtkSmartPointer<vtkTexture> environment =
      IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 64);
    scene.Renderer->SetEnvironmentTexture(environment);
    const IceTest::Image without = scene.Render();
    vtkNew<vtkSphereSource> sphere;
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    mapper->GetIceProperty()->SetNumberOfCracks(2);
    vtkNew<vtkActor> ice;
    ice->SetMapper(mapper);
    ice->SetPosition(-0.2, 0.6, 1.2);
    scene.Renderer->AddActor(ice);
    const size_t changed = Differing(without, scene.Render());
    ok = changed > 1000 && ok;
    std::cout << (changed > 1000 ? "ok   " : "FAIL ") << "ice with " << names[i] << ": " << changed
              << " pixels drawn\n";
  }
  return ok;
}

int TestIcePassRendererOptions(int, char*[])
{
  bool ok = CheckOption("UseHiddenLineRemoval",
    [](vtkRenderer* renderer, bool on) { renderer->SetUseHiddenLineRemoval(on); });
  ok = CheckOption("UseSSAO",
         [](vtkRenderer* renderer, bool on) {
           renderer->SetUseSSAO(on);
           renderer->SetSSAORadius(0.5);
           renderer->SetSSAOBias(0.01);
           renderer->SetSSAOKernelSize(32);
         }) &&
    ok;
  ok =
    CheckOption("UseFXAA", [](vtkRenderer* renderer, bool on) { renderer->SetUseFXAA(on); }) && ok;
  ok = CheckOption("depth peeling with MaximumNumberOfPeels 1 and OcclusionRatio 0.3",
         [](vtkRenderer* renderer, bool on) {
           renderer->SetUseDepthPeeling(true);
           renderer->SetMaximumNumberOfPeels(on ? 1 : 4);
           renderer->SetOcclusionRatio(on ? 0.3 : 0.0);
         }) &&
    ok;
  ok = IceUnderEachOption() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
