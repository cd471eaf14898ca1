// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceTriangleBVH.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkIceTriangleBVH);

namespace
{
using Vec = std::array<double, 3>;

struct Triangle
{
  Vec Corner[3];
  Vec Normal[3];
  Vec Centroid;
  Vec Low; // bounds of the corners
  Vec High;
};

// The surface-area split's bins per axis, and the depth from which the median split takes over:
// from there log2(MaximumTriangles / LeafSize) = 21 more levels at most stay within MaximumDepth.
constexpr int Bins = 12;
constexpr int SurfaceAreaDepth = vtkIceTriangleBVH::MaximumDepth - 24;

struct Builder
{
  std::vector<Triangle> Input;
  std::vector<int> Order;
  std::vector<float>* Nodes;
  std::vector<float>* Triangles;
  int Depth = 0;

  void Bounds(int first, int last, Vec& low, Vec& high, bool centroids) const
  {
    low.fill(std::numeric_limits<double>::max());
    high.fill(-std::numeric_limits<double>::max());
    for (int i = first; i < last; ++i)
    {
      const Triangle& t = this->Input[this->Order[i]];
      for (int c = 0; c < (centroids ? 1 : 3); ++c)
      {
        const Vec& p = centroids ? t.Centroid : t.Corner[c];
        for (int a = 0; a < 3; ++a)
        {
          low[a] = std::min(low[a], p[a]);
          high[a] = std::max(high[a], p[a]);
        }
      }
    }
  }

  // A child as its parent holds it: its box (two texels), the index of its node or of its first
  // triangle, and minus its triangle count when it is a leaf (0 for a node).
  struct Child
  {
    Vec Low;
    Vec High;
    float Index = 0.0f;
    float Count = 0.0f;
  };

  // The child made of Order[first, last): a leaf of at most LeafSize triangles (appended to the
  // triangles), else a node (appended to the nodes, with its subtree).
  Child Make(int first, int last, int depth)
  {
    this->Depth = std::max(this->Depth, depth);
    Child child;
    this->Bounds(first, last, child.Low, child.High, false);
    if (last - first <= vtkIceTriangleBVH::LeafSize)
    {
      child.Index = static_cast<float>(this->Triangles->size() / 24);
      child.Count = -static_cast<float>(last - first);
      for (int i = first; i < last; ++i)
      {
        const Triangle& t = this->Input[this->Order[i]];
        for (const Vec* part : { t.Corner, t.Normal })
        {
          for (int c = 0; c < 3; ++c)
          {
            this->Triangles->insert(this->Triangles->end(),
              { static_cast<float>(part[c][0]), static_cast<float>(part[c][1]),
                static_cast<float>(part[c][2]), 0.0f });
          }
        }
      }
      return child;
    }
    child.Index = static_cast<float>(this->Split(first, last, depth));
    return child;
  }

  // Binned surface-area heuristic: Order[first, last) partitioned at the best of Bins - 1 planes
  // per axis between the centroids' bounds; returns where the second child starts (first: none
  // better than putting everything on one side).
  int SurfaceAreaSplit(int first, int last, const Vec& centreLow, const Vec& centreHigh)
  {
    struct Bin
    {
      Vec Low;
      Vec High;
      int Count = 0;
    };
    auto area = [](const Vec& low, const Vec& high) {
      const double x = high[0] - low[0];
      const double y = high[1] - low[1];
      const double z = high[2] - low[2];
      return x * y + y * z + z * x;
    };
    auto grow = [](Vec& low, Vec& high, const Vec& otherLow, const Vec& otherHigh) {
      for (int a = 0; a < 3; ++a)
      {
        low[a] = std::min(low[a], otherLow[a]);
        high[a] = std::max(high[a], otherHigh[a]);
      }
    };
    double bestCost = std::numeric_limits<double>::max();
    int bestAxis = -1;
    int bestPlane = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double extent = centreHigh[axis] - centreLow[axis];
      if (!(extent > 0.0))
      {
        continue;
      }
      std::array<Bin, Bins> bins;
      for (Bin& b : bins)
      {
        b.Low.fill(std::numeric_limits<double>::max());
        b.High.fill(-std::numeric_limits<double>::max());
      }
      for (int i = first; i < last; ++i)
      {
        const Triangle& t = this->Input[this->Order[i]];
        Bin& b = bins[this->BinOf(t, axis, centreLow[axis], extent)];
        ++b.Count;
        grow(b.Low, b.High, t.Low, t.High);
      }
      // Areas and counts of every prefix of bins, then sweep the suffixes against them.
      std::array<double, Bins> leftArea;
      std::array<int, Bins> leftCount;
      Vec low;
      Vec high;
      low.fill(std::numeric_limits<double>::max());
      high.fill(-std::numeric_limits<double>::max());
      int count = 0;
      for (int b = 0; b < Bins; ++b)
      {
        grow(low, high, bins[b].Low, bins[b].High);
        count += bins[b].Count;
        leftArea[b] = count > 0 ? area(low, high) : 0.0;
        leftCount[b] = count;
      }
      low.fill(std::numeric_limits<double>::max());
      high.fill(-std::numeric_limits<double>::max());
      count = 0;
      for (int b = Bins - 1; b > 0; --b)
      {
        grow(low, high, bins[b].Low, bins[b].High);
        count += bins[b].Count;
        if (count == 0 || leftCount[b - 1] == 0)
        {
          continue;
        }
        const double cost = leftArea[b - 1] * leftCount[b - 1] + area(low, high) * count;
        if (cost < bestCost)
        {
          bestCost = cost;
          bestAxis = axis;
          bestPlane = b;
        }
      }
    }
    if (bestAxis < 0)
    {
      return first;
    }
    const double extent = centreHigh[bestAxis] - centreLow[bestAxis];
    return static_cast<int>(std::partition(this->Order.begin() + first, this->Order.begin() + last,
                              [&](int i) {
                                return this->BinOf(this->Input[i], bestAxis, centreLow[bestAxis],
                                         extent) < bestPlane;
                              }) -
      this->Order.begin());
  }

  static int BinOf(const Triangle& t, int axis, double low, double extent)
  {
    const int b = static_cast<int>(Bins * (t.Centroid[axis] - low) / extent);
    return std::min(Bins - 1, std::max(0, b));
  }

  // Appends the node splitting Order[first, last) in two children; returns its index.
  int Split(int first, int last, int depth)
  {
    const int index = static_cast<int>(this->Nodes->size() / 16);
    this->Nodes->resize(this->Nodes->size() + 16, 0.0f);
    Vec centreLow;
    Vec centreHigh;
    this->Bounds(first, last, centreLow, centreHigh, true);
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      if (centreHigh[a] - centreLow[a] > centreHigh[axis] - centreLow[axis])
      {
        axis = a;
      }
    }
    // A binned surface-area split where it finds one: a ray meets a box in proportion to its area,
    // so the children of least area times triangles are the fewest visits. Deep in the tree (or
    // where all centroids fall in one bin) the median split, which halves the count whatever the
    // shape: the depth then stays within MaximumDepth.
    int middle =
      depth < SurfaceAreaDepth ? this->SurfaceAreaSplit(first, last, centreLow, centreHigh) : first;
    if (middle <= first || middle >= last)
    {
      middle = first + (last - first) / 2;
      std::nth_element(this->Order.begin() + first, this->Order.begin() + middle,
        this->Order.begin() + last, [this, axis](int a, int b) {
          return this->Input[a].Centroid[axis] < this->Input[b].Centroid[axis];
        });
    }
    const Child children[2] = { this->Make(first, middle, depth + 1),
      this->Make(middle, last, depth + 1) };
    float* node = this->Nodes->data() + 16 * index; // the vector may have grown
    for (const Child& c : children)
    {
      *node++ = static_cast<float>(c.Low[0]);
      *node++ = static_cast<float>(c.Low[1]);
      *node++ = static_cast<float>(c.Low[2]);
      *node++ = c.Index;
      *node++ = static_cast<float>(c.High[0]);
      *node++ = static_cast<float>(c.High[1]);
      *node++ = static_cast<float>(c.High[2]);
      *node++ = c.Count;
    }
    return index;
  }
};

// The ray's parameter interval inside the box [low, high], empty when tNear > tFar.
void SlabInterval(const double origin[3], const double inverse[3], const float* low,
  const float* high, double& tNear, double& tFar)
{
  for (int a = 0; a < 3; ++a)
  {
    double t0 = (low[a] - origin[a]) * inverse[a];
    double t1 = (high[a] - origin[a]) * inverse[a];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
  }
}
}

//------------------------------------------------------------------------------
bool vtkIceTriangleBVH::Build(vtkPolyData* surface, vtkDataArray* normals)
{
  this->Nodes.clear();
  this->Triangles.clear();
  this->Depth = 0;
  this->Diagonal = 0.0;
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  if (!points || !normals || normals->GetNumberOfComponents() != 3 ||
    normals->GetNumberOfTuples() < points->GetNumberOfPoints())
  {
    return false;
  }
  Builder builder;
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    Triangle t;
    const vtkIdType ids[3] = { a, b, c };
    for (int i = 0; i < 3; ++i)
    {
      points->GetPoint(ids[i], t.Corner[i].data());
      normals->GetTuple(ids[i], t.Normal[i].data());
    }
    for (int i = 0; i < 3; ++i)
    {
      t.Centroid[i] = (t.Corner[0][i] + t.Corner[1][i] + t.Corner[2][i]) / 3.0;
      t.Low[i] = std::min({ t.Corner[0][i], t.Corner[1][i], t.Corner[2][i] });
      t.High[i] = std::max({ t.Corner[0][i], t.Corner[1][i], t.Corner[2][i] });
    }
    builder.Input.push_back(t);
  };
  vtkIdType count;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    for (vtkIdType i = 2; i < count; ++i)
    {
      add(ids[0], ids[i - 1], ids[i]);
    }
  }
  vtkCellArray* strips = surface->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(count, ids);)
  {
    for (vtkIdType i = 2; i < count; ++i)
    {
      // A strip's odd triangles run clockwise in its order: turned, every triangle faces as its
      // cell does (the trace tells inside from outside by it).
      if (i % 2 == 0)
      {
        add(ids[i - 2], ids[i - 1], ids[i]);
      }
      else
      {
        add(ids[i - 1], ids[i - 2], ids[i]);
      }
    }
  }
  const vtkIdType triangles = static_cast<vtkIdType>(builder.Input.size());
  if (triangles == 0 || triangles > MaximumTriangles)
  {
    return false;
  }
  builder.Order.resize(builder.Input.size());
  for (size_t i = 0; i < builder.Order.size(); ++i)
  {
    builder.Order[i] = static_cast<int>(i);
  }
  builder.Nodes = &this->Nodes;
  builder.Triangles = &this->Triangles;
  this->Nodes.reserve(static_cast<size_t>(16 * (triangles / LeafSize + 1)));
  this->Triangles.reserve(static_cast<size_t>(24 * triangles));
  // The root is always a node: a surface of LeafSize triangles or fewer gets an empty second
  // child, a leaf of no triangle (count -0.5: negative marks a leaf, and it truncates to 0). Not
  // a node: the slab test takes any box's corners in either order, so a ray enters even an
  // "inverted" box, and a node child there pointed back at the root (the traversal never ended).
  if (triangles > LeafSize)
  {
    builder.Split(0, static_cast<int>(triangles), 1);
  }
  else
  {
    const Builder::Child leaf = builder.Make(0, static_cast<int>(triangles), 1);
    this->Nodes = { static_cast<float>(leaf.Low[0]), static_cast<float>(leaf.Low[1]),
      static_cast<float>(leaf.Low[2]), leaf.Index, static_cast<float>(leaf.High[0]),
      static_cast<float>(leaf.High[1]), static_cast<float>(leaf.High[2]), leaf.Count,
      static_cast<float>(leaf.Low[0]), static_cast<float>(leaf.Low[1]),
      static_cast<float>(leaf.Low[2]), 0.0f, static_cast<float>(leaf.High[0]),
      static_cast<float>(leaf.High[1]), static_cast<float>(leaf.High[2]), -0.5f };
  }
  this->Depth = builder.Depth;
  Vec low;
  Vec high;
  builder.Bounds(0, static_cast<int>(triangles), low, high, false);
  this->Diagonal = std::sqrt(std::pow(high[0] - low[0], 2.0) + std::pow(high[1] - low[1], 2.0) +
    std::pow(high[2] - low[2], 2.0));
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceTriangleBVH::Intersect(const double origin[3], const double direction[3], double tMin,
  double tMax, double& t, double normal[3], double faceNormal[3], int orientation) const
{
  if (this->Nodes.empty())
  {
    return false;
  }
  double inverse[3];
  for (int a = 0; a < 3; ++a)
  {
    inverse[a] = direction[a] != 0.0 ? 1.0 / direction[a] : 1.0e30;
  }
  bool hit = false;
  t = tMax;
  // Nodes to visit and where the ray enters their box: one beyond the nearest hit is skipped.
  int stack[MaximumDepth];
  double entries[MaximumDepth];
  int top = 1;
  stack[0] = 0;
  entries[0] = tMin;
  auto leaf = [&](const float* child) {
    const int first = static_cast<int>(child[3]);
    for (int i = first; i < first - static_cast<int>(child[7]); ++i)
    {
      const float* tri = this->Triangles.data() + 24 * i;
      double e1[3];
      double e2[3];
      double s[3];
      for (int a = 0; a < 3; ++a)
      {
        e1[a] = tri[4 + a] - tri[a];
        e2[a] = tri[8 + a] - tri[a];
        s[a] = origin[a] - tri[a];
      }
      const double p[3] = { direction[1] * e2[2] - direction[2] * e2[1],
        direction[2] * e2[0] - direction[0] * e2[2], direction[0] * e2[1] - direction[1] * e2[0] };
      const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
      if (det == 0.0 || orientation * det > 0.0) // det > 0: met counter-clockwise
      {
        continue;
      }
      const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
      const double q[3] = { s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
        s[0] * e1[1] - s[1] * e1[0] };
      const double v = (direction[0] * q[0] + direction[1] * q[1] + direction[2] * q[2]) / det;
      const double along = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
      // Edges widened by 1e-5, as in the shader: a ray along a shared edge meets one of them.
      if (u < -1.0e-5 || v < -1.0e-5 || u + v > 1.00001 || along <= tMin || along >= t)
      {
        continue;
      }
      t = along;
      hit = true;
      for (int a = 0; a < 3; ++a)
      {
        normal[a] = (1.0 - u - v) * tri[12 + a] + u * tri[16 + a] + v * tri[20 + a];
      }
      if (faceNormal)
      {
        faceNormal[0] = e1[1] * e2[2] - e1[2] * e2[1];
        faceNormal[1] = e1[2] * e2[0] - e1[0] * e2[2];
        faceNormal[2] = e1[0] * e2[1] - e1[1] * e2[0];
      }
    }
  };
  while (top > 0)
  {
    --top;
    if (entries[top] >= t)
    {
      continue;
    }
    const float* node = this->Nodes.data() + 16 * stack[top];
    // Both children's boxes; leaves are searched at once (the hit shortens the rest), nodes pushed
    // the nearer last.
    double entry[2];
    bool enters[2];
    for (int c = 0; c < 2; ++c)
    {
      const float* child = node + 8 * c;
      double tFar = t;
      entry[c] = tMin;
      SlabInterval(origin, inverse, child, child + 4, entry[c], tFar);
      enters[c] = entry[c] <= tFar;
      if (enters[c] && child[7] < 0.0f)
      {
        leaf(child);
        enters[c] = false;
      }
    }
    const int first = entry[0] <= entry[1] ? 1 : 0; // pushed first: the farther
    for (int c : { first, 1 - first })
    {
      if (enters[c] && entry[c] < t && top < MaximumDepth)
      {
        stack[top] = static_cast<int>(node[8 * c + 3]);
        entries[top] = entry[c];
        ++top;
      }
    }
  }
  return hit;
}

//------------------------------------------------------------------------------
void vtkIceTriangleBVH::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Triangles: " << this->GetNumberOfTriangles() << "\n";
  os << indent << "Nodes: " << this->GetNumberOfNodes() << "\n";
  os << indent << "Depth: " << this->Depth << "\n";
}
