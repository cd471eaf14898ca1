// ice-bench: the measured configurations and their results, shared by the measuring program
// (IceBench.cxx) and the plot (IceBenchPlot.cxx).
#ifndef IceBench_h
#define IceBench_h

#include <string>
#include <vector>

namespace IceBench
{
enum class Material
{
  Plain,    // plain VTK: a vtkPolyDataMapper, Phong shading (the baseline)
  OneSided, // vtkIceMapper without vtkIcePass
  TwoSided, // vtkIceMapper with vtkIcePass; Cracks cracks
  CracksAir // vtkIceMapper with vtkIcePass, 2 cracks and 19 air planes
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
  int AirPlanes = 0; // vtkIceMapper::NumberOfAirPlanes
  bool CubeMap = false;
  int UpdateMode = 0; // vtkIceCubeMapPass::UpdateModes
  int FaceSize = 512;
  int FacesPerFrame = 6;
  bool Culling = true;
  bool Moving = false; // a ball circles the ice, moved before every frame

  // Results.
  std::vector<double> Times;    // wall-clock milliseconds per timed frame
  std::vector<double> CpuTimes; // CPU milliseconds of the process (all threads) per timed frame
  Statistics Stats;
  double CpuMedian = 0.0;
  double Ratio = 0.0;             // median / the group's plain VTK median
  double CpuRatio = 0.0;          // the same for CPU time: less sensitive to other load
  double CubeFacesPerFrame = 0.0; // measured over the timed frames
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

// Writes a PNG with the ratios and scaling curves of `groups`; empty on success, else the error.
std::string WritePlot(
  const std::vector<Group>& groups, const std::string& path, const std::string& subtitle);
}

#endif
