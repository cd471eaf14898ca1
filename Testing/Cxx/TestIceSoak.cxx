// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Soak: the full ice (two-sided refraction, a cube map of the scene rendered every frame, cracks,
// air, bumps) for many frames while the application does what long-running applications do.
// Every 100 frames (one cycle) the window is resized to a random size, ice actors are added and
// removed (one of them sharing another's mapper), one is hidden and shown, crack clipping is
// switched, and the pass is removed from the renderer and set again (every other cycle a new
// pass, the old one deleted). After every frame: no OpenGL error (glGetError) and no VTK error or
// warning. At the end of each cycle (same ice actors, same window size): the OpenGL objects of
// the context are counted (IceTest::TakeGLCensus) and the process's memory read (VmRSS, heap).
// After the first cycle (warm-up) the number of OpenGL objects of each kind must not grow and
// memory must stay flat.
//
//   IceCxxTests TestIceSoak [--frames N] [--seed S] [--keep-going] [--small | --window W H]
// 300 frames by default (ctest); the long soak (Testing/Scripts/soak.sh) runs 10 000 and keeps
// going after a failure to report every figure. --window: the largest window (first cycle) is
// W x H instead of 320 x 240, the others and the cube faces scaled with it.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkLight.h"
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
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{
//------------------------------------------------------------------------------
// THE FULL ICE. Everything the soak turns on for each ice mapper lives here, so that new ice
// features join the soak in one place.
void ConfigureFullIce(vtkIceMapper* mapper, int seed)
{
  mapper->GetIceProperty()->SetNumberOfCracks(6);
  mapper->GetIceProperty()->SetCrackSeed(seed);
  mapper->GetIceProperty()->SetCrackIntensity(1.5);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(19);
  mapper->GetIceProperty()->SetAirSeed(seed);
  mapper->GetIceProperty()->SetBumpStrength(0.1);
}

// The full ice pass: two-sided refraction, the depth interval (cracks, air) and a dynamic cube
// map of the scene rendered for every ice prop every frame, with its steps' GPU times measured.
vtkSmartPointer<vtkIcePass> MakeFullIcePass(int faceSize)
{
  auto pass = vtkSmartPointer<vtkIcePass>::New();
  pass->MeasureStepTimesOn();
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  cubeMaps->SetUpdateModeToEveryFrame();
  cubeMaps->SetFaceSize(faceSize);
  pass->SetCubeMapPass(cubeMaps);
  return pass;
}
//------------------------------------------------------------------------------

const int CycleLength = 100;
// Window sizes and cube faces; --small quarters the pixels (for valgrind, Testing/Scripts).
struct Sizes
{
  int Max[2];
  int Reference[2];
  int Face;
};
const Sizes Normal = { { 320, 240 }, { 200, 150 }, 64 };
const Sizes Small = { { 160, 120 }, { 100, 75 }, 32 };

// Normal's proportions with the largest window `width` x `height` (at least 64 x 48).
Sizes Scaled(int width, int height)
{
  width = std::max(64, width);
  height = std::max(48, height);
  Sizes sizes = { { width, height }, { width * 5 / 8, height * 5 / 8 },
    std::max(32, std::min(1024, width / 5)) };
  return sizes;
}

struct IceObject
{
  vtkSmartPointer<vtkAlgorithm> Source;
  vtkSmartPointer<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Actor;
};

class Soak
{
public:
  Soak(unsigned int seed, const Sizes& sizes)
    : Seed(seed)
    , Size(sizes)
    , Random(seed)
  {
    this->Environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
    this->Renderer->SetEnvironmentTexture(this->Environment);
    this->Renderer->SetBackground(0.3, 0.4, 0.5);
    vtkNew<vtkSkybox> skybox;
    skybox->SetTexture(this->Environment);
    this->Renderer->AddActor(skybox);
    this->AddScene();
    this->Pass = MakeFullIcePass(this->Size.Face);
    this->Renderer->SetPass(this->Pass);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(this->Size.Reference[0], this->Size.Reference[1]);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 3.0, 9.0);
    camera->SetViewAngle(40.0);
    this->AddIce(nullptr);
    this->AddIce(nullptr);
  }

  // Renders `frames` frames; false on the first failure.
  bool Run(int frames, bool keepGoing);

private:
  void AddScene();
  void AddIce(vtkIceMapper* shared);
  void RemoveIce(size_t index);
  void Event(int frame);
  bool Checkpoint(int frame);
  bool ReportMemory() const;

  unsigned int Seed;
  Sizes Size;
  std::mt19937 Random;
  vtkSmartPointer<vtkTexture> Environment;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkSmartPointer<vtkIcePass> Pass;
  std::vector<std::unique_ptr<IceObject>> Ice;
  int Created = 0;
  int GLErrors = 0;
  int NewPasses = 0;
  int Resizes = 0;
  int MessagesSeen = 0;
  IceTest::MessageCounter Messages;

  // Figures at the end of each cycle.
  struct Sample
  {
    int Frame;
    long Resident;
    long Heap;
    IceTest::GLCensus Census;
  };
  std::vector<Sample> Samples;
};

void Soak::AddScene()
{
  vtkNew<vtkPlaneSource> groundShape;
  groundShape->SetOrigin(-6.0, -1.2, 6.0);
  groundShape->SetPoint1(6.0, -1.2, 6.0);
  groundShape->SetPoint2(-6.0, -1.2, -6.0);
  vtkNew<vtkPolyDataMapper> groundMapper;
  groundMapper->SetInputConnection(groundShape->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(groundMapper);
  ground->GetProperty()->SetColor(0.8, 0.85, 0.9);
  this->Renderer->AddActor(ground);
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkConeSource> cone;
    cone->SetDirection(0.0, 1.0, 0.0);
    cone->SetResolution(16);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(cone->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetPosition(4.0 * std::cos(1.57 * i + 0.4), -0.7, 4.0 * std::sin(1.57 * i + 0.4));
    actor->GetProperty()->SetColor(0.2 + 0.2 * i, 0.6, 0.3);
    this->Renderer->AddActor(actor);
  }
  // A translucent sphere: the delegate's translucent pass runs every frame too.
  vtkNew<vtkSphereSource> glassShape;
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glassShape->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->SetPosition(0.0, 0.5, 2.5);
  glass->GetProperty()->SetColor(1.0, 0.4, 0.2);
  glass->GetProperty()->SetOpacity(0.4);
  this->Renderer->AddActor(glass);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(20.0, 30.0, 10.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  this->Renderer->AddLight(sun);
}

void Soak::AddIce(vtkIceMapper* shared)
{
  auto ice = std::make_unique<IceObject>();
  const int id = this->Created++;
  if (shared)
  {
    ice->Mapper = shared;
  }
  else
  {
    switch (id % 3)
    {
      case 0:
      {
        auto teapot = vtkSmartPointer<vtkIceTeapotSource>::New();
        teapot->SetResolution(5);
        ice->Source = teapot;
        break;
      }
      case 1:
      {
        auto block = vtkSmartPointer<vtkIceBlockSource>::New();
        block->SetResolution(6);
        block->SetSeed(id);
        ice->Source = block;
        break;
      }
      default:
      {
        auto sphere = vtkSmartPointer<vtkSphereSource>::New();
        sphere->SetThetaResolution(24);
        sphere->SetPhiResolution(12);
        ice->Source = sphere;
        break;
      }
    }
    ice->Mapper = vtkSmartPointer<vtkIceMapper>::New();
    ice->Mapper->SetInputConnection(ice->Source->GetOutputPort());
    ConfigureFullIce(ice->Mapper, id);
  }
  ice->Actor->SetMapper(ice->Mapper);
  std::uniform_real_distribution<double> place(-2.5, 2.5);
  ice->Actor->SetPosition(place(this->Random), 0.0, place(this->Random));
  ice->Actor->SetScale(0.8);
  this->Renderer->AddActor(ice->Actor);
  this->Ice.push_back(std::move(ice));
}

void Soak::RemoveIce(size_t index)
{
  this->Renderer->RemoveActor(this->Ice[index]->Actor);
  this->Ice.erase(this->Ice.begin() + static_cast<std::ptrdiff_t>(index));
}

// What the application does at `frame`, before rendering it.
void Soak::Event(int frame)
{
  const int cycle = frame / CycleLength;
  auto any = [this](
               size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(this->Random); };
  switch (frame % CycleLength)
  {
    case 0:
      // A random size; the largest one in the first cycle, so that later sizes need no new
      // memory.
      if (cycle == 0)
      {
        this->Window->SetSize(this->Size.Max[0], this->Size.Max[1]);
      }
      else
      {
        this->Window->SetSize(std::uniform_int_distribution<int>(
                                this->Size.Max[0] / 6, this->Size.Max[0])(this->Random),
          std::uniform_int_distribution<int>(this->Size.Max[1] / 6, this->Size.Max[1])(
            this->Random));
      }
      ++this->Resizes;
      break;
    case 10:
    case 30:
      this->AddIce(nullptr);
      break;
    case 20:
    {
      // Geometry clipping needs a closed surface: the teapot is open (spout, handle), it would
      // warn and keep the depth interval (TestIceBadInput).
      std::vector<vtkIceMapper*> closed;
      for (auto& ice : this->Ice)
      {
        if (!vtkIceTeapotSource::SafeDownCast(ice->Mapper->GetInputAlgorithm()))
        {
          closed.push_back(ice->Mapper);
        }
      }
      if (!closed.empty())
      {
        vtkIcePaperInterior* paper = closed[any(closed.size())]->GetPaperInterior();
        paper->SetCrackClipping(paper->GetCrackClipping() == vtkIcePaperInterior::Geometry
            ? vtkIcePaperInterior::DepthInterval
            : vtkIcePaperInterior::Geometry);
      }
      break;
    }
    case 40:
      this->Ice[any(this->Ice.size())]->Actor->VisibilityOff();
      break;
    case 45:
      for (auto& ice : this->Ice)
      {
        ice->Actor->VisibilityOn();
      }
      break;
    case 50:
      this->Renderer->SetPass(nullptr);
      break;
    case 55:
      if (cycle % 2 == 0)
      {
        // The old pass is deleted here, with its textures, framebuffers and cube maps.
        this->Pass = MakeFullIcePass(this->Size.Face);
        ++this->NewPasses;
      }
      this->Renderer->SetPass(this->Pass);
      break;
    case 60:
    case 80:
      this->RemoveIce(any(this->Ice.size()));
      if (frame % CycleLength == 80)
      {
        this->Window->SetSize(this->Size.Reference[0], this->Size.Reference[1]);
        ++this->Resizes;
      }
      break;
    case 65:
      // A second actor drawn by the mapper of an existing one.
      this->AddIce(this->Ice[any(this->Ice.size())]->Mapper);
      break;
    case 75:
      this->RemoveIce(this->Ice.size() - 1);
      break;
    default:
      break;
  }
}

bool Soak::Checkpoint(int frame)
{
  // Nothing in flight: what the driver allocated for the frame is counted.
  this->Window->WaitForCompletion();
  Sample sample;
  sample.Frame = frame;
  sample.Resident = IceTest::ResidentKiB();
  sample.Heap = IceTest::HeapInUseKiB();
  sample.Census = IceTest::TakeGLCensus(this->Window);
  this->Samples.push_back(sample);
  std::cout << "frame " << std::setw(6) << frame + 1 << ": " << this->Ice.size()
            << " ice actors, RSS " << sample.Resident / 1024.0 << " MiB, heap "
            << sample.Heap / 1024.0 << " MiB, GL objects " << sample.Census.Describe() << "\n";
  if (this->Samples.size() < 2)
  {
    return true; // the end of the warm-up cycle: the reference
  }
  const IceTest::GLCensus& reference = this->Samples.front().Census;
  const IceTest::GLCensus& now = sample.Census;
  const bool grew = now.Textures > reference.Textures || now.Buffers > reference.Buffers ||
    now.Framebuffers > reference.Framebuffers || now.Renderbuffers > reference.Renderbuffers ||
    now.VertexArrays > reference.VertexArrays || now.Programs > reference.Programs ||
    now.Shaders > reference.Shaders || now.Queries > reference.Queries;
  if (grew)
  {
    std::cout << "FAIL OpenGL objects grew after the warm-up: " << reference.Describe() << " -> "
              << now.Describe() << "\n";
    return false;
  }
  return true;
}

namespace
{
// Least-squares slope of y over x.
double Slope(const std::vector<double>& x, const std::vector<double>& y)
{
  double mx = 0.0;
  double my = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    mx += x[i] / x.size();
    my += y[i] / y.size();
  }
  double sxy = 0.0;
  double sxx = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0.0 ? sxy / sxx : 0.0;
}
}

// Memory after the warm-up. Both figures are noisy: what VTK and Mesa keep depends on what the
// last cycles did (sizes, shapes, crack clipping), and malloc does not give memory back in
// order. Measured with llvmpipe's rasterizer threads off (LP_NUM_THREADS=0, set by ctest and
// the soak script; with threads the heap moves by several MiB from frame to frame), the heap in
// use stays within about 1.5 MiB and VmRSS within about 8 MiB over 10 000 frames, without
// trend. Hence the bounds: the growth from the end of the warm-up to the end must stay below
// 3 MiB (heap) and 16 MiB (RSS), and over long runs (10 cycles or more) the least-squares
// trend below 100 bytes per frame (heap) and 1 KiB per frame (RSS), several times the trend
// that noise alone gives over 10 000 frames (about 20 and 100 bytes per frame).
bool Soak::ReportMemory() const
{
  const Sample& first = this->Samples.front();
  const Sample& last = this->Samples.back();
  std::vector<double> frames;
  std::vector<double> resident;
  std::vector<double> heap;
  for (const Sample& sample : this->Samples)
  {
    frames.push_back(sample.Frame);
    resident.push_back(1024.0 * sample.Resident);
    heap.push_back(1024.0 * sample.Heap);
  }
  const double mib = 1024.0 * 1024.0;
  const double residentGrowth = (last.Resident - first.Resident) / 1024.0;
  const double heapGrowth = (last.Heap - first.Heap) / 1024.0;
  const double residentSlope = Slope(frames, resident);
  const double heapSlope = Slope(frames, heap);
  std::cout << std::fixed << std::setprecision(2) << "soak: after the warm-up (frames "
            << first.Frame + 1 << " to " << last.Frame + 1 << ", " << this->Samples.size()
            << " checkpoints): RSS " << first.Resident / 1024.0 << " -> " << last.Resident / 1024.0
            << " MiB (growth " << residentGrowth << " MiB, range "
            << *std::min_element(resident.begin(), resident.end()) / mib << " to "
            << *std::max_element(resident.begin(), resident.end()) / mib << ", trend "
            << std::setprecision(0) << residentSlope << " B/frame)" << std::setprecision(2)
            << "; heap in use " << first.Heap / 1024.0 << " -> " << last.Heap / 1024.0
            << " MiB (growth " << heapGrowth << " MiB, range "
            << *std::min_element(heap.begin(), heap.end()) / mib << " to "
            << *std::max_element(heap.begin(), heap.end()) / mib << ", trend "
            << std::setprecision(0) << heapSlope << " B/frame); OpenGL objects "
            << first.Census.Describe() << " -> " << last.Census.Describe() << "\n"
            << std::defaultfloat << std::setprecision(6);
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer holds freed memory in its quarantine (up to 256 MiB) and replaces malloc:
  // memory figures mean nothing here. LeakSanitizer checks for leaks at exit instead.
  std::cout << "soak: memory bounds not checked under AddressSanitizer\n";
  return true;
#endif
  bool ok = true;
  if (heapGrowth > 3.0 || residentGrowth > 16.0)
  {
    std::cout << "FAIL memory grew after the warm-up (bounds: heap 3 MiB, RSS 16 MiB)\n";
    ok = false;
  }
  if (this->Samples.size() >= 10 && (heapSlope > 100.0 || residentSlope > 1024.0))
  {
    std::cout
      << "FAIL memory trend after the warm-up (bounds: heap 100 B/frame, RSS 1 KiB/frame)\n";
    ok = false;
  }
  return ok;
}

bool Soak::Run(int frames, bool keepGoing)
{
  this->Messages.Install();
  const auto start = std::chrono::steady_clock::now();
  bool ok = true;
  int frame = 0;
  for (; frame < frames && (ok || keepGoing); ++frame)
  {
    this->Event(frame);
    this->Renderer->GetActiveCamera()->Azimuth(1.5);
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
    const std::string errors = IceTest::TakeGLErrors(this->Window);
    if (!errors.empty())
    {
      std::cout << "FAIL OpenGL error after frame " << frame + 1 << ": " << errors << "\n";
      ++this->GLErrors;
      ok = false;
    }
    if (this->Messages.Errors() + this->Messages.Warnings() > this->MessagesSeen)
    {
      this->MessagesSeen = this->Messages.Errors() + this->Messages.Warnings();
      std::cout << "FAIL VTK error or warning at frame " << frame + 1 << ": "
                << this->Messages.Last() << "\n";
      ok = false;
    }
    if ((ok || keepGoing) && frame % CycleLength == CycleLength - 1)
    {
      ok = this->Checkpoint(frame) && ok;
    }
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Messages.Uninstall();

  std::cout << "soak: " << frame << " frames in " << seconds << " s ("
            << 1000.0 * seconds / std::max(frame, 1) << " ms/frame), " << this->Resizes
            << " resizes, " << this->Created << " ice actors created, " << this->NewPasses
            << " new passes, " << this->GLErrors << " OpenGL errors; windows up to "
            << this->Size.Max[0] << "x" << this->Size.Max[1] << ", cube faces " << this->Size.Face
            << " pixels\n";
  if (this->Samples.size() >= 2)
  {
    ok = this->ReportMemory() && ok;
  }
  std::cout << "soak: " << (ok ? "passed" : "FAILED") << " (seed " << this->Seed << ")\n";
  return ok;
}
}

int TestIceSoak(int argc, char* argv[])
{
  int frames = 300;
  unsigned int seed = 12345;
  bool keepGoing = false;
  Sizes sizes = Normal;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
    {
      frames = std::max(CycleLength, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--keep-going"))
    {
      keepGoing = true;
    }
    else if (!std::strcmp(argv[i], "--small"))
    {
      sizes = Small;
    }
    else if (!std::strcmp(argv[i], "--window") && i + 2 < argc)
    {
      sizes = Scaled(std::atoi(argv[i + 1]), std::atoi(argv[i + 2]));
      i += 2;
    }
    else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
    {
      seed = static_cast<unsigned int>(std::strtoul(argv[++i], nullptr, 10));
    }
  }
  Soak soak(seed, sizes);
  return soak.Run(frames, keepGoing) ? EXIT_SUCCESS : EXIT_FAILURE;
}
