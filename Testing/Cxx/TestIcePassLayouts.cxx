// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Two-sided ice stays correct (GLM reference, per pixel) when the window is resized several times,
// with two ice actors in one renderer, and with two renderers (viewports) in one window. The
// back-face normal texture must follow the viewport size each time.
#include "IceTestUtilities.h"
#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <iostream>
#include <string>

namespace
{
struct Ice
{
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Actor;
  double Center[3];

  Ice(vtkRenderer* renderer, double x, double y)
    : Center{ x, y, 0.0 }
  {
    this->Sphere->SetCenter(this->Center);
    this->Sphere->SetRadius(1.0);
    this->Sphere->SetThetaResolution(200);
    this->Sphere->SetPhiResolution(200);
    this->Mapper->SetInputConnection(this->Sphere->GetOutputPort());
    IceTest::UseCleanOptics(this->Mapper);
    this->Actor->SetMapper(this->Mapper);
    renderer->AddActor(this->Actor);
  }
};

struct Scene
{
  vtkNew<vtkIceCubeMapSource> Pattern;
  vtkNew<vtkTexture> Environment;
  Scene()
  {
    this->Pattern->SetPatternToDirectionTest();
    this->Pattern->ConfigureTexture(this->Environment);
  }
  void Setup(vtkRenderer* renderer, vtkIcePass* pass, double x, double z)
  {
    renderer->SetEnvironmentTexture(this->Environment);
    renderer->SetPass(pass);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(x, 0.0, 0.0);
    camera->SetPosition(x + 0.6, 0.8, z);
  }
};

bool Check(const std::string& name, vtkRenderer* renderer, const IceTest::Image& image,
  const Ice& ice, size_t minimumPixels)
{
  const vtkIceOpticsReference::Material material;
  vtkNew<vtkIceCubeMapSource> pattern;
  pattern->SetPatternToDirectionTest();
  return IceTest::ReportReference(name,
    IceTest::CompareSphereWithReference(
      renderer, image, ice.Center, 1.0, material, IceTest::PatternEnvironment(pattern), true),
    minimumPixels);
}

bool TextureFollows(vtkIcePass* pass, vtkRenderer* renderer)
{
  vtkTextureObject* texture = pass->GetBackfaceNormalPass()->GetNormalTexture();
  const int* size = renderer->GetSize();
  const bool ok = texture && static_cast<int>(texture->GetWidth()) == size[0] &&
    static_cast<int>(texture->GetHeight()) == size[1];
  std::cout << (ok ? "ok   " : "FAIL ") << "back-face normal texture "
            << (texture ? texture->GetWidth() : 0) << "x" << (texture ? texture->GetHeight() : 0)
            << " for a viewport of " << size[0] << "x" << size[1] << "\n";
  return ok;
}

bool Resizes()
{
  Scene scene;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkIcePass> pass;
  Ice ice(renderer, 0.0, 0.0);
  scene.Setup(renderer, pass, 0.0, 4.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  bool ok = true;
  const int sizes[][2] = { { 300, 300 }, { 211, 157 }, { 420, 260 }, { 160, 240 }, { 300, 300 } };
  for (const auto& size : sizes)
  {
    window->SetSize(size[0], size[1]);
    renderer->ResetCameraClippingRange();
    window->Render();
    const std::string name =
      "resized to " + std::to_string(size[0]) + "x" + std::to_string(size[1]);
    ok = TextureFollows(pass, renderer) && ok;
    ok = Check(name, renderer, IceTest::Capture(window), ice, 3000) && ok;
  }
  return ok;
}

bool TwoActors()
{
  Scene scene;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkIcePass> pass;
  Ice left(renderer, -1.4, 0.0);
  Ice right(renderer, 1.4, 0.2);
  scene.Setup(renderer, pass, 0.0, 7.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 240);
  window->AddRenderer(renderer);
  renderer->ResetCameraClippingRange();
  window->Render();
  const IceTest::Image image = IceTest::Capture(window);
  bool ok = pass->GetNumberOfIceProps() == 2;
  ok = Check("two actors, left", renderer, image, left, 5000) && ok;
  ok = Check("two actors, right", renderer, image, right, 5000) && ok;
  return ok;
}

bool TwoViewports()
{
  Scene scene;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(480, 240);
  vtkNew<vtkRenderer> left;
  vtkNew<vtkRenderer> right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkNew<vtkIcePass> leftPass;
  vtkNew<vtkIcePass> rightPass;
  Ice leftIce(left, 0.0, 0.0);
  Ice rightIce(right, 0.5, -0.3);
  scene.Setup(left, leftPass, 0.0, 4.0);
  scene.Setup(right, rightPass, 0.5, 3.5);
  window->AddRenderer(left);
  window->AddRenderer(right);
  left->ResetCameraClippingRange();
  right->ResetCameraClippingRange();
  window->Render();
  const IceTest::Image image = IceTest::Capture(window);
  bool ok = TextureFollows(leftPass, left);
  ok = TextureFollows(rightPass, right) && ok;
  ok = Check("left viewport", left, image, leftIce, 5000) && ok;
  ok = Check("right viewport", right, image, rightIce, 5000) && ok;
  return ok;
}
}

int TestIcePassLayouts(int, char*[])
{
  bool ok = Resizes();
  ok = TwoActors() && ok;
  ok = TwoViewports() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
