// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Shared helpers for the VTK Ice C++ tests: pixel capture, statistics, strict baseline
// comparison and error capture.
#ifndef IceTestUtilities_h
#define IceTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include "vtkIceOpticsReference.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkIceCubeMapSource;
class vtkActor;
class vtkIceMapper;
class vtkIcePass;
class vtkObject;
class vtkRenderer;
class vtkRenderWindow;
class vtkTexture;

namespace IceTest
{
// An RGB image read back from a render window; row 0 is the bottom row, as in VTK.
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> RGB;
  const unsigned char* At(int x, int y) const { return &this->RGB[3 * (y * this->Width + x)]; }
};

Image Capture(vtkRenderWindow* window);
// A PNG file as an Image (empty when it cannot be read), and an Image into one.
Image ReadPNG(const std::string& path);
void WritePNG(const Image& image, const std::string& path);

// Prints "ok   WHAT" or "FAIL WHAT" and returns `condition`: the tests' one line per check.
bool Expect(bool condition, const std::string& what);

// A test of several behaviours, one per ctest test: runs the case named by `--case NAME` in
// argv, or every case in turn without it. EXIT_SUCCESS when all run passed; an unknown name fails.
using Cases = std::vector<std::pair<std::string, std::function<bool()>>>;
int RunCases(const char* test, int argc, char* argv[], const Cases& cases);

// Largest channel difference of two pixels, in 0..255.
int PixelDifference(const unsigned char* a, const unsigned char* b);

// Pixels of two images of the same size whose PixelDifference exceeds `threshold`.
size_t CountDiffering(const Image& a, const Image& b, int threshold);

struct Stats
{
  double Mean = 0.0;
  double P99 = 0.0;
  double Max = 0.0;
  size_t Count = 0;
};
Stats Summarize(std::vector<double> values);

// The image regression test of VTK (vtkRegressionTestImage) followed by a strict numeric
// comparison with the same baseline: mean channel difference <= 1/255 and at most 0.2 % of pixels
// off by more than 16/255. Returns true when both pass.
bool CheckImage(int argc, char* argv[], vtkRenderWindow* window);

// Turns off cracks, air and bumps: the paper's optics alone, as the pixel references compute them.
void UseCleanOptics(vtkIceMapper* mapper);

// A cube-map texture from vtkIceCubeMapSource.
vtkSmartPointer<vtkTexture> MakeCubeMap(int pattern, int faceSize);

// The sky (vtkIceCubeMapSource::Sky) as `renderer`'s environment texture and its skybox.
void AddSky(vtkRenderer* renderer, int faceSize);

// The ray through the centre of window pixel (x, y) (display coordinates) of `renderer`, in world
// space.
void PixelRay(vtkRenderer* renderer, int x, int y, double origin[3], double direction[3]);
// The ray through display point (x, y) (pixel x's centre is x + 0.5).
void PixelRay(vtkRenderer* renderer, double x, double y, double origin[3], double direction[3]);

// Distances along the unit `direction` to the near and far intersections with the sphere; false
// when the ray misses it or the sphere is behind.
bool IntersectSphere(const double origin[3], const double direction[3], const double center[3],
  double radius, double& tNear, double& tFar);

// Window pixels of `renderer`'s viewport whose ray hits the sphere with hits on all pixels within
// `margin` too (so silhouette pixels are excluded). Indexed y * windowWidth + x.
std::vector<bool> SphereInterior(
  vtkRenderer* renderer, const double center[3], double radius, int margin);

// The environment's colour (components in [0, 1]) of a world direction. A NaN component marks a
// direction whose colour is ambiguous (for instance on an edge): pixels that need it are skipped.
using Environment = std::function<glm::dvec3(const glm::dvec3&)>;
Environment PatternEnvironment(const vtkIceCubeMapSource* source);

// Compares every interior pixel (margin 3) of an ice sphere in `renderer` with the GLM reference
// of the ice optics, sampling `environment` analytically. Two-sided uses the sphere's analytic
// back normal at the far intersection. Differences are the largest channel error in 0..255.
Stats CompareSphereWithReference(vtkRenderer* renderer, const Image& image, const double center[3],
  double radius, const vtkIceOpticsReference::Material& material, const Environment& environment,
  bool twoSided);

// Prints the figures and checks the reference bounds of the foundation issue: at least
// `minimumPixels` compared, mean <= 2/255, p99 <= 8/255.
bool ReportReference(const std::string& name, const Stats& stats, size_t minimumPixels);

// The invisibility check of the ice optics against vtkSkybox's cube-map convention: an ice sphere
// (radius 1 at the origin) in front of a skybox of `environment` (also the renderer's environment
// texture), in a 300x300 window, rendered without ice (Background), with RefractionRatio 1 and
// FresnelPower 1e6 (Invisible: difference from the background over the sphere's interior) and
// with the default ice (Visible). Differences are the largest channel error in 0..255.
struct Invisibility
{
  Image Background;
  Stats Invisible;
  Stats Visible;
};
Invisibility MeasureInvisibility(vtkTexture* environment);
// The same with a 2D equirectangular panorama as the environment, behind a vtkSkybox of sphere
// projection oriented as ParaView orients it (FloorRight (0, 0, 1)), gamma-corrected or not.
Invisibility MeasurePanoramaInvisibility(vtkTexture* panorama, bool gammaCorrect = false);

// Prints the figures and checks the bounds: over 20 000 interior pixels, invisible ice within
// mean 1/255 and p99 4/255 of the background, default ice at least 5/255 off on average.
bool ReportInvisibility(const std::string& name, const Invisibility& result);

// The ice block (clean optics) in a sky environment on black, with vtkIcePass, 240 x 240: the
// scene of the crack, air and bump tests.
struct BlockScene
{
  BlockScene();
  ~BlockScene();
  // Renders and reads back (rendering again once more, as Capture does).
  Image Render();
  vtkSmartPointer<vtkIceMapper> Mapper;
  vtkSmartPointer<vtkActor> Ice;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkIcePass> Pass;
  vtkSmartPointer<vtkRenderWindow> Window;
};

// An ice sphere (radius 1 at the origin, 128 segments, clean optics) that every view ray passes
// straight through (IndexOfRefraction 1, no reflection), before a sky skybox, with vtkIcePass,
// 300 x 300: the scene that holds the effects along the ray's chord against their references.
// Background is the skybox alone; Interior the pixels at least 3 px inside the silhouette.
struct ClearSphereScene
{
  ClearSphereScene();
  ~ClearSphereScene();
  Image Render();
  // The colour a pixel should have (0-255 per channel) when its ray enters the sphere at `entry`
  // along the unit `direction` and travels `chord` inside it.
  using Expected = std::function<glm::dvec3(
    int x, int y, const glm::dvec3& entry, const glm::dvec3& direction, double chord)>;
  // |image - expected| (the largest channel) over the interior pixels.
  Stats CompareAlongChords(const Image& image, const Expected& expected);
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkIceMapper> Mapper;
  vtkSmartPointer<vtkActor> Ice;
  vtkSmartPointer<vtkIcePass> Pass;
  vtkSmartPointer<vtkRenderWindow> Window;
  double Bounds[6]; // of the sphere's polygons
  std::vector<bool> Interior;
  Image Background;
};

// Records the error and warning messages an object emits (and keeps them off the console).
class MessageRecorder : public vtkCommand
{
public:
  static MessageRecorder* New() { return new MessageRecorder; }
  void Execute(vtkObject*, unsigned long event, void* data) override;
  void Watch(vtkObject* object);
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};
}

#endif
