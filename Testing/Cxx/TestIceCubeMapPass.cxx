// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceCubeMapPass: an ice sphere inside a room whose six walls have six colours, each wall in
// four quadrants of different brightness. Seen from the sphere's centre the walls fill the cube map
// face by face, so the GLM reference with "colour of the wall quadrant the direction points at"
// must match every interior pixel whose refracted and reflected directions are clear of the edges:
// a flipped or rotated face, the ice in its own cube map, or bad frustum culling would put wrong
// colours at those positions. Then: with eta 1 and no
// reflection the ice nearly vanishes in front of distant walls; and the update modes re-render
// exactly when they should (counted face renders).
#include "IceTestUtilities.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
const double WallColors[6][3] = {
  { 0.9, 0.1, 0.1 },  // +X
  { 0.1, 0.8, 0.2 },  // -X
  { 0.2, 0.3, 0.9 },  // +Y
  { 0.9, 0.85, 0.1 }, // -Y
  { 0.8, 0.2, 0.8 },  // +Z
  { 0.1, 0.8, 0.8 },  // -Z
};

// Brightness of quadrant (u > 0, v > 0) of a wall, u and v its axes (k + 1) % 3 and (k + 2) % 3.
double QuadrantShade(bool uPositive, bool vPositive)
{
  return 0.5 + 0.16 * ((uPositive ? 1 : 0) + (vPositive ? 2 : 0));
}

// The wall quadrant a direction from the room's centre hits; NaN within ~3 degrees of an edge
// between walls or quadrants.
glm::dvec3 WallColor(const glm::dvec3& direction)
{
  const glm::dvec3 d = glm::normalize(direction);
  const glm::dvec3 a = glm::abs(d);
  const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const int u = (k + 1) % 3;
  const int v = (k + 2) % 3;
  if (a[k] - std::max(a[u], a[v]) < 0.05 || a[u] < 0.05 || a[v] < 0.05)
  {
    return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
  }
  const double* c = WallColors[2 * k + (d[k] < 0.0 ? 1 : 0)];
  return QuadrantShade(d[u] > 0.0, d[v] > 0.0) * glm::dvec3(c[0], c[1], c[2]);
}

struct Room
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkIcePass> IcePass;
  vtkNew<vtkIceCubeMapPass> CubeMapPass;
  vtkNew<vtkIceMapper> IceMapper;
  vtkNew<vtkActor> Ice;
  vtkSmartPointer<vtkActor> Walls[6][4];
  double Center[3] = { 0.4, -0.2, 0.3 };

  explicit Room(double halfSize)
  {
    for (int face = 0; face < 6; ++face)
    {
      const int k = face / 2;
      const int u = (k + 1) % 3;
      const int v = (k + 2) % 3;
      for (int quadrant = 0; quadrant < 4; ++quadrant)
      {
        const bool uPositive = quadrant & 1;
        const bool vPositive = quadrant & 2;
        double origin[3] = { this->Center[0], this->Center[1], this->Center[2] };
        origin[k] += (face % 2 ? -1.0 : 1.0) * halfSize;
        origin[u] -= uPositive ? 0.0 : halfSize;
        origin[v] -= vPositive ? 0.0 : halfSize;
        double p1[3] = { origin[0], origin[1], origin[2] };
        double p2[3] = { origin[0], origin[1], origin[2] };
        p1[u] += halfSize;
        p2[v] += halfSize;
        vtkNew<vtkPlaneSource> plane;
        plane->SetOrigin(origin);
        plane->SetPoint1(p1);
        plane->SetPoint2(p2);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(plane->GetOutputPort());
        vtkSmartPointer<vtkActor>& wall = this->Walls[face][quadrant];
        wall = vtkSmartPointer<vtkActor>::New();
        wall->SetMapper(mapper);
        const double shade = QuadrantShade(uPositive, vPositive);
        wall->GetProperty()->SetColor(
          shade * WallColors[face][0], shade * WallColors[face][1], shade * WallColors[face][2]);
        wall->GetProperty()->LightingOff();
        this->Renderer->AddActor(wall);
      }
    }
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(this->Center);
    sphere->SetRadius(1.0);
    sphere->SetThetaResolution(200);
    sphere->SetPhiResolution(200);
    this->IceMapper->SetInputConnection(sphere->GetOutputPort());
    IceTest::UseCleanOptics(this->IceMapper);
    this->Ice->SetMapper(this->IceMapper);
    this->Renderer->AddActor(this->Ice);

    this->CubeMapPass->SetFaceSize(256);
    this->IcePass->SetCubeMapPass(this->CubeMapPass);
    this->Renderer->SetPass(this->IcePass);
    this->Window->SetSize(300, 300);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(this->Center);
    camera->SetPosition(this->Center[0] + 1.2, this->Center[1] + 1.5, this->Center[2] + 2.4);
    camera->SetViewAngle(50.0);
    this->Renderer->ResetCameraClippingRange();
  }
};

bool Positions(bool frustumCulling)
{
  Room room(5.0);
  room.CubeMapPass->SetFrustumCulling(frustumCulling);
  room.Window->Render();
  const vtkIceOpticsReference::Material material;
  const IceTest::Stats stats = IceTest::CompareSphereWithReference(
    room.Renderer, IceTest::Capture(room.Window), room.Center, 1.0, material, WallColor, true);
  std::cout << "culled props " << room.CubeMapPass->GetNumberOfCulledProps() << "\n";
  const bool culledAsExpected = frustumCulling ? room.CubeMapPass->GetNumberOfCulledProps() > 0
                                               : room.CubeMapPass->GetNumberOfCulledProps() == 0;
  return IceTest::ReportReference(
           std::string("wall colours, frustum culling ") + (frustumCulling ? "on" : "off"), stats,
           10000) &&
    culledAsExpected;
}

bool NearlyInvisible()
{
  Room room(200.0);
  room.IceMapper->GetIceProperty()->SetRefractionRatio(1.0);
  room.IceMapper->GetIceProperty()->SetFresnelPower(1.0e6);
  room.Ice->VisibilityOff();
  room.Window->Render();
  const IceTest::Image behind = IceTest::Capture(room.Window);
  room.Ice->VisibilityOn();
  room.Window->Render();
  const IceTest::Image ice = IceTest::Capture(room.Window);
  const std::vector<bool> interior = IceTest::SphereInterior(room.Renderer, room.Center, 1.0, 3);
  std::vector<double> differences;
  for (size_t p = 0; p < interior.size(); ++p)
  {
    if (interior[p])
    {
      differences.push_back(IceTest::PixelDifference(&behind.RGB[3 * p], &ice.RGB[3 * p]));
    }
  }
  const IceTest::Stats stats = IceTest::Summarize(differences);
  const bool ok = stats.Count > 10000 && stats.Mean <= 2.0;
  std::cout << (ok ? "ok   " : "FAIL ") << "eta 1, no reflection, distant walls: " << stats.Count
            << " pixels differ from the scene behind by mean " << stats.Mean << "/255, p99 "
            << stats.P99 << "/255\n";
  return ok;
}

// IceTest::Expect, with the pass's count of face renders so far.
bool ExpectRenders(bool condition, const std::string& what, vtkIdType renders)
{
  return IceTest::Expect(condition, what + " (" + std::to_string(renders) + " face renders)");
}

bool UpdateModes()
{
  bool ok = true;
  {
    Room room(5.0);
    vtkIceCubeMapPass* pass = room.CubeMapPass;
    // A prop whose vtkProperty its first render makes (a user's actor, never given a colour):
    // that is no change of the scene.
    vtkNew<vtkCubeSource> box;
    vtkNew<vtkPolyDataMapper> boxMapper;
    boxMapper->SetInputConnection(box->GetOutputPort());
    vtkNew<vtkActor> plain;
    plain->SetMapper(boxMapper);
    plain->SetPosition(3.0, 0.0, 0.0);
    room.Renderer->AddActor(plain);
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 6,
           "on change: first frame renders 6 faces", pass->GetNumberOfFaceRenders()) &&
      ok;
    room.Window->Render();
    room.Renderer->GetActiveCamera()->Azimuth(30.0);
    room.Renderer->ResetCameraClippingRange();
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 6,
           "on change: a still scene and a moving camera render nothing",
           pass->GetNumberOfFaceRenders()) &&
      ok;
    room.Walls[0][0]->SetPosition(0.5, 0.0, 0.0);
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 12, "on change: moving a wall re-renders",
           pass->GetNumberOfFaceRenders()) &&
      ok;
    room.Walls[2][1]->GetProperty()->SetColor(1.0, 1.0, 1.0);
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 18,
           "on change: recolouring a wall re-renders", pass->GetNumberOfFaceRenders()) &&
      ok;
  }
  {
    Room room(5.0);
    vtkIceCubeMapPass* pass = room.CubeMapPass;
    pass->SetUpdateModeToManual();
    room.Window->Render();
    room.Walls[0][0]->SetPosition(0.5, 0.0, 0.0);
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 6, "manual: a change renders nothing",
           pass->GetNumberOfFaceRenders()) &&
      ok;
    pass->Update();
    room.Window->Render();
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 12, "manual: Update() renders once",
           pass->GetNumberOfFaceRenders()) &&
      ok;
  }
  {
    Room room(5.0);
    vtkIceCubeMapPass* pass = room.CubeMapPass;
    pass->SetUpdateModeToEveryFrame();
    for (int frame = 0; frame < 3; ++frame)
    {
      room.Window->Render();
    }
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 18,
           "every frame: 3 frames render 18 faces", pass->GetNumberOfFaceRenders()) &&
      ok;
    pass->SetFacesPerFrame(2);
    room.Window->Render();
    ok = ExpectRenders(pass->GetNumberOfFaceRenders() == 20, "time slicing: 2 faces per frame",
           pass->GetNumberOfFaceRenders()) &&
      ok;
  }
  return ok;
}
}

int TestIceCubeMapPass(int, char*[])
{
  bool ok = Positions(true);
  ok = Positions(false) && ok;
  ok = NearlyInvisible() && ok;
  ok = UpdateModes() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
