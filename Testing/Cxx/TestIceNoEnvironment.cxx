// Without an environment cube map the ice still renders, using the built-in sky, and the mapper
// warns exactly once (not every frame). A 2D environment texture is refused the same way.
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>

namespace
{
bool CheckCase(const char* name, vtkTexture* environment, const char* expected)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  const IceTest::Image image = IceTest::Capture(window);
  const unsigned char* middle = image.At(100, 100);
  const bool drawn = middle[0] + middle[1] + middle[2] > 150;
  const bool warnedOnce = recorder->Warnings.size() == 1 && recorder->Errors.empty() &&
    recorder->Warnings[0].find(expected) != std::string::npos;
  std::cout << name << ": " << recorder->Warnings.size() << " warning(s)"
            << (recorder->Warnings.empty() ? std::string() : ": " + recorder->Warnings[0])
            << "; centre pixel " << int(middle[0]) << "," << int(middle[1]) << "," << int(middle[2])
            << "\n";
  return drawn && warnedOnce;
}
}

int TestIceNoEnvironment(int, char*[])
{
  bool ok = CheckCase("no environment", nullptr, "has no environment texture");

  vtkNew<vtkImageData> flat;
  flat->SetDimensions(4, 4, 1);
  flat->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkNew<vtkTexture> texture2D;
  texture2D->SetInputData(flat);
  ok = CheckCase("2D environment", texture2D, "is not a cube map") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
