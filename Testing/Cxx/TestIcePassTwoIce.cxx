// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Several ice objects with their own parameters:
// - Two ice blocks side by side in one renderer, A left, B right. A has cracks and air, B has none:
// drawn in red (DebugCracksClipped), no crack pixel of A lies
//   outside A's silhouette (with one depth interval for all the ice, A's cracks showed on B), and
//   with its highlights and air every pixel outside A's silhouette equals the frame where A has
//   neither.
// - Two renderers in one window (left and right viewports), each with its own vtkIcePass: each
//   half equals the same half rendered with the other renderer removed.
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iostream>
#include <string>

namespace
{
using IceTest::Expect;

struct TwoIce
{
  TwoIce()
  {
    this->Environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 128);
    this->Renderer->SetEnvironmentTexture(this->Environment); // no skybox: black background
    for (int i = 0; i < 2; ++i)
    {
      vtkNew<vtkIceBlockSource> block;
      block->SetSeed(3 + i);
      this->Mappers[i] = vtkSmartPointer<vtkIceMapper>::New();
      this->Mappers[i]->SetInputConnection(block->GetOutputPort());
      IceTest::UseCleanOptics(this->Mappers[i]);
      this->Actors[i] = vtkSmartPointer<vtkActor>::New();
      this->Actors[i]->SetMapper(this->Mappers[i]);
      this->Renderer->AddActor(this->Actors[i]);
    }
    // Side by side at one depth, B close enough to lie partly in A's projected bounding box (to
    // which A's crack sheets are scissored) and within A's depths.
    this->Actors[0]->SetPosition(-0.5, 0.0, 0.0);
    this->Actors[1]->SetPosition(0.45, 0.1, 0.0);
    this->Actors[1]->RotateY(30.0);
    this->Renderer->SetPass(this->Pass);
    this->Window->SetSize(240, 160);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.6, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    this->Renderer->ResetCameraClippingRange();
  }
  IceTest::Image Render()
  {
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }
  vtkSmartPointer<vtkTexture> Environment;
  vtkSmartPointer<vtkIceMapper> Mappers[2];
  vtkSmartPointer<vtkActor> Actors[2];
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
};

bool IsRed(const unsigned char* p)
{
  return p[0] >= 250 && p[1] <= 5 && p[2] <= 5;
}

bool IsBlack(const unsigned char* p)
{
  return !p[0] && !p[1] && !p[2];
}

bool OneRenderer()
{
  TwoIce scene;
  scene.Actors[1]->VisibilityOff();
  const IceTest::Image silhouetteA = scene.Render();
  scene.Actors[0]->VisibilityOff();
  scene.Actors[1]->VisibilityOn();
  const IceTest::Image silhouetteB = scene.Render();
  scene.Actors[0]->VisibilityOn();
  const IceTest::Image clear = scene.Render();

  scene.Mappers[0]->GetIceProperty()->SetNumberOfCracks(6);
  scene.Mappers[0]->SetDebugView(vtkIceMapper::DebugCracksClipped);
  const IceTest::Image red = scene.Render();
  size_t inside = 0;
  size_t outside = 0;
  size_t onB = 0;
  size_t overlap = 0;
  for (int y = 0; y < red.Height; ++y)
  {
    for (int x = 0; x < red.Width; ++x)
    {
      const bool inA = !IsBlack(silhouetteA.At(x, y));
      const bool inB = !IsBlack(silhouetteB.At(x, y));
      overlap += inA && inB ? 1 : 0;
      if (IsRed(red.At(x, y)))
      {
        (inA ? inside : outside)++;
        onB += !inA && inB ? 1 : 0;
      }
    }
  }
  std::cout << "the two blocks overlap on " << overlap << " pixels\n";
  bool ok = Expect(inside > 1000 && outside == 0,
    "A's cracks in red: " + std::to_string(inside) + " pixels inside A's silhouette, " +
      std::to_string(outside) + " outside (" + std::to_string(onB) + " on B)");

  scene.Mappers[0]->SetDebugView(vtkIceMapper::DebugOff);
  scene.Mappers[0]->GetIceProperty()->SetNumberOfAirPlanes(8);
  const IceTest::Image full = scene.Render();
  size_t changedInA = 0;
  size_t changedOutside = 0;
  for (int y = 0; y < full.Height; ++y)
  {
    for (int x = 0; x < full.Width; ++x)
    {
      if (IceTest::PixelDifference(full.At(x, y), clear.At(x, y)) > 2)
      {
        (IsBlack(silhouetteA.At(x, y)) ? changedOutside : changedInA)++;
      }
    }
  }
  ok = Expect(changedInA > 1000 && changedOutside == 0,
         "A's cracks and air change " + std::to_string(changedInA) + " pixels of A and " +
           std::to_string(changedOutside) + " elsewhere (B without either)") &&
    ok;
  return ok;
}

bool TwoRenderers()
{
  vtkSmartPointer<vtkTexture> environment =
    IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 128);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(240, 120);
  window->SetOffScreenRendering(1);
  vtkSmartPointer<vtkRenderer> renderers[2];
  vtkSmartPointer<vtkIcePass> passes[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkIceBlockSource> block;
    block->SetSeed(5 + i);
    vtkNew<vtkIceMapper> mapper;
    mapper->SetInputConnection(block->GetOutputPort());
    mapper->GetIceProperty()->SetNumberOfCracks(i == 0 ? 4 : 0);
    mapper->GetIceProperty()->SetNumberOfAirPlanes(i == 0 ? 0 : 6);
    mapper->SetTwoSidedRefraction(i == 0);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderers[i] = vtkSmartPointer<vtkRenderer>::New();
    renderers[i]->SetEnvironmentTexture(environment);
    renderers[i]->AddActor(actor);
    renderers[i]->SetViewport(0.5 * i, 0.0, 0.5 * (i + 1), 1.0);
    passes[i] = vtkSmartPointer<vtkIcePass>::New();
    renderers[i]->SetPass(passes[i]);
    renderers[i]->GetActiveCamera()->SetPosition(0.4 * (1 - 2 * i), 0.5, 4.0);
    renderers[i]->ResetCameraClippingRange();
    window->AddRenderer(renderers[i]);
  }
  window->Render();
  const IceTest::Image both = IceTest::Capture(window);
  bool ok = true;
  for (int i = 0; i < 2; ++i)
  {
    window->RemoveRenderer(renderers[1 - i]);
    window->Render();
    const IceTest::Image alone = IceTest::Capture(window);
    window->AddRenderer(renderers[1 - i]);
    size_t differing = 0;
    size_t ice = 0;
    for (int y = 0; y < both.Height; ++y)
    {
      for (int x = 120 * i; x < 120 * (i + 1); ++x)
      {
        differing += IceTest::PixelDifference(both.At(x, y), alone.At(x, y)) > 0 ? 1 : 0;
        ice += IsBlack(alone.At(x, y)) ? 0 : 1;
      }
    }
    ok = Expect(ice > 1000 && differing == 0,
           std::string(i == 0 ? "left" : "right") + " renderer (" + std::to_string(ice) +
             " ice pixels): " + std::to_string(differing) +
             " pixels differ from it rendered without the other") &&
      ok;
  }
  return ok;
}
}

int TestIcePassTwoIce(int, char*[])
{
  bool ok = OneRenderer();
  ok = TwoRenderers() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
