// Absorption by the path in the ice (Beer-Lambert, AttenuationColor and AttenuationDistance)
// against the CPU reference: an ice sphere with IndexOfRefraction 1 and no reflection passes every
// view ray straight through, so each interior pixel must be the skybox behind it times the
// transmittance of the ray's chord through the sphere (vtkIceOpticsReference::Transmittance of
// EyePathLength, with the sphere's exact front and back depths), for both two-sided methods.
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkCamera.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace
{
const glm::dvec3 AttenuationColor(0.3, 0.6, 0.9);
const double AttenuationDistance = 1.5;

// Interior pixels of the unit sphere: |rendered - background x transmittance of the chord|.
IceTest::Stats CompareWithReference(vtkRenderer* renderer, const IceTest::Image& background,
  const IceTest::Image& image, const std::vector<bool>& interior)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  glm::dvec3 viewDirection;
  camera->GetDirectionOfProjection(&viewDirection[0]);
  glm::dvec3 cameraPosition;
  camera->GetPosition(&cameraPosition[0]);
  const double center[3] = { 0.0, 0.0, 0.0 };
  std::vector<double> differences;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      if (!interior[static_cast<size_t>(y) * image.Width + x])
      {
        continue;
      }
      double origin[3];
      double direction[3];
      double tNear;
      double tFar;
      IceTest::PixelRay(renderer, x, y, origin, direction);
      IceTest::IntersectSphere(origin, direction, center, 1.0, tNear, tFar);
      const glm::dvec3 e(direction[0], direction[1], direction[2]);
      const glm::dvec3 o(origin[0], origin[1], origin[2]);
      const double frontDepth = glm::dot(o + tNear * e - cameraPosition, viewDirection);
      const double backDepth = glm::dot(o + tFar * e - cameraPosition, viewDirection);
      const glm::dvec3 transmittance = vtkIceOpticsReference::Transmittance(
        vtkIceOpticsReference::EyePathLength(e, viewDirection, frontDepth, backDepth),
        AttenuationColor, 1.0 / AttenuationDistance);
      const unsigned char* behind = background.At(x, y);
      const unsigned char* rendered = image.At(x, y);
      double largest = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest, std::abs(rendered[c] - behind[c] * transmittance[c]));
      }
      differences.push_back(largest);
    }
  }
  return IceTest::Summarize(differences);
}
}

int TestIceAbsorption(int, char*[])
{
  IceTest::ClearSphereScene scene;
  scene.Mapper->SetAttenuationColor(AttenuationColor[0], AttenuationColor[1], AttenuationColor[2]);
  scene.Mapper->SetAttenuationDistance(AttenuationDistance);

  bool ok = true;
  const struct
  {
    int Method;
    const char* Name;
  } methods[] = { { vtkIceMapper::TwoSidedBlendedNormals, "blended normals" },
    { vtkIceMapper::TwoSidedExitPoint, "exit point" } };
  for (const auto& method : methods)
  {
    scene.Mapper->SetTwoSidedMethod(method.Method);
    const IceTest::Stats stats =
      CompareWithReference(scene.Renderer, scene.Background, scene.Render(), scene.Interior);
    ok = IceTest::ReportReference(
           std::string("absorption along the chord, ") + method.Name, stats, 20000) &&
      ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
