// Shared helpers for the VTK Ice C++ tests: pixel capture, statistics, strict baseline
// comparison and error capture.
#ifndef IceTestUtilities_h
#define IceTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

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

// Largest channel difference of two pixels, in 0..255.
int PixelDifference(const unsigned char* a, const unsigned char* b);

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

// A cube-map texture from vtkIceCubeMapSource.
vtkSmartPointer<vtkTexture> MakeCubeMap(int pattern, int faceSize);

// The ray through the centre of pixel (x, y) of `renderer` (perspective camera), in world space.
void PixelRay(vtkRenderer* renderer, int x, int y, double origin[3], double direction[3]);

// Distance along the unit `direction` to the first intersection with the sphere, or -1.
double IntersectSphere(
  const double origin[3], const double direction[3], const double center[3], double radius);

// For each pixel of a width x height image: does the ray through it hit the sphere with at least
// `margin` pixels of hits around it (so silhouette pixels are excluded)? Row 0 is the bottom row.
std::vector<bool> SphereInterior(
  vtkRenderer* renderer, const double center[3], double radius, int margin);

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
