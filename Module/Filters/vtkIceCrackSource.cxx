// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCrackSource.h"

#include "vtkIceNoise.h"
#include "vtkIceSmoothNormals.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceCrackSource);

//------------------------------------------------------------------------------
vtkIceCrackSource::vtkIceCrackSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkIceCrackSource::Shape vtkIceCrackSource::GetShape(int seed)
{
  const std::uint32_t s = static_cast<std::uint32_t>(seed);
  // Bowl and saddle curvature, roughness, outline raggedness.
  Shape shape;
  shape.Bowl = 0.35 * (vtkIceNoise::Uniform(s, 0) - 0.5);
  shape.Saddle = 0.35 * (vtkIceNoise::Uniform(s, 1) - 0.5);
  shape.Roughness = 0.04 + 0.04 * vtkIceNoise::Uniform(s, 2);
  shape.Ragged = 0.25 + 0.2 * vtkIceNoise::Uniform(s, 3);
  shape.Seed = seed;
  return shape;
}

//------------------------------------------------------------------------------
double vtkIceCrackSource::Shape::OutlineRadius(double angle) const
{
  // Varies smoothly (and periodically) with the angle.
  const double around[3] = { 1.3 * std::cos(angle), 1.3 * std::sin(angle), 0.5 };
  return 1.0 +
    this->Ragged * vtkIceNoise::FractalNoise(around, static_cast<std::uint32_t>(this->Seed) + 17);
}

//------------------------------------------------------------------------------
int vtkIceCrackSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const Shape shape = GetShape(this->Seed);
  const std::uint32_t seed = static_cast<std::uint32_t>(this->Seed);

  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  for (int ring = 1; ring <= this->Rings; ++ring)
  {
    for (int sector = 0; sector < this->Sectors; ++sector)
    {
      const double angle = 2.0 * vtkMath::Pi() * sector / this->Sectors;
      const double r = shape.OutlineRadius(angle) * ring / this->Rings;
      const double x = r * std::cos(angle);
      const double y = r * std::sin(angle);
      const double p[3] = { 2.0 * x, 2.0 * y, 0.0 };
      const double z = shape.Bowl * (x * x + y * y) + shape.Saddle * (x * x - y * y) +
        shape.Roughness * vtkIceNoise::FractalNoise(p, seed + 31);
      points->InsertNextPoint(x, y, z);
    }
  }

  vtkNew<vtkCellArray> triangles;
  const int n = this->Sectors;
  auto id = [n](int ring, int sector) { return 1 + (ring - 1) * n + (sector % n); };
  for (int sector = 0; sector < n; ++sector)
  {
    const vtkIdType fan[3] = { 0, id(1, sector), id(1, sector + 1) };
    triangles->InsertNextCell(3, fan);
  }
  for (int ring = 1; ring < this->Rings; ++ring)
  {
    for (int sector = 0; sector < n; ++sector)
    {
      const vtkIdType a = id(ring, sector);
      const vtkIdType b = id(ring, sector + 1);
      const vtkIdType c = id(ring + 1, sector + 1);
      const vtkIdType d = id(ring + 1, sector);
      const vtkIdType first[3] = { a, d, c };
      const vtkIdType second[3] = { a, c, b };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }

  vtkNew<vtkPolyData> sheet;
  sheet->SetPoints(points);
  sheet->SetPolys(triangles);
  output->ShallowCopy(vtkIceSmoothNormals(sheet));
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceCrackSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Rings: " << this->Rings << "\n";
  os << indent << "Sectors: " << this->Sectors << "\n";
}
