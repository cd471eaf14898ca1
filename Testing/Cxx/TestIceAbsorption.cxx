// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Absorption by the path in the ice (Beer-Lambert, AttenuationColor and AttenuationDistance)
// against the CPU reference: an ice sphere with IndexOfRefraction 1 and no reflection passes every
// view ray straight through, so each interior pixel must be the skybox behind it times the
// transmittance of the ray's chord through the sphere (vtkIceOpticsReference::Transmittance of
// EyePathLength, with the sphere's exact front and back depths), for both two-sided methods; and
// behind a skybox that shows its texture as linear light, gamma-corrected, the encoded colour
// behind times the transmittance's 1/2.2th power (the light itself keeps the transmittance).
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkCamera.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace
{
const glm::dvec3 AttenuationColor(0.3, 0.6, 0.9);
const double AttenuationDistance = 1.5;

// Every interior pixel: the background behind it times the transmittance of its chord, to the
// power `power` (1/2.2 where the background shows gamma-encoded light).
IceTest::Stats CompareWithReference(
  IceTest::ClearSphereScene& scene, const IceTest::Image& image, double power = 1.0)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  glm::dvec3 viewDirection;
  camera->GetDirectionOfProjection(&viewDirection[0]);
  glm::dvec3 cameraPosition;
  camera->GetPosition(&cameraPosition[0]);
  return scene.CompareAlongChords(
    image, [&](int x, int y, const glm::dvec3& entry, const glm::dvec3& e, double chord) {
      const double frontDepth = glm::dot(entry - cameraPosition, viewDirection);
      const double backDepth = glm::dot(entry + chord * e - cameraPosition, viewDirection);
      const glm::dvec3 transmittance = vtkIceOpticsReference::Transmittance(
        vtkIceOpticsReference::EyePathLength(e, viewDirection, frontDepth, backDepth),
        AttenuationColor, 1.0 / AttenuationDistance);
      const unsigned char* behind = scene.Background.At(x, y);
      return glm::dvec3(behind[0], behind[1], behind[2]) *
        glm::pow(transmittance, glm::dvec3(power));
    });
}
}

int TestIceAbsorption(int, char*[])
{
  IceTest::ClearSphereScene scene;
  scene.Mapper->GetIceProperty()->SetAttenuationColor(
    AttenuationColor[0], AttenuationColor[1], AttenuationColor[2]);
  scene.Mapper->GetIceProperty()->SetAttenuationDistance(AttenuationDistance);

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
    const IceTest::Stats stats = CompareWithReference(scene, scene.Render());
    ok = IceTest::ReportReference(
           std::string("absorption along the chord, ") + method.Name, stats, 20000) &&
      ok;
  }

  // The skybox gamma-corrects its texture (as ParaView's does, and ice-render's of an HDR
  // panorama): the ice's colours are gamma-encoded too.
  vtkSkybox* skybox = nullptr;
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = scene.Renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    skybox = skybox ? skybox : vtkSkybox::SafeDownCast(prop);
  }
  skybox->GammaCorrectOn();
  scene.Ice->VisibilityOff();
  scene.Background = scene.Render();
  scene.Ice->VisibilityOn();
  const IceTest::Stats stats = CompareWithReference(scene, scene.Render(), 1.0 / 2.2);
  ok = IceTest::ReportReference(
         "absorption along the chord, gamma-corrected skybox (exit point)", stats, 20000) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
