// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The screen-space interior (InteriorScreenSpace) against the single-pass interior it replaced,
// which evaluated the same look once per fragment in the ice's own shader: its pictures, rendered
// at aea73f3 (the last commit that had it) on Debian 12's Mesa llvmpipe and reviewed, are the
// baselines (Testing/Data/Baseline/TestIceScreenInterior/; NAME_1.png: the screen-space interior as
// sid's Mesa renders it, which matched sid's single pass within these bounds at aea73f3's landing,
// while sid renders the scene 1-3/255 apart from Debian 12), matched up to the pixels along the
// ice's silhouette (where the single pass shaded fragments whose pixel centre lies outside the ice)
// and float rounding. One behaviour per case: the default look on the block and the teapot, 128
// cracks (found through their grid), a dynamic cube map, the milky core behind the air planes,
// two ice props overlapping (and one of them hidden: no program compiled), the debug views, a
// frosted surface, a turned and stretched actor, parallel projection and a renderer in a
// viewport (the milky core behind the air: baselines of its own, below). Each case also checks
// that the interior shows (the picture without cracks and air differs) and that nothing differs
// away from the ice.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceProperty.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const int Width = 320;
const int Height = 240;
std::string Baselines; // -V: the folder of the single pass's pictures
std::string Temporary; // -T: where a render that fails is written

// What a case changes in the scene: the mapper of the first (or only) ice, and the scene.
struct Scene
{
  vtkRenderWindow* Window;
  vtkRenderer* Renderer;
  vtkIcePass* Pass;
  std::vector<vtkIceMapper*> Mappers;
  std::vector<vtkActor*> Actors;
};
using Setup = std::function<void(Scene&)>;

// A Width x Height off-screen window drawing `renderer` with `pass` under the sky (cube faces of
// `faceSize` pixels).
vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* renderer, vtkIcePass* pass, int faceSize)
{
  IceTest::AddSky(renderer, faceSize);
  renderer->SetPass(pass);
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(Width, Height);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  return window;
}

// The scene rendered with every ice mapper set to `method`; `interior` false: no cracks or air.
IceTest::Image Render(
  vtkPolyDataAlgorithm* source, int method, bool interior, const Setup& setup, int ice = 1)
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkIcePass> pass;
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(renderer, pass, 256);
  IceTest::MessageRecorder* messages = IceTest::MessageRecorder::New();
  Scene scene{ window, renderer, pass, {} };
  std::vector<vtkSmartPointer<vtkIceMapper>> mappers;
  for (int i = 0; i < ice; ++i)
  {
    auto mapper = vtkSmartPointer<vtkIceMapper>::New();
    mapper->SetInputConnection(source->GetOutputPort());
    mapper->SetInteriorMethod(method);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    // A second ice beside and behind the first, overlapping it on screen.
    actor->SetPosition(0.9 * i, 0.25 * i, -1.2 * i);
    renderer->AddActor(actor);
    messages->Watch(mapper);
    messages->Watch(mapper->GetIceProperty());
    mappers.push_back(mapper);
    scene.Mappers.push_back(mapper);
    scene.Actors.push_back(actor);
  }
  messages->Watch(pass);
  messages->Watch(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.2, 1.6, 3.4);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  if (setup)
  {
    setup(scene);
  }
  for (vtkIceMapper* mapper : scene.Mappers)
  {
    if (!interior)
    {
      mapper->GetIceProperty()->SetNumberOfCracks(0);
      mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
      mapper->GetIceProperty()->SetMilkyCoreRadius(0.0);
    }
  }
  renderer->ResetCameraClippingRange();
  window->Render();
  IceTest::Image image = IceTest::Capture(window);
  for (const std::string& message : messages->Errors)
  {
    std::cout << "FAIL error: " << message << "\n";
  }
  for (const std::string& message : messages->Warnings)
  {
    std::cout << "FAIL warning: " << message << "\n";
  }
  const bool quiet = messages->Errors.empty() && messages->Warnings.empty();
  messages->Delete();
  if (!quiet)
  {
    image.RGB.clear();
  }
  return image;
}

// Screen-space against the single pass's picture of the same scene (the baseline named after
// the case, spaces as dashes): over the pixels the interior changes mean and 99th percentile of
// the difference bounded, elsewhere next to nothing differs.
bool Compare(const std::string& name, vtkPolyDataAlgorithm* source, const Setup& setup = nullptr,
  int ice = 1, double maxMean = 0.5, int maxP99 = 8)
{
  std::string file = name;
  std::replace(file.begin(), file.end(), ' ', '-');
  const IceTest::Image clean = Render(source, vtkIceMapper::InteriorScreenSpace, false, setup, ice);
  const IceTest::Image screen = Render(source, vtkIceMapper::InteriorScreenSpace, true, setup, ice);
  if (clean.RGB.empty() || screen.RGB.empty())
  {
    return IceTest::Expect(false, name + ": rendered without a message");
  }
  // The baseline and its alternatives (NAME_1.png, ...: sid's Mesa renders the scene around the
  // interior differently), as VTK's regression test takes them: one must meet the bounds.
  std::ostringstream what;
  bool ok = false;
  for (int alternative = 0; !ok; ++alternative)
  {
    const std::string path = Baselines + "/" + file +
      (alternative ? "_" + std::to_string(alternative) : std::string()) + ".png";
    const IceTest::Image single = IceTest::ReadPNG(path);
    if (single.Width != Width || single.Height != Height)
    {
      if (alternative == 0)
      {
        return IceTest::Expect(false,
          name + ": a " + std::to_string(Width) + "x" + std::to_string(Height) + " baseline " +
            path);
      }
      break;
    }
    std::vector<double> inside;
    size_t interiorPixels = 0;
    size_t outside = 0;
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        const int difference = IceTest::PixelDifference(single.At(x, y), screen.At(x, y));
        const bool interior = IceTest::PixelDifference(clean.At(x, y), single.At(x, y)) > 0;
        interiorPixels += interior ? 1 : 0;
        if (interior)
        {
          inside.push_back(difference);
        }
        else
        {
          outside += difference > 2 ? 1 : 0;
        }
      }
    }
    const IceTest::Stats stats = IceTest::Summarize(inside);
    what.str("");
    what << name << ": screen-space against single pass (" << path.substr(path.rfind('/') + 1)
         << ") over " << stats.Count << " pixels the interior changes: mean " << stats.Mean
         << "/255, p99 " << stats.P99 << "/255, max " << stats.Max << "/255; " << outside
         << " pixels elsewhere differ by more than 2/255";
    ok = interiorPixels > 2000 && stats.Mean <= maxMean && stats.P99 <= maxP99 &&
      outside < 0.002 * Width * Height;
  }
  if (!ok && !Temporary.empty())
  {
    IceTest::WritePNG(screen, Temporary + "/TestIceScreenInterior-" + file + ".png");
    what << " (render written to " << Temporary << "/TestIceScreenInterior-" << file << ".png)";
  }
  return IceTest::Expect(ok, what.str());
}

bool DefaultLookBlock()
{
  vtkNew<vtkIceBlockSource> block;
  return Compare("block", block);
}

bool DefaultLookTeapot()
{
  vtkNew<vtkIceTeapotSource> teapot;
  return Compare("teapot", teapot);
}

// 128 cracks: each pixel's ray meets only the cracks listed in the grid's cells it crosses; a
// crack left out of a cell its ray crosses would show as a difference (a crack's whole outline, tens of pixels over
// 16/255). Each crack's outline is a hard edge that the two methods, whose ray origins differ in
// the last bits (interpolated, or reconstructed from the depth), cut a pixel apart here and
// there: 64 times the outline of two cracks leaves about 1 % of the pixels 10/255 apart.
bool ManyCracks()
{
  vtkNew<vtkIceTeapotSource> teapot;
  return Compare(
    "128 cracks", teapot,
    [](Scene& scene) { scene.Mappers[0]->GetIceProperty()->SetNumberOfCracks(128); }, 1, 0.5, 16);
}

bool DynamicCubeMap()
{
  vtkNew<vtkIceTeapotSource> teapot;
  return Compare("dynamic cube map", teapot, [](Scene& scene) {
    vtkNew<vtkIceCubeMapPass> cubeMaps;
    cubeMaps->SetFaceSize(128);
    scene.Pass->SetCubeMapPass(cubeMaps);
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(1.6, 0.0, 0.0);
    ball->SetRadius(0.4);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(ball->GetOutputPort());
    vtkNew<vtkActor> ballActor;
    ballActor->SetMapper(ballMapper);
    ballActor->GetProperty()->SetColor(0.9, 0.3, 0.1);
    scene.Renderer->AddActor(ballActor);
  });
}

// The milky core behind the air planes and the bubbles in front of them: three draws composed
// one in front of the other (the core, the planes' quads, then the bubbles and the cracks). Its
// baselines are the screen-space interior at b411c06, which evaluated all of it in one quad, the
// planes in a loop per pixel (Debian 12's Mesa; NAME_1.png: sid's).
bool CoreBehindAir()
{
  vtkNew<vtkIceBlockSource> block;
  return Compare("core behind air", block, [](Scene& scene) {
    vtkIceProperty* look = scene.Mappers[0]->GetIceProperty();
    look->SetMilkyCoreRadius(0.6);
    look->SetMilkiness(0.5);
    look->SetBubbleDensity(0.5);
  });
}

bool TwoIce()
{
  vtkNew<vtkIceBlockSource> block;
  return Compare(
    "two ice", block,
    [](Scene& scene) {
      scene.Mappers[1]->GetIceProperty()->SetCrackSeed(7);
      scene.Mappers[1]->GetIceProperty()->SetAirSeed(9);
      scene.Renderer->ResetCamera();
    },
    2);
}

// Two ice props, then one hidden: the step's program for one prop is the one
// for several (the nearest test against its own front faces), so an ice prop leaving the view
// compiles nothing (the 10 000-frame soak at 1280 x 1024 saw a program appear at frame 3400
// when a random window size left one ice prop in view).
bool HiddenIceCompilesNothing()
{
  vtkNew<vtkIceBlockSource> block;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkIcePass> pass;
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(renderer, pass, 64);
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputConnection(block->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->SetPosition(0.9 * i, 0.25 * i, -1.2 * i);
    renderer->AddActor(actor);
    actors.push_back(actor);
  }
  renderer->ResetCamera();
  // The second frame compiles what a still input gets then (vtkIceMapper's closure check).
  window->Render();
  window->Render();
  const IceTest::GLCensus both = IceTest::TakeGLCensus(window);
  actors[1]->VisibilityOff();
  window->Render();
  const IceTest::GLCensus one = IceTest::TakeGLCensus(window);
  return IceTest::Expect(one.Programs == both.Programs && one.Shaders == both.Shaders,
    "one of two ice props hidden: " + std::to_string(both.Programs) + " -> " +
      std::to_string(one.Programs) + " programs, " + std::to_string(both.Shaders) + " -> " +
      std::to_string(one.Shaders) + " shaders");
}

bool DebugViews()
{
  vtkNew<vtkIceBlockSource> block;
  bool ok = Compare("cracks debug view", block,
    [](Scene& scene) { scene.Mappers[0]->SetDebugView(vtkIceMapper::DebugCracksClipped); });
  ok = Compare("air debug view", block,
         [](Scene& scene) { scene.Mappers[0]->SetDebugView(vtkIceMapper::DebugAir); }) &&
    ok;
  return ok;
}

bool Frosted()
{
  vtkNew<vtkIceBlockSource> block;
  return Compare(
    "frosted", block, [](Scene& scene) { scene.Mappers[0]->GetIceProperty()->SetRoughness(0.3); });
}

// A turned and stretched actor: the crack sheets' normals go through the actor's normal matrix.
bool Transformed()
{
  vtkNew<vtkIceBlockSource> block;
  return Compare("turned and stretched actor", block, [](Scene& scene) {
    scene.Actors[0]->RotateY(30.0);
    scene.Actors[0]->RotateX(20.0);
    scene.Actors[0]->SetScale(1.0, 1.3, 0.8);
    scene.Renderer->ResetCamera();
  });
}

bool Parallel()
{
  vtkNew<vtkIceTeapotSource> teapot;
  return Compare("parallel projection", teapot, [](Scene& scene) {
    scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
    scene.Renderer->ResetCamera();
  });
}

bool Viewport()
{
  vtkNew<vtkIceTeapotSource> teapot;
  return Compare("viewport", teapot, [](Scene& scene) {
    scene.Renderer->SetViewport(0.3, 0.2, 1.0, 1.0);
    scene.Renderer->ResetCamera();
  });
}
}

int TestIceScreenInterior(int argc, char* argv[])
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "-V")
    {
      Baselines = argv[i + 1];
    }
    else if (option == "-T")
    {
      Temporary = argv[i + 1];
    }
  }
  const IceTest::Cases cases = {
    { "block", DefaultLookBlock },
    { "teapot", DefaultLookTeapot },
    { "many-cracks", ManyCracks },
    { "dynamic-cube-map", DynamicCubeMap },
    { "core-behind-air", CoreBehindAir },
    { "two-ice", TwoIce },
    { "hidden-ice-compiles-nothing", HiddenIceCompilesNothing },
    { "debug-views", DebugViews },
    { "frosted", Frosted },
    { "transformed", Transformed },
    { "parallel", Parallel },
    { "viewport", Viewport },
  };
  return IceTest::RunCases("TestIceScreenInterior", argc, argv, cases);
}
