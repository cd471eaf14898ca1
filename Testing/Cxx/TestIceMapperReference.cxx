// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Renders ice spheres in a synthetic cube map and compares every interior pixel with the GLM
// reference (vtkIceOpticsReference.h) evaluated for that pixel's view ray: one-sided (eqs 2-4)
// without vtkIcePass, and two-sided (eq 1 with the sphere's analytic back normal) with it.
// Four placements: at the origin, moved/rotated/scaled by the actor, far from the origin (where
// VTK shifts and scales the vertex buffer), and at the origin seen in parallel projection.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <iostream>
#include <string>

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
  bool Parallel; // parallel projection: every eye vector is the direction of projection
};

enum class Mode
{
  OneSided,          // no vtkIcePass
  TwoSided,          // vtkIcePass, TwoSidedRefraction on
  TwoSidedSwitchOff, // vtkIcePass, TwoSidedRefraction off: must equal one-sided
};

bool CheckPlacement(const Placement& placement, Mode mode)
{
  vtkNew<vtkIceCubeMapSource> pattern;
  pattern->SetPatternToDirectionTest();
  pattern->SetFaceSize(256);
  vtkNew<vtkTexture> environment;
  pattern->ConfigureTexture(environment);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(
    placement.SourceCenter[0], placement.SourceCenter[1], placement.SourceCenter[2]);
  sphere->SetRadius(placement.SourceRadius);
  sphere->SetThetaResolution(256);
  sphere->SetPhiResolution(256);

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetTwoSidedRefraction(mode == Mode::TwoSided);
  IceTest::UseCleanOptics(mapper);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetPosition(placement.Position[0], placement.Position[1], placement.Position[2]);
  actor->SetScale(placement.Scale);
  actor->RotateY(placement.RotationY);

  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(environment);
  renderer->AddActor(actor);
  vtkNew<vtkIcePass> icePass;
  if (mode != Mode::OneSided)
  {
    renderer->SetPass(icePass);
  }
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
  camera->SetParallelProjection(placement.Parallel);
  camera->SetParallelScale(1.3 * radius);
  renderer->ResetCameraClippingRange();
  window->Render();

  const vtkIceOpticsReference::Material material;
  const IceTest::Stats stats =
    IceTest::CompareSphereWithReference(renderer, IceTest::Capture(window), center, radius,
      material, IceTest::PatternEnvironment(pattern), mode == Mode::TwoSided);
  const char* modeName = mode == Mode::OneSided ? "one-sided"
    : mode == Mode::TwoSided                    ? "two-sided"
                                                : "pass, two-sided off";
  return IceTest::ReportReference(std::string(placement.Name) + ", " + modeName, stats, 20000);
}
}

int TestIceMapperReference(int, char*[])
{
  const Placement placements[] = {
    { "origin", { 0, 0, 0 }, 1.0, { 0, 0, 0 }, 1.0, 0.0, false },
    { "actor-transform", { 0.1, 0, 0 }, 1.2, { 0.3, -0.2, 0.1 }, 0.7, 30.0, false },
    { "far-from-origin", { 800, -300, 50 }, 1.0, { 0, 0, 0 }, 1.0, 0.0, false },
    { "parallel-projection", { 0, 0, 0 }, 1.0, { 0, 0, 0 }, 1.0, 0.0, true },
  };
  bool ok = true;
  for (const Placement& placement : placements)
  {
    for (Mode mode : { Mode::OneSided, Mode::TwoSided, Mode::TwoSidedSwitchOff })
    {
      ok = CheckPlacement(placement, mode) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
