// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The model sources of the paper's three objects: triangle counts near the paper's figures,
// normals present and outward, closed block surface, and seeds that reproduce exactly.
#include "vtkIceBlockSource.h"
#include "vtkIceTeapotSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFeatureEdges.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <iostream>

namespace
{
// Orientation check that also holds for the concave teapot: the signed volume enclosed by the
// triangles (divergence theorem) is positive, so the winding faces outward, and `agreement` is
// the fraction of triangles whose point normals agree with their winding.
double SignedVolume(vtkPolyData* data, double& agreement)
{
  vtkDataArray* normals = data->GetPointData()->GetNormals();
  double volume = 0.0;
  vtkIdType agreeing = 0;
  vtkIdType triangles = 0;
  vtkCellArray* polys = data->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n != 3)
    {
      continue;
    }
    double p[3][3];
    double average[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      data->GetPoint(ids[k], p[k]);
      const double* normal = normals->GetTuple3(ids[k]);
      vtkMath::Add(average, normal, average);
    }
    double u[3];
    double v[3];
    double face[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, face);
    double cross12[3];
    vtkMath::Cross(p[1], p[2], cross12);
    volume += vtkMath::Dot(p[0], cross12) / 6.0;
    agreeing += vtkMath::Dot(face, average) > 0.0 ? 1 : 0;
    ++triangles;
  }
  agreement = triangles ? static_cast<double>(agreeing) / triangles : 0.0;
  return volume;
}

vtkIdType BoundaryEdges(vtkPolyData* data)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(data);
  edges->BoundaryEdgesOn();
  edges->FeatureEdgesOff();
  edges->NonManifoldEdgesOn();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3];
    double q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return false;
    }
  }
  return true;
}
}

int TestIceSources(int, char*[])
{
  bool ok = true;
  auto expect = [&ok](bool condition, const char* what) {
    std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
    ok = ok && condition;
  };

  vtkNew<vtkIceTeapotSource> teapot;
  teapot->Update();
  vtkPolyData* pot = teapot->GetOutput();
  double potAgreement = 0.0;
  const double potVolume = SignedVolume(pot, potAgreement);
  std::cout << "teapot: " << pot->GetNumberOfPolys() << " triangles, " << pot->GetNumberOfPoints()
            << " points, signed volume " << potVolume << ", normals agree with winding on "
            << 100.0 * potAgreement << "% of triangles\n";
  expect(pot->GetNumberOfPolys() >= 13500 && pot->GetNumberOfPolys() <= 14400,
    "teapot has about 14 400 triangles");
  expect(pot->GetPointData()->GetNormals() != nullptr, "teapot has point normals");
  expect(potVolume > 0.5 && potAgreement > 0.99, "teapot triangles and normals face outward");
  double bounds[6];
  pot->GetBounds(bounds);
  expect(bounds[3] - bounds[2] < bounds[1] - bounds[0], "teapot stands upright (+Y up)");

  vtkNew<vtkIceBlockSource> block;
  block->Update();
  vtkPolyData* ice = block->GetOutput();
  double blockAgreement = 0.0;
  const double blockVolume = SignedVolume(ice, blockAgreement);
  std::cout << "block: " << ice->GetNumberOfPolys() << " triangles, signed volume " << blockVolume
            << ", normals agree with winding on " << 100.0 * blockAgreement << "% of triangles, "
            << BoundaryEdges(ice) << " open edges\n";
  expect(ice->GetNumberOfPolys() == 4800, "block has 4 800 triangles");
  expect(blockVolume > 4.0 && blockAgreement > 0.999, "block triangles and normals face outward");
  expect(BoundaryEdges(ice) == 0, "block surface is closed");

  vtkNew<vtkIceBlockSource> same;
  same->Update();
  expect(SamePoints(ice, same->GetOutput()), "same seed gives the same block");
  vtkNew<vtkIceBlockSource> other;
  other->SetSeed(7);
  other->Update();
  expect(!SamePoints(ice, other->GetOutput()), "another seed gives another block");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
