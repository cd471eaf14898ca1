// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceBlockSource.h"

#include "vtkIceNoise.h"
#include "vtkIceSmoothNormals.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

vtkStandardNewMacro(vtkIceBlockSource);

//------------------------------------------------------------------------------
vtkIceBlockSource::vtkIceBlockSource()
  : Resolution(20)
  , Seed(1)
  , Displacement(0.08)
  , Size(2.0)
  , Roundness(0.3)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkIceBlockSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int res = this->Resolution;
  const double radius = this->Roundness;
  const double inner = 1.0 - radius;
  // Keeps the displacement direction defined on the edges of a sharp cube.
  const double innerForDirection = std::min(inner, 0.999);
  const double halfSize = 0.5 * this->Size;
  const std::uint32_t seed = static_cast<std::uint32_t>(this->Seed);

  vtkNew<vtkPoints> points;
  points->Allocate(6 * res * res + 2);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(12 * res * res, 36 * res * res);

  // Points are keyed by their integer lattice position on the cube, so the
  // faces share the points along their common edges and corners.
  std::unordered_map<long long, vtkIdType> latticeToId;
  auto pointId = [&](const int ijk[3]) {
    const long long key =
      (static_cast<long long>(ijk[0]) * (res + 1) + ijk[1]) * (res + 1) + ijk[2];
    const auto found = latticeToId.find(key);
    if (found != latticeToId.end())
    {
      return found->second;
    }

    // Cube point in [-1, 1]^3, projected onto the rounded box: the inner box
    // [-inner, inner]^3 grown by the rounding radius.
    double cube[3], dir[3], surface[3];
    double length = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      cube[c] = 2.0 * ijk[c] / res - 1.0;
      dir[c] = cube[c] - std::max(-innerForDirection, std::min(innerForDirection, cube[c]));
      length += dir[c] * dir[c];
    }
    length = std::sqrt(length);
    for (int c = 0; c < 3; ++c)
    {
      dir[c] /= length;
      surface[c] = std::max(-inner, std::min(inner, cube[c])) + radius * dir[c];
    }

    const double offset = this->Displacement * vtkIceNoise::FractalNoise(surface, seed);
    double x[3];
    for (int c = 0; c < 3; ++c)
    {
      x[c] = halfSize * (surface[c] + offset * dir[c]);
    }
    const vtkIdType id = points->InsertNextPoint(x);
    latticeToId.emplace(key, id);
    return id;
  };

  for (int axis = 0; axis < 3; ++axis)
  {
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (int m = 0; m < res; ++m)
      {
        for (int n = 0; n < res; ++n)
        {
          const int corners[4][2] = { { m, n }, { m + 1, n }, { m + 1, n + 1 }, { m, n + 1 } };
          vtkIdType quad[4];
          for (int k = 0; k < 4; ++k)
          {
            int ijk[3];
            ijk[axis] = side * res;
            ijk[b] = corners[k][0];
            ijk[c] = corners[k][1];
            quad[k] = pointId(ijk);
          }
          // (b, c, axis) is right-handed, so this corner order faces +axis.
          if (side == 0)
          {
            std::swap(quad[1], quad[3]);
          }
          const vtkIdType tri1[3] = { quad[0], quad[1], quad[2] };
          const vtkIdType tri2[3] = { quad[0], quad[2], quad[3] };
          polys->InsertNextCell(3, tri1);
          polys->InsertNextCell(3, tri2);
        }
      }
    }
  }

  vtkNew<vtkPolyData> block;
  block->SetPoints(points);
  block->SetPolys(polys);

  output->ShallowCopy(vtkIceSmoothNormals(block));
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceBlockSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Displacement: " << this->Displacement << "\n";
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Roundness: " << this->Roundness << "\n";
}
