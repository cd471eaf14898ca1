// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The ice through the life of an application's windows and scenes:
// - closing the window (Finalize) releases the ice's graphics resources (with either interior
//   method), and the window opened again renders the same picture; so does releasing them
//   without closing it;
// - a vtkIcePass removed from its renderer and deleted leaves no OpenGL object behind;
// - two render windows, each with ice, render what each renders alone, also after one closes;
// - renderers on two layers (ice over a scene) and in two viewports;
// - an ice actor with SetVisibility(0) is as if removed, and comes back;
// - one ice mapper drawn by two actors gives the picture of two mappers;
// - translucent VTK actors in front of and behind the ice blend correctly, with order-independent
//   translucency and with depth peeling.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using IceTest::Expect;

// Largest and mean channel difference of two images of one size (255 each when sizes differ).
struct Difference
{
  int Max = 255;
  double Mean = 255.0;
};
Difference Compare(const IceTest::Image& a, const IceTest::Image& b)
{
  Difference d;
  if (a.Width != b.Width || a.Height != b.Height || a.RGB.empty())
  {
    return d;
  }
  d.Max = 0;
  double sum = 0.0;
  const size_t pixels = a.RGB.size() / 3;
  for (size_t p = 0; p < pixels; ++p)
  {
    const int value = IceTest::PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]);
    d.Max = std::max(d.Max, value);
    sum += value;
  }
  d.Mean = sum / pixels;
  return d;
}

std::string Describe(const Difference& d)
{
  return "max " + std::to_string(d.Max) + "/255, mean " + std::to_string(d.Mean) + "/255";
}

// An ice scene: skybox, a cone beside the ice, the teapot as ice with cracks, the full ice pass
// (cube map of the scene around the ice).
struct IceScene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIceTeapotSource> Teapot;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Ice;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkIceCubeMapPass> CubeMaps;
  vtkSmartPointer<vtkTexture> Environment;

  explicit IceScene(double coneX = 1.8)
  {
    this->Environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
    this->Renderer->SetEnvironmentTexture(this->Environment);
    vtkNew<vtkSkybox> skybox;
    skybox->SetTexture(this->Environment);
    this->Renderer->AddActor(skybox);
    vtkNew<vtkConeSource> cone;
    cone->SetResolution(24);
    vtkNew<vtkPolyDataMapper> coneMapper;
    coneMapper->SetInputConnection(cone->GetOutputPort());
    vtkNew<vtkActor> coneActor;
    coneActor->SetMapper(coneMapper);
    coneActor->SetPosition(coneX, 0.0, -0.5);
    coneActor->GetProperty()->SetColor(0.9, 0.3, 0.2);
    this->Renderer->AddActor(coneActor);

    this->Teapot->SetResolution(8);
    this->Mapper->SetInputConnection(this->Teapot->GetOutputPort());
    this->Mapper->GetIceProperty()->SetNumberOfCracks(4);
    this->Ice->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Ice);
    this->CubeMaps->SetFaceSize(64);
    this->Pass->SetCubeMapPass(this->CubeMaps);
    this->Renderer->SetPass(this->Pass);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.3, 0.0, 0.0);
    camera->SetPosition(1.0, 1.2, 4.5);
    this->Renderer->ResetCameraClippingRange();
  }

  // Whether the pass holds any graphics resource.
  bool HoldsResources()
  {
    return this->Pass->GetBackfaceNormalPass()->GetNormalTexture() ||
      this->Pass->GetDepthIntervalPass()->GetDepthTexture() ||
      this->CubeMaps->GetCubeMap(this->Ice);
  }
};

vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* renderer, int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  return window;
}

IceTest::Image RenderAlone(int width, int height, double coneX)
{
  IceScene scene(coneX);
  auto window = MakeWindow(scene.Renderer, width, height);
  window->Render();
  return IceTest::Capture(window);
}

bool CloseAndReopen(int interiorMethod)
{
  bool ok = true;
  IceScene scene;
  scene.Mapper->SetInteriorMethod(interiorMethod);
  const std::string method =
    interiorMethod == vtkIceMapper::InteriorScreenSpace ? "screen space: " : "paper passes: ";
  auto window = MakeWindow(scene.Renderer, 240, 180);
  window->Render();
  const IceTest::Image before = IceTest::Capture(window);
  const IceTest::GLCensus census = IceTest::TakeGLCensus(window);
  ok = Expect(
         scene.HoldsResources(), method + "the pass holds its textures while the window is open") &&
    ok;

  window->Finalize();
  ok = Expect(!scene.HoldsResources(),
         method + "closing the window (Finalize) released the pass's textures and cube maps") &&
    ok;
  window->Render();
  const Difference reopened = Compare(before, IceTest::Capture(window));
  ok =
    Expect(reopened.Max == 0,
      method + "the window opened again renders the same picture (" + Describe(reopened) + ")") &&
    ok;
  const IceTest::GLCensus again = IceTest::TakeGLCensus(window);
  ok =
    Expect(again.Total() == census.Total(),
      method + "the new context holds as many OpenGL objects as the first: " + census.Describe() +
        " and " + again.Describe()) &&
    ok;

  scene.Renderer->ReleaseGraphicsResources(window);
  ok = Expect(!scene.HoldsResources(), "vtkRenderer::ReleaseGraphicsResources released them") && ok;
  window->Render();
  const Difference released = Compare(before, IceTest::Capture(window));
  ok = Expect(released.Max == 0,
         "after releasing them the next frame is the same (" + Describe(released) + ")") &&
    ok;
  ok = Expect(IceTest::TakeGLErrors(window).empty(), "no OpenGL error") && ok;
  return ok;
}

bool DeletedPassLeavesNothing()
{
  IceScene scene;
  auto window = MakeWindow(scene.Renderer, 200, 150);
  window->Render();
  // The same scene without the ice pass: the objects that remain are VTK's and the mappers'.
  scene.Renderer->SetPass(nullptr);
  window->Render();
  const IceTest::GLCensus without = IceTest::TakeGLCensus(window);
  for (int round = 0; round < 3; ++round)
  {
    vtkNew<vtkIcePass> pass;
    vtkNew<vtkIceCubeMapPass> cubeMaps;
    cubeMaps->SetFaceSize(32);
    pass->SetCubeMapPass(cubeMaps);
    scene.Renderer->SetUseDepthPeeling(round == 1);
    scene.Renderer->SetPass(pass);
    window->Render();
    scene.Renderer->SetPass(nullptr);
    window->Render();
    // pass and cubeMaps are deleted here, without ReleaseGraphicsResources.
  }
  scene.Renderer->SetUseDepthPeeling(false);
  window->Render();
  const IceTest::GLCensus after = IceTest::TakeGLCensus(window);
  // Depth peeling's own objects are the renderer's, made the first time it peels.
  return Expect(after.Textures <= without.Textures && after.VertexArrays <= without.VertexArrays &&
      after.Framebuffers <= without.Framebuffers && after.Buffers <= without.Buffers &&
      after.Renderbuffers <= without.Renderbuffers,
    "three ice passes set, used, removed and deleted leave no texture, buffer, framebuffer or "
    "vertex array behind: " +
      without.Describe() + " -> " + after.Describe());
}

bool TwoWindows()
{
  const IceTest::Image aloneA = RenderAlone(240, 180, 1.8);
  const IceTest::Image aloneB = RenderAlone(200, 200, -1.8);
  IceScene sceneA(1.8);
  IceScene sceneB(-1.8);
  auto windowA = MakeWindow(sceneA.Renderer, 240, 180);
  auto windowB = MakeWindow(sceneB.Renderer, 200, 200);
  bool ok = true;
  for (int frame = 0; frame < 3; ++frame)
  {
    windowA->Render();
    windowB->Render();
  }
  const Difference a = Compare(aloneA, IceTest::Capture(windowA));
  const Difference b = Compare(aloneB, IceTest::Capture(windowB));
  ok = Expect(a.Max == 0 && b.Max == 0,
         "two windows with ice render what each renders alone (" + Describe(a) + "; " +
           Describe(b) + ")") &&
    ok;
  windowA->Finalize();
  windowB->Render();
  const Difference afterClose = Compare(aloneB, IceTest::Capture(windowB));
  ok = Expect(afterClose.Max == 0,
         "the second window still renders the same after the first closes (" +
           Describe(afterClose) + ")") &&
    ok;
  ok = Expect(IceTest::TakeGLErrors(windowB).empty(), "no OpenGL error") && ok;
  return ok;
}

// A small ice teapot (not added to `renderer`), with the sky as `renderer`'s environment.
vtkSmartPointer<vtkActor> SmallIceTeapot(vtkRenderer* renderer)
{
  vtkSmartPointer<vtkTexture> environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkIceTeapotSource> teapot;
  teapot->SetResolution(8);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(teapot->GetOutputPort());
  auto ice = vtkSmartPointer<vtkActor>::New();
  ice->SetMapper(mapper);
  return ice;
}

// Pixels where the ice covers the picture: those that do not change with the background. Partly
// covered pixels (multisampling) are neither covered nor clear: the ice's thin parts make them
// away from any covered pixel too (NVIDIA's 8 samples caught slivers that 4 did not).
struct IceCoverage
{
  std::vector<bool> Covered;
  std::vector<bool> Clear; // the background in both pictures: no sample of the ice
};

IceCoverage IceMask(int width, int height)
{
  IceTest::Image images[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(i, i, i);
    renderer->AddActor(SmallIceTeapot(renderer));
    vtkNew<vtkIcePass> pass;
    renderer->SetPass(pass);
    renderer->GetActiveCamera()->SetPosition(0.0, 1.0, 5.0);
    renderer->GetActiveCamera()->SetClippingRange(0.5, 20.0);
    auto window = MakeWindow(renderer, width, height);
    window->Render();
    images[i] = IceTest::Capture(window);
  }
  const size_t pixels = images[0].RGB.size() / 3;
  IceCoverage coverage{ std::vector<bool>(pixels), std::vector<bool>(pixels) };
  const unsigned char black[3] = { 0, 0, 0 };
  const unsigned char white[3] = { 255, 255, 255 };
  for (size_t p = 0; p < pixels; ++p)
  {
    coverage.Covered[p] =
      IceTest::PixelDifference(&images[0].RGB[3 * p], &images[1].RGB[3 * p]) == 0;
    coverage.Clear[p] = IceTest::PixelDifference(&images[0].RGB[3 * p], black) == 0 &&
      IceTest::PixelDifference(&images[1].RGB[3 * p], white) == 0;
  }
  return coverage;
}

bool Layers()
{
  const int width = 220;
  const int height = 160;
  const IceCoverage coverage = IceMask(width, height);
  const std::vector<bool>& mask = coverage.Covered;
  // Layer 0: a scene (green plane, background); layer 1: the ice alone, with its pass.
  int samples = -1; // the window's default; a failure is tried again without multisampling
  auto build = [&](bool scene, bool ice) {
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    window->SetNumberOfLayers(2);
    if (samples >= 0)
    {
      window->SetMultiSamples(samples);
    }
    vtkNew<vtkRenderer> back;
    back->SetBackground(0.2, 0.1, 0.3);
    back->SetLayer(0);
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-3.0, -2.0, -1.0);
    plane->SetPoint1(3.0, -2.0, -1.0);
    plane->SetPoint2(-3.0, 2.0, -1.0);
    vtkNew<vtkPolyDataMapper> planeMapper;
    planeMapper->SetInputConnection(plane->GetOutputPort());
    vtkNew<vtkActor> planeActor;
    planeActor->SetMapper(planeMapper);
    planeActor->GetProperty()->SetColor(0.1, 0.8, 0.2);
    planeActor->GetProperty()->LightingOff();
    if (scene)
    {
      back->AddActor(planeActor);
    }
    window->AddRenderer(back);
    vtkNew<vtkRenderer> front;
    front->SetLayer(1);
    vtkSmartPointer<vtkActor> iceActor = SmallIceTeapot(front);
    if (ice)
    {
      front->AddActor(iceActor);
    }
    vtkNew<vtkIcePass> pass;
    front->SetPass(pass);
    front->SetActiveCamera(back->GetActiveCamera());
    back->GetActiveCamera()->SetPosition(0.0, 1.0, 5.0);
    back->GetActiveCamera()->SetClippingRange(0.5, 20.0);
    window->AddRenderer(front);
    window->Render();
    return IceTest::Capture(window);
  };
  // Where layer 0 shows through: the worst pixel's values say what went wrong there.
  struct Comparison
  {
    size_t Inside = 0, Outside = 0;
    int InsideMax = 0, OutsideMax = 0;
    size_t Worst = 0;
    IceTest::Image Both, SceneOnly, IceOnly;
  };
  auto compare = [&]() {
    Comparison c;
    c.Both = build(true, true);
    c.SceneOnly = build(true, false);
    c.IceOnly = build(false, true);
    // Silhouette pixels are partly covered (multisampling): their colour mixes the ice with
    // what lies below, which is what layers must do. Compare the pixels clear of the silhouette.
    auto nearSilhouette = [&](int x, int y) {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const int nx = std::min(std::max(x + dx, 0), width - 1);
          const int ny = std::min(std::max(y + dy, 0), height - 1);
          if (mask[ny * width + nx] != mask[y * width + x])
          {
            return true;
          }
        }
      }
      return false;
    };
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const size_t p = static_cast<size_t>(y) * width + x;
        if (nearSilhouette(x, y) || (!mask[p] && !coverage.Clear[p]))
        {
          continue;
        }
        const IceTest::Image& expected = mask[p] ? c.IceOnly : c.SceneOnly;
        const int d = IceTest::PixelDifference(&c.Both.RGB[3 * p], &expected.RGB[3 * p]);
        if (!mask[p] && d > c.OutsideMax)
        {
          c.Worst = p;
        }
        int& worst = mask[p] ? c.InsideMax : c.OutsideMax;
        worst = std::max(worst, d);
        (mask[p] ? c.Inside : c.Outside)++;
      }
    }
    return c;
  };
  auto describe = [&](const Comparison& c) {
    auto rgb = [&](const IceTest::Image& image) {
      const unsigned char* v = &image.RGB[3 * c.Worst];
      return std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]);
    };
    return std::to_string(c.Inside) + " pixels of ice as without the scene (max " +
      std::to_string(c.InsideMax) + "/255), " + std::to_string(c.Outside) +
      " others as without the ice (max " + std::to_string(c.OutsideMax) + "/255" +
      (c.OutsideMax ? ", worst at (" + std::to_string(c.Worst % width) + ", " +
            std::to_string(c.Worst / width) + "): " + rgb(c.Both) + " with the ice, " +
            rgb(c.SceneOnly) + " without, " + rgb(c.IceOnly) + " ice alone"
                    : std::string()) +
      ")";
  };
  auto passes = [](const Comparison& c) {
    return c.Inside > 2000 && c.Outside > 10000 && c.InsideMax == 0 && c.OutsideMax == 0;
  };
  const Comparison result = compare();
  if (!passes(result))
  {
    samples = 0;
    const Comparison single = compare();
    std::cout << "     without multisampling: " << describe(single) << "\n";
  }
  return Expect(passes(result), "ice on layer 1 over a scene on layer 0: " + describe(result));
}

bool Viewports()
{
  const IceTest::Image leftAlone = RenderAlone(150, 180, 1.8);
  const IceTest::Image rightAlone = RenderAlone(150, 180, -1.8);
  IceScene left(1.8);
  IceScene right(-1.8);
  left.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  right.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 180);
  window->AddRenderer(left.Renderer);
  window->AddRenderer(right.Renderer);
  window->Render();
  const IceTest::Image both = IceTest::Capture(window);
  int worst = 0;
  int different = 0;
  for (int y = 0; y < 180; ++y)
  {
    for (int x = 0; x < 150; ++x)
    {
      for (int d : { IceTest::PixelDifference(both.At(x, y), leftAlone.At(x, y)),
             IceTest::PixelDifference(both.At(150 + x, y), rightAlone.At(x, y)) })
      {
        worst = std::max(worst, d);
        different += d > 0 ? 1 : 0;
      }
    }
  }
  // A viewport 150 pixels to the right changes the rounding of a few texture lookups (VTK's
  // skybox and the cube maps work from window coordinates): 1/255 at a handful of pixels.
  return Expect(worst <= 1 && different <= 50,
    "two viewports with the full ice render what each renders alone (" + std::to_string(different) +
      " of 54000 pixels differ, by at most " + std::to_string(worst) + "/255)");
}

// Renders the scene with a second ice actor (a sphere): absent, or present and hidden (then
// shown for a second frame), or present and visible.
struct VisibilityRun
{
  IceTest::Image First;
  IceTest::Image Shown;
  int IceProps = 0;
};
VisibilityRun RenderWithSecondIce(bool present, bool hidden)
{
  IceScene scene;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> other;
  other->SetMapper(mapper);
  other->SetPosition(-1.4, 0.3, 0.0);
  other->SetVisibility(!hidden);
  if (present)
  {
    scene.Renderer->AddActor(other);
  }
  auto window = MakeWindow(scene.Renderer, 240, 180);
  VisibilityRun run;
  window->Render();
  run.First = IceTest::Capture(window);
  run.IceProps = scene.Pass->GetNumberOfIceProps();
  other->SetVisibility(true);
  window->Render();
  run.Shown = IceTest::Capture(window);
  return run;
}

bool Visibility()
{
  const VisibilityRun absent = RenderWithSecondIce(false, false);
  const VisibilityRun hidden = RenderWithSecondIce(true, true);
  const VisibilityRun visible = RenderWithSecondIce(true, false);
  const Difference asRemoved = Compare(absent.First, hidden.First);
  bool ok = Expect(asRemoved.Max == 0 && hidden.IceProps == 1,
    "an ice actor with SetVisibility(0) is as if removed (" + Describe(asRemoved) + "; " +
      std::to_string(hidden.IceProps) + " ice prop rendered)");
  const Difference shown = Compare(visible.First, hidden.Shown);
  ok = Expect(shown.Max == 0 && Compare(absent.First, visible.First).Max > 0,
         "shown again, it renders as if it had always been visible (" + Describe(shown) + ")") &&
    ok;
  return ok;
}

bool SharedMapper()
{
  auto render = [](bool shared) {
    IceScene scene;
    vtkNew<vtkIceMapper> otherMapper;
    otherMapper->SetInputConnection(scene.Teapot->GetOutputPort());
    otherMapper->GetIceProperty()->SetNumberOfCracks(4);
    vtkNew<vtkActor> other;
    other->SetMapper(shared ? scene.Mapper.Get() : otherMapper.Get());
    other->SetPosition(-1.6, 0.2, -0.6);
    other->RotateY(40.0);
    scene.Renderer->AddActor(other);
    auto window = MakeWindow(scene.Renderer, 260, 180);
    window->Render();
    window->Render();
    return IceTest::Capture(window);
  };
  const Difference d = Compare(render(false), render(true));
  return Expect(d.Max == 0,
    "one ice mapper drawn by two actors gives the picture of two mappers (" + Describe(d) + ")");
}

// Translucent quads (lighting off, so their colour is exact) in front of and behind an ice
// sphere: in front they blend over the ice, behind they are hidden by it.
const double QuadSpecs[3][7] = { { -1.0, 0.0, 1.0, 1.0, 0.1, 0.1, 0.5 },
  { -0.1, 1.0, 1.5, 0.1, 0.2, 1.0, 0.4 }, { -2.0, 2.0, -1.5, 0.1, 1.0, 0.1, 0.6 } };

bool Translucency(bool depthPeeling)
{
  const int width = 200;
  const int height = 160;
  auto render = [&](int quads) {
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.1, 0.1, 0.2);
    renderer->SetUseDepthPeeling(depthPeeling);
    renderer->SetMaximumNumberOfPeels(8);
    renderer->SetOcclusionRatio(0.0);
    vtkSmartPointer<vtkTexture> environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
    renderer->SetEnvironmentTexture(environment);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    mapper->GetIceProperty()->SetNumberOfCracks(
      0); // cracks are added over the finished frame (see reliability.md)
    vtkNew<vtkActor> ice;
    ice->SetMapper(mapper);
    renderer->AddActor(ice);
    // x0, x1, z, r, g, b, opacity: two quads in front of the ice (the second nearer, overlapping
    // the first over x in [-0.1, 0]), one behind it.
    for (int q = 0; q < quads; ++q)
    {
      const double* spec = QuadSpecs[q];
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(spec[0], -0.3, spec[2]);
      plane->SetPoint1(spec[1], -0.3, spec[2]);
      plane->SetPoint2(spec[0], 0.3, spec[2]);
      vtkNew<vtkPolyDataMapper> planeMapper;
      planeMapper->SetInputConnection(plane->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(planeMapper);
      actor->GetProperty()->SetColor(spec[3], spec[4], spec[5]);
      actor->GetProperty()->SetOpacity(spec[6]);
      actor->GetProperty()->LightingOff();
      renderer->AddActor(actor);
    }
    vtkNew<vtkIcePass> pass;
    renderer->SetPass(pass);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 6.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewAngle(40.0);
    renderer->ResetCameraClippingRange();
    auto window = MakeWindow(renderer, width, height);
    window->SetAlphaBitPlanes(1);
    window->SetMultiSamples(0);
    window->Render();
    return IceTest::Capture(window);
  };
  const auto ice = render(0);
  const auto scene = render(3);
  vtkNew<vtkRenderer> probe;
  probe->GetActiveCamera()->SetPosition(0.0, 0.0, 6.0);
  probe->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  probe->GetActiveCamera()->SetViewAngle(40.0);
  auto probeWindow = MakeWindow(probe, width, height);
  // The error at the pixel showing world point (x, 0, z) on a quad: the ice-only (or
  // background) pixel there with the listed quads composited over it, far to near.
  auto error = [&](double x, double z, std::initializer_list<int> quads) {
    probe->SetWorldPoint(x, 0.0, z, 1.0);
    probe->WorldToDisplay();
    double display[3];
    probe->GetDisplayPoint(display);
    const int px = static_cast<int>(display[0]);
    const int py = static_cast<int>(display[1]);
    const unsigned char* under = ice.At(px, py);
    double expected[3] = { under[0] / 255.0, under[1] / 255.0, under[2] / 255.0 };
    for (int q : quads)
    {
      const double* spec = QuadSpecs[q];
      for (int c = 0; c < 3; ++c)
      {
        expected[c] = spec[6] * spec[3 + c] + (1.0 - spec[6]) * expected[c];
      }
    }
    const unsigned char* got = scene.At(px, py);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(got[c] - 255.0 * expected[c]));
    }
    return worst;
  };
  // Over the ice: the near quads blend over it, the quad behind is hidden by it. Beside the
  // ice: the quad behind blends over the background.
  const double single =
    std::max({ error(-0.25, 1.0, { 0 }), error(0.25, 1.5, { 1 }), error(1.8, -1.5, { 2 }) });
  // Where the two near quads overlap, order-independent translucency only approximates the
  // order (weighted by depth); depth peeling composites exactly.
  const double overlap = error(-0.05, 1.0, { 0, 1 });
  const bool ok = single <= 3.0 && (!depthPeeling || overlap <= 3.0);
  return Expect(ok,
    std::string(depthPeeling ? "depth peeling" : "order-independent translucency") +
      ": translucent quads over the ice and hidden behind it, largest error " +
      std::to_string(single) + "/255 for one layer, " + std::to_string(overlap) + "/255 for two" +
      (depthPeeling ? " (bound 3/255 for both)" : " (bound 3/255 for one)"));
}
}

// One behaviour per ctest test: --case NAME (Testing/Cxx/CMakeLists.txt lists them); without
// it, every case in turn.
int TestIceLifecycle(int argc, char* argv[])
{
  const IceTest::Cases cases = {
    { "close-reopen-paper-passes",
      [] { return CloseAndReopen(vtkIceMapper::InteriorPaperPasses); } },
    { "close-reopen-screen-space",
      [] { return CloseAndReopen(vtkIceMapper::InteriorScreenSpace); } },
    { "deleted-pass", DeletedPassLeavesNothing },
    { "two-windows", TwoWindows },
    { "layers", Layers },
    { "viewports", Viewports },
    { "visibility", Visibility },
    { "shared-mapper", SharedMapper },
    { "translucency-oit", [] { return Translucency(false); } },
    { "translucency-depth-peeling", [] { return Translucency(true); } },
  };
  return IceTest::RunCases("TestIceLifecycle", argc, argv, cases);
}
