#include "vtkIceBlockSource.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

vtkStandardNewMacro(vtkIceBlockSource);

namespace
{
// Integer hashing keeps the noise identical on every platform for a seed
// (std:: distributions are implementation defined).
std::uint32_t Mix(std::uint32_t h)
{
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

std::uint32_t HashLattice(int x, int y, int z, std::uint32_t seed)
{
  std::uint32_t h = Mix(seed ^ 0x9e3779b9U);
  h = Mix(h ^ static_cast<std::uint32_t>(x));
  h = Mix(h ^ static_cast<std::uint32_t>(y));
  return Mix(h ^ static_cast<std::uint32_t>(z));
}

double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double Lerp(double a, double b, double t)
{
  return a + t * (b - a);
}

// Gradient noise with values in about [-1, 1].
double GradientNoise(const double p[3], std::uint32_t seed)
{
  static const double gradients[12][3] = { { 1, 1, 0 }, { -1, 1, 0 }, { 1, -1, 0 }, { -1, -1, 0 },
    { 1, 0, 1 }, { -1, 0, 1 }, { 1, 0, -1 }, { -1, 0, -1 }, { 0, 1, 1 }, { 0, -1, 1 },
    { 0, 1, -1 }, { 0, -1, -1 } };

  int cell[3];
  double f[3];
  for (int c = 0; c < 3; ++c)
  {
    const double fl = std::floor(p[c]);
    cell[c] = static_cast<int>(fl);
    f[c] = p[c] - fl;
  }

  double value[2][2][2];
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int k = 0; k < 2; ++k)
      {
        const double* g = gradients[HashLattice(cell[0] + i, cell[1] + j, cell[2] + k, seed) % 12];
        value[i][j][k] = g[0] * (f[0] - i) + g[1] * (f[1] - j) + g[2] * (f[2] - k);
      }
    }
  }

  const double wx = Fade(f[0]);
  const double wy = Fade(f[1]);
  const double wz = Fade(f[2]);
  const double y0 =
    Lerp(Lerp(value[0][0][0], value[1][0][0], wx), Lerp(value[0][1][0], value[1][1][0], wx), wy);
  const double y1 =
    Lerp(Lerp(value[0][0][1], value[1][0][1], wx), Lerp(value[0][1][1], value[1][1][1], wx), wy);
  return Lerp(y0, y1, wz);
}

// A few octaves of gradient noise, normalized to about [-1, 1]. Each octave
// gets its own lattice hash and a random offset so that the lattices do not
// line up with each other or with the cube.
double FractalNoise(const double p[3], std::uint32_t seed)
{
  const int octaves = 4;
  double frequency = 1.5;
  double amplitude = 1.0;
  double sum = 0.0;
  double norm = 0.0;
  for (int octave = 0; octave < octaves; ++octave)
  {
    const std::uint32_t octaveSeed = Mix(seed + 0x632be5abU * static_cast<std::uint32_t>(octave));
    double q[3];
    for (int c = 0; c < 3; ++c)
    {
      const double offset = 256.0 * (HashLattice(c, octave, 0, octaveSeed) / 4294967296.0);
      q[c] = frequency * p[c] + offset;
    }
    sum += amplitude * GradientNoise(q, octaveSeed);
    norm += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / norm;
}
}

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
    const long long key = (static_cast<long long>(ijk[0]) * (res + 1) + ijk[1]) * (res + 1) + ijk[2];
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

    const double offset = this->Displacement * FractalNoise(surface, seed);
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

  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(block);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();

  output->ShallowCopy(normals->GetOutput());
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
