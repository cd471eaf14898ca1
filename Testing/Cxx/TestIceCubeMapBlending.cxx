// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A dynamic cube map keeps translucent geometry translucent, one behaviour per case: a black
// square at opacity 0.12 over a white plane.
// - first-frame: inside a vtkToneMappingPass (whose framebuffer makes the ice pass blend
//   translucent geometry plainly, as PyVista's tone mapping does) the square is as light in the
//   first frame with a cube map as without one. Rendering a face once left blending off for the
//   rest of the frame (the framebuffer's Start disables it) and drew the square black.
// - in-cube-map: seen through ice that neither bends nor reflects (eta 1), the square is as light
//   as an opaque square of the grey it blends to: the faces blend translucent geometry too (they
//   drew it opaque, black).
#include "IceTestUtilities.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceProperty.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkToneMappingPass.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <string>

namespace
{
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkIcePass> IcePass;
  vtkNew<vtkIceMapper> IceMapper;
  vtkNew<vtkActor> Ice;

  void AddPlane(double half, double z, double grey, double opacity)
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-half, -half, z);
    plane->SetPoint1(half, -half, z);
    plane->SetPoint2(-half, half, z);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(plane->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(grey, grey, grey);
    actor->GetProperty()->SetOpacity(opacity);
    actor->GetProperty()->LightingOff();
    this->Renderer->AddActor(actor);
  }

  // The ice sphere at `center`; the camera looks down at the planes from `eye`.
  Scene(const double center[3], double radius, const double eye[3], double grey = 0.0,
    double opacity = 0.12)
  {
    this->AddPlane(20.0, 0.0, 1.0, 1.0);
    this->AddPlane(0.5, 0.1, grey, opacity);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(center[0], center[1], center[2]);
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(64);
    sphere->SetPhiResolution(64);
    this->IceMapper->SetInputConnection(sphere->GetOutputPort());
    this->Ice->SetMapper(this->IceMapper);
    this->Renderer->AddActor(this->Ice);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(200, 200);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(eye[0], eye[1], eye[2]);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    this->Renderer->ResetCameraClippingRange();
  }
};

// Red of the middle pixel of the frame last rendered (IceTest::Capture renders another).
int Middle(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  const int* size = grab->GetOutput()->GetDimensions();
  return static_cast<int>(
    grab->GetOutput()->GetScalarComponentAsDouble(size[0] / 2, size[1] / 2, 0, 0));
}

int FirstFrame(bool cubeMap)
{
  const double center[3] = { 1.5, 1.5, 0.5 };
  const double eye[3] = { 0.0, 0.0, 6.0 };
  Scene scene(center, 0.3, eye);
  vtkNew<vtkIceCubeMapPass> cubeMapPass;
  if (cubeMap)
  {
    scene.IcePass->SetCubeMapPass(cubeMapPass);
  }
  vtkNew<vtkToneMappingPass> toneMapping;
  toneMapping->SetToneMappingType(vtkToneMappingPass::Clamp);
  toneMapping->SetDelegatePass(scene.IcePass);
  scene.Renderer->SetPass(toneMapping);
  scene.Window->Render();
  const int middle = Middle(scene.Window);
  scene.Renderer->SetPass(nullptr);
  toneMapping->ReleaseGraphicsResources(scene.Window);
  return middle;
}

bool FirstFrameCase()
{
  const int without = FirstFrame(false);
  const int with = FirstFrame(true);
  return IceTest::Expect(without > 200 && std::abs(with - without) <= 2,
    "the translucent square in the first frame: " + std::to_string(with) +
      " with a cube map, " + std::to_string(without) + " without");
}

// The middle of the sphere right above the square, seen from above through ice that neither
// bends nor reflects, the square at `opacity` with the grey `grey`.
int ThroughIce(double grey, double opacity)
{
  const double center[3] = { 0.0, 0.0, 1.5 };
  const double eye[3] = { 0.0, 0.0, 6.0 };
  Scene scene(center, 0.6, eye, grey, opacity);
  IceTest::UseCleanOptics(scene.IceMapper);
  scene.IceMapper->GetIceProperty()->SetRefractionRatio(1.0);
  scene.IceMapper->GetIceProperty()->SetFresnelPower(1.0e6);
  vtkNew<vtkIceCubeMapPass> cubeMapPass;
  cubeMapPass->SetFaceSize(256);
  scene.IcePass->SetCubeMapPass(cubeMapPass);
  scene.Renderer->SetPass(scene.IcePass);
  scene.Window->Render();
  const int middle = Middle(scene.Window);
  scene.Renderer->SetPass(nullptr);
  scene.IcePass->ReleaseGraphicsResources(scene.Window);
  return middle;
}

bool InCubeMapCase()
{
  const int translucent = ThroughIce(0.0, 0.12);
  const int opaque = ThroughIce(0.88, 1.0);
  return IceTest::Expect(opaque > 150 && std::abs(translucent - opaque) <= 3,
    "through clear ice, a black square at opacity 0.12: " + std::to_string(translucent) +
      "; an opaque square of its blended grey: " + std::to_string(opaque));
}
}

int TestIceCubeMapBlending(int argc, char* argv[])
{
  return IceTest::RunCases("TestIceCubeMapBlending", argc, argv,
    { { "first-frame", FirstFrameCase }, { "in-cube-map", InCubeMapCase } });
}
