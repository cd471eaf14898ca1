// Renders ice spheres in a synthetic cube map and compares every interior pixel with the GLM
// reference of eqs 2-4 (vtkIceOpticsReference.h) evaluated for that pixel's view ray.
// Three placements: at the origin, moved/rotated/scaled by the actor, and far from the origin
// (where VTK shifts and scales the vertex buffer).
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIceOpticsReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <cmath>
#include <iostream>

namespace
{
struct Placement
{
  const char* Name;
  double SourceCenter[3];
  double SourceRadius;
  double Position[3];
  double Scale;
  double RotationY;
};

bool CheckPlacement(const Placement& placement)
{
  vtkNew<vtkIceCubeMapSource> pattern;
  pattern->SetPatternToDirectionTest();

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(placement.SourceCenter[0], placement.SourceCenter[1], placement.SourceCenter[2]);
  sphere->SetRadius(placement.SourceRadius);
  sphere->SetThetaResolution(256);
  sphere->SetPhiResolution(256);

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetPosition(placement.Position[0], placement.Position[1], placement.Position[2]);
  actor->SetScale(placement.Scale);
  actor->RotateY(placement.RotationY);

  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 256));
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);

  double center[4] = { placement.SourceCenter[0], placement.SourceCenter[1],
    placement.SourceCenter[2], 1.0 };
  actor->GetMatrix()->MultiplyPoint(center, center);
  const double radius = placement.SourceRadius * placement.Scale;

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + 0.9, center[1] + 1.2, center[2] + 3.6 * radius);
  renderer->ResetCameraClippingRange();
  window->Render();

  const IceTest::Image image = IceTest::Capture(window);
  const std::vector<bool> interior = IceTest::SphereInterior(renderer, center, radius, 3);
  const vtkIceOpticsReference::Material material;
  auto environment = [&pattern](const glm::dvec3& d) {
    double rgb[3];
    const double dir[3] = { d.x, d.y, d.z };
    pattern->Evaluate(dir, rgb);
    return glm::dvec3(rgb[0], rgb[1], rgb[2]);
  };

  std::vector<double> differences;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      if (!interior[y * image.Width + x])
      {
        continue;
      }
      double origin[3];
      double direction[3];
      IceTest::PixelRay(renderer, x, y, origin, direction);
      const double t = IceTest::IntersectSphere(origin, direction, center, radius);
      const glm::dvec3 e(direction[0], direction[1], direction[2]);
      const glm::dvec3 hit = glm::dvec3(origin[0], origin[1], origin[2]) + t * e;
      const glm::dvec3 n = glm::normalize(hit - glm::dvec3(center[0], center[1], center[2]));
      const glm::dvec3 expected =
        255.0 * vtkIceOpticsReference::Shade(e, n, nullptr, material, environment);
      const unsigned char* pixel = image.At(x, y);
      double worst = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(pixel[c] - expected[c]));
      }
      differences.push_back(worst);
    }
  }
  const IceTest::Stats stats = IceTest::Summarize(differences);
  std::cout << placement.Name << ": " << stats.Count << " interior pixels, |rendered - reference| mean "
            << stats.Mean << "/255, p99 " << stats.P99 << "/255, max " << stats.Max << "/255\n";
  return stats.Count > 20000 && stats.Mean <= 2.0 && stats.P99 <= 8.0;
}
}

int TestIceMapperReference(int, char*[])
{
  const Placement placements[] = {
    { "origin", { 0, 0, 0 }, 1.0, { 0, 0, 0 }, 1.0, 0.0 },
    { "actor-transform", { 0.1, 0, 0 }, 1.2, { 0.3, -0.2, 0.1 }, 0.7, 30.0 },
    { "far-from-origin", { 800, -300, 50 }, 1.0, { 0, 0, 0 }, 1.0, 0.0 },
  };
  bool ok = true;
  for (const Placement& placement : placements)
  {
    ok = CheckPlacement(placement) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
