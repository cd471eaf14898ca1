// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Ice drawn the ways VTK users draw surfaces, with vtkIcePass (two-sided refraction, cracks and
// air, so every sub-pass sees the same actor):
// - EdgeVisibility: edges are drawn over the refracting ice, and every pixel at least two pixels
//   from an edge equals the render without edges (VTK's geometry shader for edges used to drop
//   the ice's varyings: flat colour, no refraction).
// - Wireframe and points: the ice is drawn as lines and points (iced), not as a filled disk of
//   garbage: most of the silhouette shows the background.
// - Point scalars tint the ice with ScalarVisibility on (as any VTK mapper colours) and leave it
//   as it was with ScalarVisibility off; cell scalars leave it as it was.
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkElevationFilter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <algorithm>
#include <functional>
#include <iostream>
#include <string>

namespace
{
enum class Input
{
  Plain,
  PointScalars,
  CellScalars
};

// Renders the ice sphere (none when `ice` is false) after `setup` has set its actor up.
IceTest::Image Render(bool ice, Input input, const std::function<void(vtkActor*)>& setup)
{
  vtkSmartPointer<vtkTexture> environment =
    IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 128);
  vtkNew<vtkRenderer> renderer;
  IceScene::AddEnvironment(renderer, environment);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  vtkNew<vtkElevationFilter> scalars;
  scalars->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(
    input == Input::Plain ? sphere->GetOutputPort() : scalars->GetOutputPort());
  if (input == Input::CellScalars)
  {
    mapper->SetScalarModeToUseCellData();
    scalars->Update();
    scalars->GetOutput()->GetCellData()->SetScalars(
      scalars->GetOutput()->GetPointData()->GetScalars());
  }
  mapper->GetIceProperty()->SetNumberOfCracks(3);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(4);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetVisibility(ice);
  setup(actor);
  renderer->AddActor(actor);
  vtkNew<vtkIcePass> icePass;
  renderer->SetPass(icePass);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0.3, 0.4, 2.5);
  renderer->ResetCameraClippingRange();
  window->Render();
  return IceTest::Capture(window);
}

// Pixels where two renders differ by more than `threshold`.
std::vector<bool> Differing(const IceTest::Image& a, const IceTest::Image& b, int threshold)
{
  std::vector<bool> mask(static_cast<size_t>(a.Width) * a.Height);
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      mask[y * a.Width + x] = IceTest::PixelDifference(a.At(x, y), b.At(x, y)) > threshold;
    }
  }
  return mask;
}

size_t Count(const std::vector<bool>& mask)
{
  return static_cast<size_t>(std::count(mask.begin(), mask.end(), true));
}

bool Check(bool ok, const std::string& message)
{
  std::cout << (ok ? "ok   " : "FAIL ") << message << "\n";
  return ok;
}
}

int TestIceRepresentations(int, char*[])
{
  auto nothing = [](vtkActor*) {};
  const IceTest::Image background = Render(false, Input::Plain, nothing);
  const IceTest::Image ice = Render(true, Input::Plain, nothing);
  const size_t silhouette = Count(Differing(background, ice, 8));
  bool ok = Check(silhouette > 10000, "the ice covers " + std::to_string(silhouette) + " pixels");

  // Edges over the ice.
  const IceTest::Image edged = Render(true, Input::Plain, [](vtkActor* actor) {
    actor->GetProperty()->EdgeVisibilityOn();
    actor->GetProperty()->SetEdgeColor(1.0, 0.0, 1.0);
  });
  const std::vector<bool> edges = Differing(ice, edged, 24);
  std::vector<double> awayDifferences;
  for (int y = 2; y < ice.Height - 2; ++y)
  {
    for (int x = 2; x < ice.Width - 2; ++x)
    {
      bool nearEdge = false;
      for (int dy = -2; dy <= 2 && !nearEdge; ++dy)
      {
        for (int dx = -2; dx <= 2 && !nearEdge; ++dx)
        {
          nearEdge = edges[(y + dy) * ice.Width + x + dx];
        }
      }
      if (!nearEdge && IceTest::PixelDifference(background.At(x, y), ice.At(x, y)) > 8)
      {
        awayDifferences.push_back(IceTest::PixelDifference(ice.At(x, y), edged.At(x, y)));
      }
    }
  }
  const size_t edgePixels = Count(edges);
  ok = Check(edgePixels > 1500 && edgePixels < silhouette / 2,
         "edges: " + std::to_string(edgePixels) + " edge pixels over the ice") &&
    ok;
  const IceTest::Stats away = IceTest::Summarize(awayDifferences);
  ok = Check(away.Count > 2000 && away.Mean <= 1.0 && away.P99 <= 4.0,
         "edges: " + std::to_string(away.Count) +
           " ice pixels away from the edges differ from the "
           "ice without edges by mean " +
           std::to_string(away.Mean) + "/255, p99 " + std::to_string(away.P99) + "/255, max " +
           std::to_string(away.Max) + "/255") &&
    ok;

  // Wireframe and points: drawn, the rest of the silhouette shows the background.
  const IceTest::Image wireframe = Render(true, Input::Plain,
    [](vtkActor* actor) { actor->GetProperty()->SetRepresentationToWireframe(); });
  const IceTest::Image points = Render(true, Input::Plain, [](vtkActor* actor) {
    actor->GetProperty()->SetRepresentationToPoints();
    actor->GetProperty()->SetPointSize(3.0);
  });
  for (const auto& drawn :
    { std::make_pair("wireframe", &wireframe), std::make_pair("points", &points) })
  {
    const size_t changed = Count(Differing(background, *drawn.second, 8));
    ok = Check(changed > 500 && changed < silhouette / 2,
           std::string(drawn.first) + ": " + std::to_string(changed) +
             " pixels drawn (silhouette " + std::to_string(silhouette) + ")") &&
      ok;
  }

  // Scalars on the input: point scalars tint the ice as any VTK mapper colours by them (and only
  // then: with ScalarVisibility off the ice is unchanged; TestIceColorByArray checks the tint);
  // cell scalars do not change it.
  const auto scalarsOn = [](vtkActor* actor) { actor->GetMapper()->ScalarVisibilityOn(); };
  const auto scalarsOff = [](vtkActor* actor) { actor->GetMapper()->ScalarVisibilityOff(); };
  const size_t tinted = Count(Differing(ice, Render(true, Input::PointScalars, scalarsOn), 2));
  ok = Check(tinted > silhouette / 2,
         "point scalars: " + std::to_string(tinted) + " pixels tinted (silhouette " +
           std::to_string(silhouette) + ")") &&
    ok;
  const size_t hidden = Count(Differing(ice, Render(true, Input::PointScalars, scalarsOff), 2));
  ok = Check(hidden == 0,
         "point scalars, ScalarVisibility off: " + std::to_string(hidden) +
           " pixels differ from the ice without them") &&
    ok;
  const size_t cells = Count(Differing(ice, Render(true, Input::CellScalars, scalarsOn), 2));
  ok = Check(cells == 0,
         "cell scalars: " + std::to_string(cells) + " pixels differ from the ice without them") &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
