// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench: the measured configurations and their results, shared by the measuring program and
// the plot (IceBenchPlot.cxx), and the program's parts, one job a file: IceBenchOptions.cxx,
// IceBenchGroups.cxx, IceBenchScene.cxx (IceBenchScene.h), IceBenchMeasure.cxx,
// IceBenchMachine.cxx, IceBenchTargets.cxx, IceBenchReport.cxx, IceBenchTree.cxx and main in
// IceBench.cxx.
#ifndef IceBench_h
#define IceBench_h

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderWindow;
class vtkTexture;

namespace IceBench
{
// The window every configuration is timed in.
constexpr int Width = 1024;
constexpr int Height = 768;

// The GPU-timed steps of vtkIcePass's frame (vtkIcePass::Steps, in that order) and their names
// in the CSV (gpu_NAME_ms) and the tables.
constexpr int Steps = 5;
const std::array<const char*, Steps> StepNames = { "cube_map", "depth_interval", "back_faces",
  "scene", "interior" };

enum class Material
{
  Plain,    // plain VTK: a vtkPolyDataMapper, Phong shading (the baseline)
  OneSided, // vtkIceMapper without vtkIcePass
  TwoSided, // vtkIceMapper with vtkIcePass; Cracks cracks
  FullLook, // vtkIceMapper with vtkIcePass, 2 cracks, 19 air planes and the default bumps
  ExitPoint // as TwoSided, with TwoSidedExitPoint instead of the paper's blended normals
};

struct Statistics
{
  double Median = 0.0;
  double P25 = 0.0; // first quartile
  double P75 = 0.0; // third quartile
  double Min = 0.0;
  double Max = 0.0;
  double Mean = 0.0;
};

struct Configuration
{
  std::string Label;
  Material Ice = Material::Plain;
  int Cracks = 0;
  int AirPlanes = 0;                 // vtkIceProperty::NumberOfAirPlanes
  int Interior = 1;                  // vtkIceMapper::InteriorMethods (1: InteriorScreenSpace)
  bool PlainBackfaceCulling = false; // plain VTK with its property's BackfaceCulling on
  bool DrawEveryFace = false;        // vtkIceMapper::CullHiddenBackfaces off
  bool CubeMap = false;
  int UpdateMode = 0; // vtkIceCubeMapPass::UpdateModes
  int FaceSize = 512;
  int FacesPerFrame = 6;
  bool Culling = true;
  bool Moving = false; // a ball circles the ice, moved before every frame
  int Bounces = 1;     // vtkIceMapper::MaxBounces (exit point)
  bool TraceAntiAliasing = true; // vtkIceMapper::TraceAntiAliasing
  // The ice-cube look's parts (vtkIceProperty, exit point only): Roughness, MilkyCoreRadius
  // (with the preset's Milkiness 0.4), BubbleDensity.
  double Roughness = 0.0;
  double MilkyCore = 0.0;
  double Bubbles = 0.0;

  // Results.
  std::vector<double> Times;    // wall-clock milliseconds per timed frame
  std::vector<double> CpuTimes; // CPU milliseconds of the process (all threads) per timed frame
  Statistics Stats;
  double CpuMedian = 0.0;
  double Ratio = 0.0;             // median / the group's plain VTK median
  double CpuRatio = 0.0;          // the same for CPU time: less sensitive to other load
  double CubeFacesPerFrame = 0.0; // measured over the timed frames
  // GPU milliseconds of each step of vtkIcePass (MeasureStepTimes) per timed frame where it was
  // measured (a frame's times arrive at the next frame), and their medians (-1: not measured).
  std::array<std::vector<double>, Steps> StepTimes;
  std::array<double, Steps> StepMedians = { -1.0, -1.0, -1.0, -1.0, -1.0 };
};

struct Group
{
  std::string Id;     // short key, e.g. "objects-teapot"
  std::string Title;  // for tables
  std::string Object; // sphere, block, teapot, or sphere-N (a UV sphere of about N triangles)
  bool Landscape = false;
  double Coverage = 0.2;                     // wanted fraction of the window covered by the object
  bool Quick = false;                        // part of --quick
  std::vector<Configuration> Configurations; // [0] is the plain VTK baseline

  // Filled in by the run.
  long long Triangles = 0;
  double MeasuredCoverage = 0.0;
  double CameraDistance = 0.0;
  double Seconds = 0.0; // building, warming up and timing the group
};

// The ratio a target compares and whether it is met.
struct Target
{
  std::string Name;
  std::string Limit; // as the issue states it, e.g. "<= 1.3x"
  double Value = 0.0;
  double Bound = 0.0;
  bool IsIncrease = false; // Value is a relative increase (0.15 = 15 %) rather than a ratio
  bool Met = false;
  bool Measured = false;
};

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

// IceBenchTree.cxx
// Times vtkIceTriangleBVH's build on a few objects up to a million triangles and prints it with
// the tree's size (what the trace uploads).
void MeasureTrees(std::ostream& out);

// IceBenchOptions.cxx
// Prints "ice-bench: `message`" to standard error and returns `code`.
int Fail(const std::string& message, int code);
// Returns -1 when the arguments are fine, otherwise the exit code.
int Parse(int argc, char* argv[], Options& options);

// IceBenchGroups.cxx
// The groups of a run: all, or those of --quick (shortened), whose id contains `only`.
std::vector<Group> SelectGroups(bool quick, const std::string& only);

// An interior method (vtkIceMapper::InteriorMethods) in words ("screen space") and in the CSV
// ("screen-space").
std::string InteriorName(int interior);
std::string InteriorId(int interior);

// IceBenchMeasure.cxx
Schedule ChooseSchedule(bool quick, int frames);
// Builds a scene per configuration in `window`, times them interleaved, fills in the results and
// g.Seconds, and takes the scenes out of the window again.
void RunGroup(Group& g, vtkRenderWindow* window, vtkPolyData* object, vtkTexture* environment,
  const Schedule& schedule);

// IceBenchMachine.cxx
// What is known before a window renders: the back end, the CPU, VTK.
Machine DescribeMachine();
// The GL renderer, its version and the multisampling of `window`, which has rendered.
void DescribeContext(vtkRenderWindow* window, Machine& machine);

// IceBenchTargets.cxx (issue 8, item 4)
std::vector<Target> EvaluateTargets(const std::vector<Group>& groups);

// IceBenchReport.cxx
std::string Fixed(double value, int digits);
// The first lines of a run: the machine and the schedule.
void PrintRun(std::ostream& out, const Machine& machine, const Schedule& schedule);
void PrintGroup(std::ostream& out, const Group& g);
void PrintTargets(std::ostream& out, const std::vector<Target>& targets);
// Writes the CSV, Markdown and plot files that `options` names, each reported on standard output;
// empty on success, else the error.
std::string WriteFiles(const Options& options, const std::vector<Group>& groups,
  const std::vector<Target>& targets, const Machine& machine, int frames);

// IceBenchPlot.cxx
// Writes a PNG with the ratios and scaling curves of `groups`; empty on success, else the error.
std::string WritePlot(
  const std::vector<Group>& groups, const std::string& path, const std::string& subtitle);
}

#endif
