// ice-bench: the paper's performance study, side by side with plain VTK. Every configuration is
// timed in the same run as a plain VTK rendering (vtkPolyDataMapper, Phong) of the same scene and
// object, interleaved with it round by round, and reported as a ratio to it.
#include "IceBench.h"
#include "IceHeadless.h"
#include "IceModelFile.h"
#include "IceOutputFile.h"
#include "IceScene.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using IceBench::Configuration;
using IceBench::Group;
using IceBench::Material;

namespace
{
const int Width = 1024;
const int Height = 768;

const char* const Usage =
  "usage: ice-bench [--quick] [--frames N] [--csv FILE] [--plot FILE] [--markdown FILE]\n"
  "                 [--only TEXT] [--multisamples N] [--backend auto|x|egl|osmesa]\n"
  "Times ice against plain VTK (same scene, a vtkPolyDataMapper with Phong shading) at\n"
  "1024x768, offscreen, glFinish after every frame, and prints a table of medians and ratios.\n"
  "  --quick     a few configurations and frames (under a minute)\n"
  "  --frames N  timed frames per configuration (default 20, quick 4), after warm-up; in a\n"
  "              full run configurations slower than 200 ms a frame get fewer (at least 5)\n"
  "  --csv       the results as CSV (default ice-bench.csv; '' for none)\n"
  "  --plot      a PNG of ratios and scaling curves (default none)\n"
  "  --markdown  the tables and the machine as Markdown (default none)\n"
  "  --only      only the groups whose id contains TEXT (e.g. dynamic, cracks, objects)\n"
  "  --multisamples N  the window's multisampling (default: VTK's, 4 on llvmpipe)\n"
  "  --backend   x (X display), egl or osmesa (no X needed); default $VTKICE_BACKEND or auto\n";

struct Options
{
  bool Quick = false;
  int Frames = -1;
  std::string Csv = "ice-bench.csv";
  std::string Plot;
  std::string Markdown;
  std::string Only;
  std::string Backend;
  int MultiSamples = -1;
};

int Fail(const std::string& message, int code)
{
  // Arguments and file names are echoed: terminal escapes in them are not passed on.
  std::cerr << "ice-bench: " << IceModelFile::Printable(message, 2000) << "\n";
  return code;
}

// Returns -1 when the arguments are fine, otherwise the exit code.
int Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      return 0;
    }
    if (arg == "--quick")
    {
      options.Quick = true;
      continue;
    }
    if (arg != "--frames" && arg != "--csv" && arg != "--plot" && arg != "--markdown" &&
      arg != "--only" && arg != "--multisamples" && arg != "--backend")
    {
      return Fail("unknown argument '" + arg + "' (see --help)", 2);
    }
    if (i + 1 >= argc)
    {
      return Fail("option " + arg + " needs a value (see --help)", 2);
    }
    const std::string value = argv[++i];
    if (arg == "--frames")
    {
      char extra = 0;
      if (std::sscanf(value.c_str(), "%d%c", &options.Frames, &extra) != 1 || options.Frames < 1 ||
        options.Frames > 10000)
      {
        return Fail("bad --frames '" + value + "' (expected 1..10000)", 2);
      }
    }
    else if (arg == "--multisamples")
    {
      char extra = 0;
      if (std::sscanf(value.c_str(), "%d%c", &options.MultiSamples, &extra) != 1 ||
        options.MultiSamples < 0 || options.MultiSamples > 16)
      {
        return Fail("bad --multisamples '" + value + "' (expected 0..16)", 2);
      }
    }
    else if (arg == "--csv")
    {
      options.Csv = value;
    }
    else if (arg == "--plot")
    {
      if (!value.empty() && IceOutputFile::ImageFormat(value).empty())
      {
        return Fail("bad --plot '" + value + "' (the name must end in .png, .jpg or .jpeg)", 2);
      }
      options.Plot = value;
    }
    else if (arg == "--markdown")
    {
      options.Markdown = value;
    }
    else if (arg == "--only")
    {
      options.Only = value;
    }
    else
    {
      IceHeadless::Backend backend;
      if (!IceHeadless::ParseBackend(value, backend))
      {
        return Fail("bad --backend '" + value + "' (expected auto, x, egl or osmesa)", 2);
      }
      options.Backend = value;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
// The configurations.

Configuration Plain()
{
  Configuration c;
  c.Label = "plain VTK (Phong)";
  return c;
}

Configuration Ice(const std::string& label, Material material, int cracks = 0)
{
  Configuration c;
  c.Label = label;
  c.Ice = material;
  c.Cracks = material == Material::CracksAir ? 2 : cracks;
  c.AirPlanes = material == Material::CracksAir ? 19 : 0;
  return c;
}

Configuration Dynamic(const std::string& label, int mode, int faceSize = 512, int facesPerFrame = 6,
  bool culling = true, bool moving = false)
{
  Configuration c = Ice(label, Material::TwoSided);
  c.CubeMap = true;
  c.UpdateMode = mode;
  c.FaceSize = faceSize;
  c.FacesPerFrame = facesPerFrame;
  c.Culling = culling;
  c.Moving = moving;
  return c;
}

std::vector<Group> DefineGroups()
{
  std::vector<Group> groups;
  const char* const objects[3] = { "sphere", "block", "teapot" };
  for (double coverage : { 0.2, 1.0 })
  {
    for (const char* object : objects)
    {
      Group g;
      const bool fifth = coverage < 0.5;
      g.Id = std::string(fifth ? "objects-" : "fullscreen-") + object;
      g.Title = std::string(object) + ", static environment, ice " +
        (fifth ? "about 1/5 of the screen" : "covering the screen");
      g.Object = object;
      g.Coverage = coverage;
      g.Quick = fifth && std::string(object) == "teapot";
      g.Configurations = { Plain(), Ice("one-sided ice", Material::OneSided),
        Ice("two-sided ice", Material::TwoSided),
        Ice("two-sided + cracks + air", Material::CracksAir) };
      groups.push_back(g);
    }
  }

  Group dynamic;
  dynamic.Id = "dynamic-teapot";
  dynamic.Title = "teapot in the landscape, ice about 1/5 of the screen";
  dynamic.Object = "teapot";
  dynamic.Landscape = true;
  dynamic.Quick = true;
  const int every = vtkIceCubeMapPass::EveryFrame;
  const int onChange = vtkIceCubeMapPass::OnChange;
  dynamic.Configurations = { Plain(), Ice("two-sided, static environment", Material::TwoSided),
    Dynamic("cube map every frame, 512", every),
    Dynamic("cube map every frame, 512, no culling", every, 512, 6, false),
    Dynamic("cube map every frame, 256", every, 256),
    Dynamic("cube map every frame, 128", every, 128),
    Dynamic("cube map on change, still scene", onChange),
    Dynamic("cube map on change, ball moving", onChange, 512, 6, true, true),
    Dynamic("cube map 1 face per frame, 512", every, 512, 1),
    Dynamic("cube map 2 faces per frame, 512", every, 512, 2),
    Dynamic("cube map 3 faces per frame, 512", every, 512, 3) };
  groups.push_back(dynamic);

  Group cracks;
  cracks.Id = "cracks-teapot";
  cracks.Title = "teapot, static environment, two-sided, ice about 1/5 of the screen";
  cracks.Object = "teapot";
  cracks.Quick = true;
  cracks.Configurations = { Plain() };
  for (int n : { 0, 2, 8, 32, 128 })
  {
    cracks.Configurations.push_back(
      Ice(std::to_string(n) + (n == 1 ? " crack" : " cracks"), Material::TwoSided, n));
  }
  groups.push_back(cracks);

  for (const char* size : { "1k", "10k", "100k", "1M" })
  {
    Group g;
    g.Id = std::string("triangles-") + size;
    g.Title = std::string("sphere of ") + size + " triangles, static environment, about 1/5";
    g.Object = std::string("sphere-") + size;
    g.Quick = std::string(size) == "1k" || std::string(size) == "10k";
    g.Configurations = { Plain(), Ice("one-sided ice", Material::OneSided),
      Ice("two-sided ice", Material::TwoSided) };
    groups.push_back(g);
  }
  return groups;
}

// Quick mode keeps the cheap end of every scaling series.
void Shorten(Group& g)
{
  auto keep = [&](const std::function<bool(const Configuration&)>& wanted) {
    std::vector<Configuration> kept;
    for (const Configuration& c : g.Configurations)
    {
      if (c.Ice == Material::Plain || wanted(c))
      {
        kept.push_back(c);
      }
    }
    g.Configurations = kept;
  };
  if (g.Id == "dynamic-teapot")
  {
    keep([](const Configuration& c) {
      return !c.CubeMap || (c.FaceSize == 128) ||
        (c.UpdateMode == vtkIceCubeMapPass::OnChange && !c.Moving);
    });
  }
  else if (g.Id == "cracks-teapot")
  {
    keep([](const Configuration& c) { return c.Cracks <= 8; });
  }
}

//------------------------------------------------------------------------------
// Scenes.

vtkSmartPointer<vtkPolyData> MakeObject(const std::string& object, std::string& error)
{
  static const std::map<std::string, std::pair<int, int>> spheres = { { "sphere-1k", { 32, 17 } },
    { "sphere-10k", { 100, 51 } }, { "sphere-100k", { 316, 160 } },
    { "sphere-1M", { 1000, 501 } } };
  auto found = spheres.find(object);
  if (found == spheres.end())
  {
    return IceScene::LoadModel(object, error);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(found->second.first);
  sphere->SetPhiResolution(found->second.second);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sphere->GetOutputPort());
  triangles->Update();
  vtkSmartPointer<vtkPolyData> output = triangles->GetOutput();
  return output;
}

// One configuration's renderer and what the frame loop needs of it.
struct Scene
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Ball;
  vtkSmartPointer<vtkIceCubeMapPass> CubeMapPass;
};

Scene BuildScene(const Group& g, Configuration& c, vtkPolyData* object, vtkTexture* environment)
{
  Scene scene;
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkRenderer* renderer = scene.Renderer;
  IceScene::AddEnvironment(renderer, environment);
  if (g.Landscape)
  {
    const double ground = object->GetBounds()[2];
    IceScene::AddLandscape(renderer, ground);
    // A ball that circles the ice when the configuration moves it (dynamic scenes only).
    vtkNew<vtkSphereSource> ballShape;
    ballShape->SetRadius(0.3);
    ballShape->SetThetaResolution(24);
    ballShape->SetPhiResolution(12);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(ballShape->GetOutputPort());
    scene.Ball = vtkSmartPointer<vtkActor>::New();
    scene.Ball->SetMapper(ballMapper);
    scene.Ball->GetProperty()->SetColor(0.8, 0.15, 0.1);
    scene.Ball->SetPosition(-2.4, ground + 0.3, 0.0);
    renderer->AddActor(scene.Ball);
  }

  vtkNew<vtkActor> actor;
  if (c.Ice == Material::Plain)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(object);
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetInterpolationToPhong();
    property->SetColor(0.75, 0.85, 0.95);
    property->SetSpecular(0.5);
    property->SetSpecularPower(40.0);
  }
  else
  {
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputData(object);
    // The paper's study: no bumps; cracks and air as configured (air only in the "+ cracks +
    // air" configurations).
    mapper->SetBumpStrength(0.0);
    mapper->SetNumberOfAirPlanes(0);
    actor->SetMapper(mapper);
    if (c.Ice != Material::OneSided)
    {
      vtkNew<vtkIcePass> icePass;
      renderer->SetPass(icePass);
      mapper->SetNumberOfCracks(c.Cracks);
      mapper->SetNumberOfAirPlanes(c.AirPlanes);
      if (c.CubeMap)
      {
        scene.CubeMapPass = vtkSmartPointer<vtkIceCubeMapPass>::New();
        scene.CubeMapPass->SetUpdateMode(c.UpdateMode);
        scene.CubeMapPass->SetFaceSize(c.FaceSize);
        scene.CubeMapPass->SetFacesPerFrame(c.FacesPerFrame);
        scene.CubeMapPass->SetFrustumCulling(c.Culling);
        icePass->SetCubeMapPass(scene.CubeMapPass);
      }
    }
  }
  renderer->AddActor(actor);
  return scene;
}

// Moves the ball a step along its circle around the ice.
void MoveBall(vtkActor* ball)
{
  double* p = ball->GetPosition();
  const double angle = std::atan2(p[2], p[0]) + vtkMath::RadiansFromDegrees(3.0);
  ball->SetPosition(2.4 * std::cos(angle), p[1], 2.4 * std::sin(angle));
}

//------------------------------------------------------------------------------
// Calibration: the camera distance at which the object covers the wanted fraction of the window.

double Coverage(vtkRenderWindow* window, vtkRenderer* renderer, double distance)
{
  IceScene::PlaceCamera(renderer, distance);
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, Width - 1, Height - 1, 0, pixels);
  vtkIdType covered = 0;
  const vtkIdType n = pixels->GetNumberOfTuples();
  const int components = pixels->GetNumberOfComponents();
  for (vtkIdType i = 0; i < n; ++i)
  {
    covered += pixels->GetValue(i * components) > 127 ? 1 : 0;
  }
  return static_cast<double>(covered) / static_cast<double>(n);
}

// Coverage falls as the camera backs away (outside the object). For "the whole screen" the
// farthest distance that still covers 99.5 % of it.
double Calibrate(vtkRenderWindow* window, vtkPolyData* object, double wanted, double& achieved)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(object);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  renderer->AddActor(actor);
  window->AddRenderer(renderer);

  const double target = wanted >= 1.0 ? 0.995 : wanted;
  double far = 40.0;
  double near = far;
  double nearCoverage = Coverage(window, renderer, near);
  while (nearCoverage < target && near > 0.5)
  {
    far = near;
    near /= 1.5;
    nearCoverage = Coverage(window, renderer, near);
  }
  for (int i = 0; i < 14; ++i)
  {
    const double middle = std::sqrt(near * far);
    if (Coverage(window, renderer, middle) >= target)
    {
      near = middle;
    }
    else
    {
      far = middle;
    }
  }
  // For a fraction, whichever end is closer; for the whole screen, the end that covers it.
  const double farCoverage = Coverage(window, renderer, far);
  const double nearCov = Coverage(window, renderer, near);
  double distance = near;
  achieved = nearCov;
  if (wanted < 1.0 && std::abs(farCoverage - wanted) < std::abs(nearCov - wanted))
  {
    distance = far;
    achieved = farCoverage;
  }
  window->RemoveRenderer(renderer);
  return distance;
}

//------------------------------------------------------------------------------
// Timing.

IceBench::Statistics Summarize(std::vector<double> times)
{
  IceBench::Statistics s;
  if (times.empty())
  {
    return s;
  }
  std::sort(times.begin(), times.end());
  auto quantile = [&](double q) {
    const double position = q * static_cast<double>(times.size() - 1);
    const size_t below = static_cast<size_t>(std::floor(position));
    const size_t above = std::min(below + 1, times.size() - 1);
    const double t = position - static_cast<double>(below);
    return times[below] * (1.0 - t) + times[above] * t;
  };
  s.Median = quantile(0.5);
  s.P25 = quantile(0.25);
  s.P75 = quantile(0.75);
  s.Min = times.front();
  s.Max = times.back();
  double sum = 0.0;
  for (double t : times)
  {
    sum += t;
  }
  s.Mean = sum / static_cast<double>(times.size());
  return s;
}

// CPU time of the whole process (the main thread and llvmpipe's threads) in milliseconds.
double ProcessCpuMilliseconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

struct Schedule
{
  int WarmUp = 3;   // untimed frames per configuration before the first round
  int Rounds = 5;   // every configuration of a group takes its turn once per round
  int PerRound = 4; // timed frames per turn, after one untimed frame
  // When positive, a turn of a slow configuration takes about this many milliseconds: fewer
  // timed frames (at least one per round), no untimed frame after the switch for frames over
  // SlowFrame ms, and two warm-up frames. Keeps the full run within minutes.
  double TurnBudget = 0.0;
  double SlowFrame = 100.0;
};

void MeasureGroup(
  Group& g, vtkRenderWindow* window, std::vector<Scene>& scenes, const Schedule& schedule)
{
  const size_t n = scenes.size();
  auto activate = [&](size_t active) {
    for (size_t i = 0; i < n; ++i)
    {
      scenes[i].Renderer->SetDraw(i == active ? 1 : 0);
    }
  };
  auto frame = [&](size_t i) {
    if (g.Configurations[i].Moving && scenes[i].Ball)
    {
      MoveBall(scenes[i].Ball);
    }
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
  };
  // The last warm-up frame of each configuration estimates its frame time.
  std::vector<double> estimate(n, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    activate(i);
    for (int f = 0; f < schedule.WarmUp; ++f)
    {
      estimate[i] = frame(i);
      if (f >= 1 && schedule.TurnBudget > 0.0 && estimate[i] > schedule.SlowFrame)
      {
        break;
      }
    }
  }
  auto framesPerTurn = [&](size_t i) {
    if (schedule.TurnBudget <= 0.0 || estimate[i] <= 0.0)
    {
      return schedule.PerRound;
    }
    const int fit = static_cast<int>(schedule.TurnBudget / estimate[i]);
    return std::max(1, std::min(schedule.PerRound, fit));
  };
  std::vector<long long> faces(n, 0);
  for (int round = 0; round < schedule.Rounds; ++round)
  {
    for (size_t k = 0; k < n; ++k)
    {
      // A different configuration starts each round.
      const size_t i = (k + static_cast<size_t>(round)) % n;
      activate(i);
      if (schedule.TurnBudget <= 0.0 || estimate[i] <= schedule.SlowFrame)
      {
        frame(i); // settles the switch between renderers
      }
      const long long facesBefore =
        scenes[i].CubeMapPass ? scenes[i].CubeMapPass->GetNumberOfFaceRenders() : 0;
      const int frames = framesPerTurn(i);
      for (int f = 0; f < frames; ++f)
      {
        const double cpuStart = ProcessCpuMilliseconds();
        const double milliseconds = frame(i);
        g.Configurations[i].CpuTimes.push_back(ProcessCpuMilliseconds() - cpuStart);
        g.Configurations[i].Times.push_back(milliseconds);
      }
      if (scenes[i].CubeMapPass)
      {
        faces[i] += scenes[i].CubeMapPass->GetNumberOfFaceRenders() - facesBefore;
      }
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    Configuration& c = g.Configurations[i];
    c.Stats = Summarize(c.Times);
    c.CpuMedian = Summarize(c.CpuTimes).Median;
    c.CubeFacesPerFrame =
      c.Times.empty() ? 0.0 : static_cast<double>(faces[i]) / static_cast<double>(c.Times.size());
  }
  const double baseline = g.Configurations[0].Stats.Median;
  const double cpuBaseline = g.Configurations[0].CpuMedian;
  for (Configuration& c : g.Configurations)
  {
    c.Ratio = baseline > 0.0 ? c.Stats.Median / baseline : 0.0;
    c.CpuRatio = cpuBaseline > 0.0 ? c.CpuMedian / cpuBaseline : 0.0;
  }
  activate(n); // none
}

//------------------------------------------------------------------------------
// The machine.

struct Machine
{
  std::string Renderer;
  std::string GLVersion;
  std::string CPU;
  unsigned int Threads = 0;
  std::string Backend;
  std::string VTK;
  int MultiSamples = 0;
};

std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const std::string::size_type colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown";
}

std::string GLString(GLenum name)
{
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "unknown";
}

//------------------------------------------------------------------------------
// Targets (issue 8, item 4: llvmpipe, ice about 1/5 of 1024x768, ratio to plain VTK).

const Configuration* Find(const std::vector<Group>& groups, const std::string& id,
  const std::function<bool(const Configuration&)>& wanted)
{
  for (const Group& g : groups)
  {
    if (g.Id != id)
    {
      continue;
    }
    for (const Configuration& c : g.Configurations)
    {
      if (wanted(c) && !c.Times.empty())
      {
        return &c;
      }
    }
  }
  return nullptr;
}

std::vector<IceBench::Target> EvaluateTargets(const std::vector<Group>& groups)
{
  std::vector<IceBench::Target> targets;
  auto ratio = [&](const std::string& name, const std::string& limit, double bound,
                 const Configuration* c) {
    IceBench::Target t;
    t.Name = name;
    t.Limit = limit;
    t.Bound = bound;
    t.Measured = c != nullptr;
    t.Value = c ? c->Ratio : 0.0;
    t.Met = t.Measured && t.Value <= bound;
    targets.push_back(t);
  };
  for (const char* object : { "sphere", "block", "teapot" })
  {
    const std::string id = std::string("objects-") + object;
    ratio(std::string("static environment, two-sided (") + object + ")", "<= 1.3x", 1.3,
      Find(groups, id, [](const Configuration& c) { return c.Ice == Material::TwoSided; }));
  }
  for (const char* object : { "sphere", "block", "teapot" })
  {
    const std::string id = std::string("objects-") + object;
    ratio(std::string("+ cracks + air (") + object + ")", "<= 1.5x", 1.5,
      Find(groups, id, [](const Configuration& c) { return c.Ice == Material::CracksAir; }));
  }
  ratio("dynamic cube map every frame (teapot, landscape, 512)", "<= 3x", 3.0,
    Find(groups, "dynamic-teapot", [](const Configuration& c) {
      return c.CubeMap && c.UpdateMode == vtkIceCubeMapPass::EveryFrame && c.FaceSize == 512 &&
        c.FacesPerFrame == 6 && c.Culling;
    }));
  const Configuration* two = Find(groups, "cracks-teapot",
    [](const Configuration& c) { return c.Ice == Material::TwoSided && c.Cracks == 2; });
  const Configuration* many = Find(groups, "cracks-teapot",
    [](const Configuration& c) { return c.Ice == Material::TwoSided && c.Cracks == 128; });
  IceBench::Target t;
  t.Name = "cracks 2 -> 128 (teapot)";
  t.Limit = "adds <= 15 %";
  t.Bound = 0.15;
  t.IsIncrease = true;
  t.Measured = two && many;
  t.Value = t.Measured ? many->Stats.Median / two->Stats.Median - 1.0 : 0.0;
  t.Met = t.Measured && t.Value <= t.Bound;
  targets.push_back(t);
  return targets;
}

//------------------------------------------------------------------------------
// Output.

std::string Fixed(double value, int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

std::string CoverageText(const Group& g)
{
  return Fixed(100.0 * g.MeasuredCoverage, 1) + " %";
}

std::string TargetValue(const IceBench::Target& t)
{
  if (!t.Measured)
  {
    return "not measured";
  }
  return t.IsIncrease ? (t.Value >= 0 ? "+" : "") + Fixed(100.0 * t.Value, 1) + " %"
                      : Fixed(t.Value, 2) + "x";
}

std::string TargetVerdict(const IceBench::Target& t)
{
  if (!t.Measured)
  {
    return "-";
  }
  if (t.Met)
  {
    return "met";
  }
  const double over =
    t.IsIncrease ? 100.0 * (t.Value - t.Bound) : 100.0 * (t.Value / t.Bound - 1.0);
  return "missed by " + Fixed(over, over < 10.0 ? 1 : 0) + (t.IsIncrease ? " points" : " %");
}

void PrintGroup(std::ostream& out, const Group& g)
{
  out << "\n== " << g.Title << "\n   " << g.Triangles << " triangles, object covers "
      << CoverageText(g) << " of " << Width << "x" << Height << ", " << Fixed(g.Seconds, 1)
      << " s\n";
  out << "   " << std::left << std::setw(42) << "configuration" << std::right << std::setw(10)
      << "median ms" << std::setw(18) << "IQR ms" << std::setw(9) << "fps" << std::setw(8)
      << "ratio" << std::setw(10) << "CPU ms" << std::setw(10) << "CPU ratio"
      << "\n";
  for (const Configuration& c : g.Configurations)
  {
    out << "   " << std::left << std::setw(42) << c.Label << std::right << std::setw(10)
        << Fixed(c.Stats.Median, 2) << std::setw(18)
        << (Fixed(c.Stats.P25, 2) + " - " + Fixed(c.Stats.P75, 2)) << std::setw(9)
        << Fixed(1000.0 / c.Stats.Median, 1) << std::setw(8) << Fixed(c.Ratio, 2)
        << std::setw(10) << Fixed(c.CpuMedian, 1) << std::setw(10) << Fixed(c.CpuRatio, 2)
        << "\n";
  }
}

void PrintTargets(std::ostream& out, const std::vector<IceBench::Target>& targets)
{
  out << "\n== Targets (ratio to plain VTK of the same scene)\n";
  for (const IceBench::Target& t : targets)
  {
    out << "   " << std::left << std::setw(56) << t.Name << std::setw(14) << t.Limit
        << std::setw(14) << TargetValue(t) << TargetVerdict(t) << "\n";
  }
}

const char* MaterialName(Material m)
{
  switch (m)
  {
    case Material::Plain:
      return "plain";
    case Material::OneSided:
      return "one-sided";
    case Material::TwoSided:
      return "two-sided";
    case Material::CracksAir:
      return "cracks+air";
  }
  return "";
}

std::string Csv(const std::vector<Group>& groups, const Machine& machine)
{
  std::ostringstream out;
  out << "group,object,triangles,scene,coverage,configuration,material,cracks,air_planes,"
         "cube_map,update_mode,face_size,faces_per_frame,culling,moving,frames,median_ms,p25_ms,"
         "p75_ms,min_ms,max_ms,mean_ms,fps,baseline_median_ms,ratio,cpu_median_ms,cpu_ratio,"
         "cube_faces_per_frame,"
         "renderer,multisamples\n";
  const char* modes[3] = { "every-frame", "on-change", "manual" };
  for (const Group& g : groups)
  {
    for (const Configuration& c : g.Configurations)
    {
      out << g.Id << "," << g.Object << "," << g.Triangles << ","
          << (g.Landscape ? "landscape" : "static") << "," << Fixed(g.MeasuredCoverage, 4) << ",\""
          << c.Label << "\"," << MaterialName(c.Ice) << "," << c.Cracks << "," << c.AirPlanes << ","
          << (c.CubeMap ? 1 : 0) << "," << (c.CubeMap ? modes[c.UpdateMode] : "") << ","
          << (c.CubeMap ? std::to_string(c.FaceSize) : "") << ","
          << (c.CubeMap ? std::to_string(c.FacesPerFrame) : "") << ","
          << (c.CubeMap ? (c.Culling ? "1" : "0") : "") << "," << (c.Moving ? 1 : 0) << ","
          << c.Times.size() << "," << Fixed(c.Stats.Median, 3) << "," << Fixed(c.Stats.P25, 3)
          << "," << Fixed(c.Stats.P75, 3) << "," << Fixed(c.Stats.Min, 3) << ","
          << Fixed(c.Stats.Max, 3) << "," << Fixed(c.Stats.Mean, 3) << ","
          << Fixed(1000.0 / c.Stats.Median, 2) << "," << Fixed(g.Configurations[0].Stats.Median, 3)
          << "," << Fixed(c.Ratio, 4) << "," << Fixed(c.CpuMedian, 3) << ","
          << Fixed(c.CpuRatio, 4) << "," << Fixed(c.CubeFacesPerFrame, 3) << ",\""
          << machine.Renderer << "\"," << machine.MultiSamples << "\n";
    }
  }
  return out.str();
}

std::string Markdown(const std::vector<Group>& groups,
  const std::vector<IceBench::Target>& targets, const Machine& machine, int frames)
{
  std::ostringstream out;
  out << "| machine | |\n|---|---|\n";
  out << "| renderer | " << machine.Renderer << " (OpenGL " << machine.GLVersion << ") |\n";
  out << "| CPU | " << machine.CPU << ", " << machine.Threads << " threads |\n";
  out << "| back end | " << machine.Backend << " |\n";
  out << "| VTK | " << machine.VTK << " |\n";
  out << "| window | " << Width << "x" << Height << ", multisampling " << machine.MultiSamples
      << (machine.MultiSamples > 0 ? " samples" : " (off)") << " |\n";
  out << "| frames | " << Width << "x" << Height << " offscreen, " << frames
      << " timed frames per configuration (fewer for frames over 200 ms: see the CSV), glFinish "
         "after each |\n\n";
  out << "| target | limit | measured | |\n|---|---|---|---|\n";
  for (const IceBench::Target& t : targets)
  {
    out << "| " << t.Name << " | " << t.Limit << " | " << TargetValue(t) << " | "
        << TargetVerdict(t) << " |\n";
  }
  for (const Group& g : groups)
  {
    out << "\n**" << g.Title << "** (" << g.Triangles << " triangles, object covers "
        << CoverageText(g) << " of the window)\n\n";
    out << "| configuration | median ms | IQR ms | min - max ms | fps | ratio | CPU ms | CPU ratio "
           "|\n";
    out << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Configuration& c : g.Configurations)
    {
      out << "| " << c.Label << " | " << Fixed(c.Stats.Median, 2) << " | " << Fixed(c.Stats.P25, 2)
          << " - " << Fixed(c.Stats.P75, 2) << " | " << Fixed(c.Stats.Min, 2) << " - "
          << Fixed(c.Stats.Max, 2) << " | " << Fixed(1000.0 / c.Stats.Median, 1) << " | "
          << Fixed(c.Ratio, 2) << " | " << Fixed(c.CpuMedian, 1) << " | " << Fixed(c.CpuRatio, 2)
          << " |\n";
    }
  }
  return out.str();
}
}

int main(int argc, char* argv[])
{
  Options options;
  const int parsed = Parse(argc, argv, options);
  if (parsed >= 0)
  {
    return parsed;
  }
  IceOutputFile::RemoveTemporaryOnSignals();
  // Checked before the run, without creating anything: the files are written only at the end,
  // each whole or not at all (IceOutputFile.h).
  for (const std::string& path : { options.Csv, options.Plot, options.Markdown })
  {
    const std::string problem = path.empty() ? path : IceOutputFile::CheckWritable(path);
    if (!problem.empty())
    {
      return Fail(problem, 1);
    }
  }

  Schedule schedule;
  if (options.Quick)
  {
    schedule.WarmUp = 2;
    schedule.Rounds = 2;
    schedule.PerRound = 2;
  }
  else
  {
    schedule.TurnBudget = 800.0;
  }
  if (options.Frames > 0)
  {
    schedule.PerRound = std::min(options.Frames, options.Quick ? 2 : 4);
    schedule.Rounds = (options.Frames + schedule.PerRound - 1) / schedule.PerRound;
  }
  const int frames = schedule.Rounds * schedule.PerRound;

  std::vector<Group> groups;
  for (Group& g : DefineGroups())
  {
    if ((options.Quick && !g.Quick) ||
      (!options.Only.empty() && g.Id.find(options.Only) == std::string::npos))
    {
      continue;
    }
    if (options.Quick)
    {
      Shorten(g);
    }
    groups.push_back(g);
  }
  if (groups.empty())
  {
    return Fail("no group matches --only '" + options.Only + "'", 2);
  }

  const std::string backendError = IceHeadless::Install(options.Backend);
  if (!backendError.empty())
  {
    return Fail(backendError, 1);
  }

  std::string error;
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  if (!environment)
  {
    return Fail(error, 1);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(Width, Height);
  window->SetOffScreenRendering(1);
  window->SetWindowName("ice-bench");
  if (options.MultiSamples >= 0)
  {
    window->SetMultiSamples(options.MultiSamples);
  }

  Machine machine;
  machine.Backend = IceHeadless::InstalledDescription();
  machine.CPU = CpuModel();
  machine.Threads = std::thread::hardware_concurrency();
  machine.VTK = vtkVersion::GetVTKVersion();

  const auto started = std::chrono::steady_clock::now();
  std::map<std::string, vtkSmartPointer<vtkPolyData>> objects;
  std::map<std::pair<std::string, double>, std::pair<double, double>> calibrated;
  for (Group& g : groups)
  {
    vtkSmartPointer<vtkPolyData>& object = objects[g.Object];
    if (!object)
    {
      object = MakeObject(g.Object, error);
      if (!object)
      {
        return Fail(error, 1);
      }
    }
    g.Triangles = object->GetNumberOfPolys() + object->GetNumberOfStrips();
    auto key = std::make_pair(g.Object, g.Coverage);
    if (!calibrated.count(key))
    {
      double achieved = 0.0;
      const double distance = Calibrate(window, object, g.Coverage, achieved);
      calibrated[key] = std::make_pair(distance, achieved);
    }
    g.CameraDistance = calibrated[key].first;
    g.MeasuredCoverage = calibrated[key].second;
    if (machine.Renderer.empty())
    {
      window->MakeCurrent();
      machine.Renderer = GLString(GL_RENDERER);
      machine.MultiSamples = window->GetMultiSamples();
      machine.GLVersion = GLString(GL_VERSION);
      std::cout << "ice-bench: " << machine.Renderer << ", " << machine.CPU << " ("
                << machine.Threads << " threads), " << machine.Backend << "\n"
                << "ice-bench: " << Width << "x" << Height << ", " << frames
                << " timed frames per configuration (" << schedule.Rounds << " rounds of "
                << schedule.PerRound
                << (schedule.TurnBudget > 0.0 ? "; fewer for frames over 200 ms" : "")
                << "), multisamples " << window->GetMultiSamples() << "\n";
    }

    const auto groupStarted = std::chrono::steady_clock::now();
    std::vector<Scene> scenes;
    for (Configuration& c : g.Configurations)
    {
      Scene scene = BuildScene(g, c, object, environment);
      IceScene::PlaceCamera(scene.Renderer, g.CameraDistance);
      scene.Renderer->SetDraw(0);
      window->AddRenderer(scene.Renderer);
      scenes.push_back(scene);
    }
    MeasureGroup(g, window, scenes, schedule);
    for (Scene& scene : scenes)
    {
      scene.Renderer->ReleaseGraphicsResources(window);
      window->RemoveRenderer(scene.Renderer);
    }
    g.Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - groupStarted).count();
    PrintGroup(std::cout, g);
    std::cout.flush();
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const std::vector<IceBench::Target> targets = EvaluateTargets(groups);
  PrintTargets(std::cout, targets);
  std::cout << "\nice-bench: " << groups.size() << " groups in " << Fixed(seconds, 1) << " s\n";

  if (!options.Csv.empty())
  {
    const std::string problem = IceOutputFile::Write(options.Csv, Csv(groups, machine));
    if (!problem.empty())
    {
      return Fail(problem, 1);
    }
    std::cout << "ice-bench: wrote " << options.Csv << "\n";
  }
  if (!options.Markdown.empty())
  {
    const std::string problem =
      IceOutputFile::Write(options.Markdown, Markdown(groups, targets, machine, frames));
    if (!problem.empty())
    {
      return Fail(problem, 1);
    }
    std::cout << "ice-bench: wrote " << options.Markdown << "\n";
  }
  if (!options.Plot.empty())
  {
    const std::string plotError = IceBench::WritePlot(groups, options.Plot,
      machine.Renderer + ", " + machine.CPU + ", " + std::to_string(machine.Threads) +
        " threads, multisampling " + std::to_string(machine.MultiSamples));
    if (!plotError.empty())
    {
      return Fail(plotError, 1);
    }
    std::cout << "ice-bench: wrote " << options.Plot << "\n";
  }
  // The tables went to standard output, a file too (ice-bench > run.txt on a full disk).
  return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
}
