// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's scenes: the objects, a renderer per configuration (plain VTK or ice, with the
// landscape and a moving ball for the dynamic group) and the calibration of screen coverage.
#include "IceBenchScene.h"
#include "IceScene.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceProperty.h"

#include "vtkActor.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace
{
using IceBench::Height;
using IceBench::Width;

// The fraction of the window the white, unlit object covers with the camera at `distance`.
double Coverage(vtkRenderWindow* window, vtkRenderer* renderer, double distance)
{
  IceScene::PlaceCamera(renderer, distance);
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, Width - 1, Height - 1, 0, pixels);
  vtkIdType covered = 0;
  const vtkIdType n = pixels->GetNumberOfTuples();
  const int components = pixels->GetNumberOfComponents();
  for (vtkIdType i = 0; i < n; ++i)
  {
    covered += pixels->GetValue(i * components) > 127 ? 1 : 0;
  }
  return static_cast<double>(covered) / static_cast<double>(n);
}
}

vtkSmartPointer<vtkPolyData> IceBench::MakeObject(const std::string& object, std::string& error)
{
  static const std::map<std::string, std::pair<int, int>> spheres = { { "sphere-1k", { 32, 17 } },
    { "sphere-10k", { 100, 51 } }, { "sphere-100k", { 316, 160 } },
    { "sphere-1M", { 1000, 501 } } };
  auto found = spheres.find(object);
  if (found == spheres.end())
  {
    return IceScene::LoadModel(object, error);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(found->second.first);
  sphere->SetPhiResolution(found->second.second);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sphere->GetOutputPort());
  triangles->Update();
  vtkSmartPointer<vtkPolyData> output = triangles->GetOutput();
  return output;
}

IceBench::Scene IceBench::BuildScene(
  const Group& g, Configuration& c, vtkPolyData* object, vtkTexture* environment)
{
  Scene scene;
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkRenderer* renderer = scene.Renderer;
  IceScene::AddEnvironment(renderer, environment);
  if (g.Landscape)
  {
    const double ground = object->GetBounds()[2];
    IceScene::AddLandscape(renderer, ground);
    // A ball that circles the ice when the configuration moves it (dynamic scenes only).
    vtkNew<vtkSphereSource> ballShape;
    ballShape->SetRadius(0.3);
    ballShape->SetThetaResolution(24);
    ballShape->SetPhiResolution(12);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(ballShape->GetOutputPort());
    scene.Ball = vtkSmartPointer<vtkActor>::New();
    scene.Ball->SetMapper(ballMapper);
    scene.Ball->GetProperty()->SetColor(0.8, 0.15, 0.1);
    scene.Ball->SetPosition(-2.4, ground + 0.3, 0.0);
    renderer->AddActor(scene.Ball);
  }

  vtkNew<vtkActor> actor;
  if (c.Ice == Material::Plain)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(object);
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetInterpolationToPhong();
    property->SetColor(0.75, 0.85, 0.95);
    property->SetSpecular(0.5);
    property->SetSpecularPower(40.0);
    property->SetBackfaceCulling(c.PlainBackfaceCulling);
  }
  else
  {
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputData(object);
    // The paper's study: no bumps; cracks and air as configured (the full look: the default
    // bumps, 2 cracks and 19 air planes).
    if (c.Ice != Material::FullLook)
    {
      mapper->GetIceProperty()->SetBumpStrength(0.0);
    }
    mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
    mapper->SetCullHiddenBackfaces(!c.DrawEveryFace);
    mapper->SetInteriorMethod(c.Interior);
    actor->SetMapper(mapper);
    if (c.Ice == Material::ExitPoint)
    {
      mapper->SetTwoSidedMethodToExitPoint();
      mapper->SetMaxBounces(c.Bounces);
      mapper->SetTraceAntiAliasing(c.TraceAntiAliasing);
      vtkIceProperty* look = mapper->GetIceProperty();
      look->SetRoughness(c.Roughness);
      look->SetMilkyCoreRadius(c.MilkyCore);
      look->SetMilkiness(c.MilkyCore > 0.0 ? 0.4 : look->GetMilkiness());
      look->SetBubbleDensity(c.Bubbles);
    }
    if (c.Ice != Material::OneSided)
    {
      vtkNew<vtkIcePass> icePass;
      renderer->SetPass(icePass);
      mapper->GetIceProperty()->SetNumberOfCracks(c.Cracks);
      mapper->GetIceProperty()->SetNumberOfAirPlanes(c.AirPlanes);
      if (c.CubeMap)
      {
        scene.CubeMapPass = vtkSmartPointer<vtkIceCubeMapPass>::New();
        scene.CubeMapPass->SetUpdateMode(c.UpdateMode);
        scene.CubeMapPass->SetFaceSize(c.FaceSize);
        scene.CubeMapPass->SetFacesPerFrame(c.FacesPerFrame);
        scene.CubeMapPass->SetFrustumCulling(c.Culling);
        icePass->SetCubeMapPass(scene.CubeMapPass);
      }
    }
  }
  renderer->AddActor(actor);
  return scene;
}

void IceBench::MoveBall(vtkActor* ball)
{
  double* p = ball->GetPosition();
  const double angle = std::atan2(p[2], p[0]) + vtkMath::RadiansFromDegrees(3.0);
  ball->SetPosition(2.4 * std::cos(angle), p[1], 2.4 * std::sin(angle));
}

// Coverage falls as the camera backs away (outside the object). For "the whole screen" the
// farthest distance that still covers 99.5 % of it.
double IceBench::Calibrate(
  vtkRenderWindow* window, vtkPolyData* object, double wanted, double& achieved)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(object);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  renderer->AddActor(actor);
  window->AddRenderer(renderer);

  const double target = wanted >= 1.0 ? 0.995 : wanted;
  double far = 40.0;
  double near = far;
  double nearCoverage = Coverage(window, renderer, near);
  while (nearCoverage < target && near > 0.5)
  {
    far = near;
    near /= 1.5;
    nearCoverage = Coverage(window, renderer, near);
  }
  for (int i = 0; i < 14; ++i)
  {
    const double middle = std::sqrt(near * far);
    if (Coverage(window, renderer, middle) >= target)
    {
      near = middle;
    }
    else
    {
      far = middle;
    }
  }
  // For a fraction, whichever end is closer; for the whole screen, the end that covers it.
  const double farCoverage = Coverage(window, renderer, far);
  const double nearCov = Coverage(window, renderer, near);
  double distance = near;
  achieved = nearCov;
  if (wanted < 1.0 && std::abs(farCoverage - wanted) < std::abs(nearCov - wanted))
  {
    distance = far;
    achieved = farCoverage;
  }
  window->RemoveRenderer(renderer);
  return distance;
}
