// With RefractionRatio 1 and a huge FresnelPower the ice passes every view ray straight through,
// so it must be invisible against a skybox of the same cube map: this pins the mapper's cube-map
// lookup to vtkSkybox's convention. Default ice must, by contrast, be clearly visible.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>

namespace
{
IceTest::Stats Difference(const IceTest::Image& a, const IceTest::Image& b, const std::vector<bool>& mask)
{
  std::vector<double> differences;
  for (size_t p = 0; p < mask.size(); ++p)
  {
    if (mask[p])
    {
      differences.push_back(IceTest::PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]));
    }
  }
  return IceTest::Summarize(differences);
}
}

int TestIceInvisible(int, char*[])
{
  vtkSmartPointer<vtkTexture> environment =
    IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 256);
  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(environment);
  renderer->AddActor(skybox);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(128);
  sphere->SetPhiResolution(128);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  const double center[3] = { 0.0, 0.0, 0.0 };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(1.5, 0.4, 3.2);
  renderer->ResetCameraClippingRange();

  ice->VisibilityOff();
  window->Render();
  const IceTest::Image background = IceTest::Capture(window);
  const std::vector<bool> interior = IceTest::SphereInterior(renderer, center, 1.0, 3);

  ice->VisibilityOn();
  mapper->SetRefractionRatio(1.0);
  mapper->SetFresnelPower(1.0e6);
  window->Render();
  const IceTest::Stats invisible = Difference(background, IceTest::Capture(window), interior);

  mapper->SetRefractionRatio(1.0003 / 1.3091);
  mapper->SetFresnelPower(3.0);
  window->Render();
  const IceTest::Stats visible = Difference(background, IceTest::Capture(window), interior);

  std::cout << "eta 1: " << invisible.Count << " interior pixels differ from the skybox by mean "
            << invisible.Mean << "/255, p99 " << invisible.P99 << "/255, max " << invisible.Max
            << "/255\n";
  std::cout << "default ice: mean " << visible.Mean << "/255, p99 " << visible.P99 << "/255\n";
  const bool ok = invisible.Count > 20000 && invisible.Mean <= 1.0 && invisible.P99 <= 4.0 &&
    visible.Mean >= 5.0;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
