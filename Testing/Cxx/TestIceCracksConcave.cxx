// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Cracks in a concave object, a torus seen from above at an angle. Paper passes: in DepthInterval
// mode the interval between the near and far side of the ring also covers the hole, so cracks show
// there (the paper's known limit); Geometry mode clips them to the surface on the CPU and every
// crack point lies inside the torus. The screen-space interior follows each view ray from the front
// surface to the nearest back face: cracks show only inside the near part of the ring (none in the
// hole, none seen through it in the far part). Left to right: depth interval, geometry,
// screen-space interior, cracks in red. Checked against a reviewed baseline.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{
const double RingRadius = 1.0;
const double TubeRadius = 0.35;

// Every crack point lies inside the analytic torus the mesh approximates (within the mesh's
// chord error): a check independent of how the mapper clips.
bool CracksInside(vtkPolyData* cracks)
{
  vtkIdType outside = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < cracks->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cracks->GetPoint(i, p);
    const double distance = std::hypot(std::hypot(p[0], p[1]) - RingRadius, p[2]) - TubeRadius;
    worst = std::max(worst, distance);
    outside += distance > 2e-3 ? 1 : 0;
  }
  std::cout << (outside == 0 ? "ok   " : "FAIL ") << "geometry mode: " << outside << " of "
            << cracks->GetNumberOfPoints() << " crack points outside the torus (largest distance "
            << worst << ")\n";
  return outside == 0 && cracks->GetNumberOfPoints() > 100;
}
}

int TestIceCracksConcave(int argc, char* argv[])
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(RingRadius);
  torus->SetCrossSectionRadius(TubeRadius);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(96);
  source->SetVResolution(48);
  source->Update();

  vtkSmartPointer<vtkTexture> sky = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 128);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(900, 300);
  window->SetOffScreenRendering(1);
  vtkNew<vtkIceMapper> mappers[3];
  vtkNew<vtkActor> actors[3];
  vtkNew<vtkIcePass> passes[3];
  vtkNew<vtkRenderer> renderers[3];
  for (int i = 0; i < 3; ++i)
  {
    mappers[i]->SetInputConnection(source->GetOutputPort());
    mappers[i]->GetIceProperty()->SetNumberOfCracks(4);
    mappers[i]->GetIceProperty()->SetCrackSeed(2);
    mappers[i]->SetInteriorMethod(
      i < 2 ? vtkIceMapper::InteriorPaperPasses : vtkIceMapper::InteriorScreenSpace);
    mappers[i]->GetPaperInterior()->SetCrackClipping(
      i == 1 ? vtkIcePaperInterior::Geometry : vtkIcePaperInterior::DepthInterval);
    mappers[i]->SetDebugView(vtkIceMapper::DebugCracksClipped);
    actors[i]->SetMapper(mappers[i]);
    renderers[i]->AddActor(actors[i]);
    renderers[i]->SetEnvironmentTexture(sky);
    renderers[i]->SetBackground(0.15, 0.15, 0.2);
    renderers[i]->SetPass(passes[i]);
    renderers[i]->SetViewport(i / 3.0, 0.0, (i + 1) / 3.0, 1.0);
    vtkCamera* camera = renderers[i]->GetActiveCamera();
    camera->SetPosition(0.0, -3.6, 0.9);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewAngle(45.0);
    renderers[i]->ResetCameraClippingRange();
    window->AddRenderer(renderers[i]);
  }
  window->Render();
  const bool inside = CracksInside(mappers[1]->GetCrackGeometry());
  const bool image = IceTest::CheckImage(argc, argv, window);
  return inside && image ? EXIT_SUCCESS : EXIT_FAILURE;
}
