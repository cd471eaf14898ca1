// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceMapper::CullHiddenBackfaces: the ice skips its back faces only where none can be seen.
// - A closed block and sphere seen from outside are drawn culled, and the pictures (clean optics,
//   the screen-space and the paper's interior) equal those drawn with every face.
// - Every case where a back face can be seen, or where the input does not say which side is
//   outside, draws both sides: the camera inside the ice, a clipping plane, an open surface (the
//   teapot), faces turned inward, one face turned against its neighbours, a mirroring transform,
//   wireframe, edges shown, translucent; the user's own BackfaceCulling is VTK's to do. Where
//   culling would be wrong, the pictures with it on and off would differ: they are compared too.
// - The input's closure is checked from its second frame: an input modified every frame is not.
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkReverseSense.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <iostream>
#include <string>

namespace
{
using IceTest::Expect;

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  sphere->SetRadius(0.9);
  sphere->Update();
  return sphere->GetOutput();
}

// Pixels differing by more than 2 levels of 255, apart from those next to the (nearly) black
// background in `a` (a silhouette pixel where a front and a back face meet at one depth may go
// either way).
size_t CountDifferingInside(const IceTest::Image& a, const IceTest::Image& b, size_t& silhouette)
{
  size_t inside = 0;
  silhouette = 0;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      if (IceTest::PixelDifference(a.At(x, y), b.At(x, y)) <= 2)
      {
        continue;
      }
      bool edge = false;
      for (int j = std::max(0, y - 1); j <= std::min(a.Height - 1, y + 1); ++j)
      {
        for (int i = std::max(0, x - 1); i <= std::min(a.Width - 1, x + 1); ++i)
        {
          // Nearly black counts too: Mesa 26's multisampling leaves pixels barely covered by the
          // ice (7, 13, 25) between the background and the silhouette.
          const unsigned char* p = a.At(i, j);
          edge = edge || (p[0] <= 32 && p[1] <= 32 && p[2] <= 32);
        }
      }
      if (!edge && inside == 0)
      {
        // Where the first one lies says whether it is an edge the check above misses.
        std::cout << "     first differing pixel inside: (" << x << ", " << y << "), "
                  << IceTest::PixelDifference(a.At(x, y), b.At(x, y)) << "/255\n";
      }
      (edge ? silhouette : inside) += 1;
    }
  }
  return inside;
}

// Renders with culling on and off; checks whether the draw with it on culled, and that both
// pictures agree: no pixel inside the silhouette differs, at most 4 on it.
bool Check(IceTest::BlockScene& scene, bool expectCulled, const std::string& what)
{
  scene.Mapper->CullHiddenBackfacesOn();
  const IceTest::Image on = scene.Render();
  const bool culled = scene.Mapper->GetLastDrawCulledBackfaces();
  scene.Mapper->CullHiddenBackfacesOff();
  const IceTest::Image off = scene.Render();
  const bool offCulled = scene.Mapper->GetLastDrawCulledBackfaces();
  scene.Mapper->CullHiddenBackfacesOn();
  size_t silhouette = 0;
  const size_t differing = CountDifferingInside(on, off, silhouette);
  std::cout << "     " << what << ": " << differing << " pixels differ inside, " << silhouette
            << " on the silhouette\n";
  bool ok = Expect(culled == expectCulled, what + (expectCulled ? ": culled" : ": not culled"));
  ok = Expect(!offCulled, what + ": CullHiddenBackfaces off draws every face") && ok;
  return Expect(differing == 0 && silhouette <= 4,
           what + ": the same picture with culling on and off") &&
    ok;
}
}

int TestIceBackfaceCulling(int, char*[])
{
  IceTest::BlockScene scene;
  vtkIceMapper* mapper = scene.Mapper;
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  bool ok = Expect(mapper->GetCullHiddenBackfaces(), "on by default");

  // Closed surfaces seen from outside.
  ok = Check(scene, true, "block, clean optics") && ok;
  mapper->GetIceProperty()->SetNumberOfCracks(3);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(8);
  mapper->GetIceProperty()->SetBumpStrength(0.3);
  mapper->SetInteriorMethodToScreenSpace();
  ok = Check(scene, true, "block, cracks, air and bumps, screen space") && ok;
  mapper->SetInteriorMethodToPaperPasses();
  ok = Check(scene, true, "block, cracks, air and bumps, paper passes") && ok;
  IceTest::UseCleanOptics(mapper);
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  mapper->SetInputData(sphere);
  ok = Check(scene, true, "sphere") && ok;
  scene.Renderer->SetPass(nullptr);
  ok = Check(scene, true, "sphere without vtkIcePass (one-sided)") && ok;
  scene.Renderer->SetPass(scene.Pass);

  // The camera inside the sphere, looking out through its far side.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const double position[3] = { 2.5, 2.0, 4.0 };
  camera->SetPosition(0.1, 0.0, 0.2);
  camera->SetFocalPoint(1.0, 0.2, 0.0);
  scene.Renderer->ResetCameraClippingRange();
  ok = Check(scene, false, "camera inside the sphere") && ok;
  camera->SetPosition(position);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  scene.Renderer->ResetCameraClippingRange();

  // A clipping plane opens the sphere towards the camera.
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.3);
  plane->SetNormal(0.0, 0.0, -1.0);
  mapper->AddClippingPlane(plane);
  ok = Check(scene, false, "clipping plane") && ok;
  mapper->RemoveAllClippingPlanes();

  // Inputs that do not say which side is outside.
  vtkNew<vtkIceTeapotSource> teapot;
  teapot->Update();
  mapper->SetInputData(teapot->GetOutput());
  ok = Check(scene, false, "teapot (open edges)") && ok;
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(sphere);
  reverse->ReverseCellsOn();
  reverse->ReverseNormalsOn();
  reverse->Update();
  mapper->SetInputData(reverse->GetOutput());
  ok = Check(scene, false, "sphere with its faces turned inward") && ok;
  vtkNew<vtkPolyData> oneFlipped;
  oneFlipped->DeepCopy(sphere);
  oneFlipped->GetPolys()->ReverseCellAtId(40);
  mapper->SetInputData(oneFlipped);
  ok = Check(scene, false, "sphere with one face turned against its neighbours") && ok;
  mapper->SetInputData(sphere);
  ok = Check(scene, true, "sphere again") && ok;

  // The closure check waits for the second frame of an input: an input changed every frame
  // (an animation) is never checked and draws every face.
  vtkNew<vtkPolyData> moving;
  moving->DeepCopy(sphere);
  mapper->SetInputData(moving);
  scene.Window->Render();
  ok = Expect(
         !mapper->GetLastDrawCulledBackfaces(), "a new input: its first frame draws every face") &&
    ok;
  scene.Window->Render();
  ok = Expect(mapper->GetLastDrawCulledBackfaces(), "its second frame is culled") && ok;
  bool everCulled = false;
  for (int frame = 0; frame < 4; ++frame)
  {
    moving->GetPoints()->SetPoint(0, moving->GetPoints()->GetPoint(0));
    moving->GetPoints()->Modified();
    moving->Modified();
    scene.Window->Render();
    everCulled = everCulled || mapper->GetLastDrawCulledBackfaces();
  }
  ok = Expect(!everCulled, "an input modified every frame is never checked, never culled") && ok;
  mapper->SetInputData(sphere);

  // How the actor is drawn.
  scene.Ice->SetScale(-1.0, 1.0, 1.0);
  ok = Check(scene, false, "mirroring transform") && ok;
  scene.Ice->SetScale(1.0, 1.0, 1.0);
  scene.Ice->GetProperty()->SetRepresentationToWireframe();
  ok = Check(scene, false, "wireframe") && ok;
  scene.Ice->GetProperty()->SetRepresentationToSurface();
  scene.Ice->GetProperty()->EdgeVisibilityOn();
  scene.Ice->GetProperty()->SetEdgeColor(1.0, 0.3, 0.0);
  ok = Check(scene, false, "edges shown") && ok;
  scene.Ice->GetProperty()->EdgeVisibilityOff();
  scene.Ice->GetProperty()->SetOpacity(0.5);
  ok = Check(scene, false, "translucent actor") && ok;
  scene.Ice->GetProperty()->SetOpacity(1.0);
  scene.Ice->GetProperty()->BackfaceCullingOn();
  ok = Check(scene, false, "the property's own back-face culling") && ok;
  scene.Ice->GetProperty()->BackfaceCullingOff();
  ok = Check(scene, true, "sphere, all settings back") && ok;

  ok = Expect(recorder->Errors.empty(), "no errors") && ok;
  return ok ? 0 : 1;
}
