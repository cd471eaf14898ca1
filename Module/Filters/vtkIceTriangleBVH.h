// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceTriangleBVH
 * @brief   A bounding volume hierarchy of an ice surface's triangles, laid out for a shader
 *          (for the project's modules: not installed).
 *
 * Build() takes the surface's polygons and triangle strips (polygons split into fans, every
 * triangle in its cell's order of corners: a strip's every other one turned) with point
 * normals and makes a binary tree of axis-aligned boxes down to at most LeafSize triangles, each
 * split by the binned surface-area heuristic (12 planes per axis; the median of the centroids'
 * longest axis where it finds none, and from depth MaximumDepth - 24 on, so the depth stays within
 * MaximumDepth). GetNodes() holds four RGBA texels
 * per node, two per child: its box's minimum with its node's index (or a leaf's first triangle),
 * its box's maximum with minus its triangle count for a leaf (0 for a node), so a visit reads
 * both children's boxes at once; node 0 is the root. GetTriangles() holds six texels per
 * triangle (three corners, three normals), as the trace of vtkIceTraceFS.glsl reads them from
 * texture buffers. Indices are stored as floats:
 * exact below 2^24, so at most 8 million triangles (Build refuses more). Intersect() is the same
 * traversal on the CPU: the shader's reference.
 */
#ifndef vtkIceTriangleBVH_h
#define vtkIceTriangleBVH_h

#include "FiltersIceModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For the node and triangle arrays

class vtkDataArray;
class vtkPolyData;

class FILTERSICE_EXPORT vtkIceTriangleBVH : public vtkObject
{
public:
  static vtkIceTriangleBVH* New();
  vtkTypeMacro(vtkIceTriangleBVH, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr int LeafSize = 4;
  static constexpr vtkIdType MaximumTriangles = 8 << 20;
  static constexpr int MaximumDepth = 48; // the shader's traversal stack holds as many

  /**
   * Builds the tree of `surface`'s triangles with the point normals `normals` (3 components, one
   * per point). False, with an empty tree, when there is no triangle or more than
   * MaximumTriangles.
   */
  bool Build(vtkPolyData* surface, vtkDataArray* normals);

  const std::vector<float>& GetNodes() const { return this->Nodes; }
  const std::vector<float>& GetTriangles() const { return this->Triangles; }
  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 24);
  }
  vtkIdType GetNumberOfNodes() const { return static_cast<vtkIdType>(this->Nodes.size() / 16); }
  int GetDepth() const { return this->Depth; }
  // The diagonal of the root box (0 when empty).
  double GetDiagonal() const { return this->Diagonal; }

  /**
   * The nearest triangle the ray origin + t direction meets with t in (tMin, tMax), as the shader
   * finds it: true with t and the interpolated (unnormalised) normal there; where faceNormal is
   * given, also the triangle's own normal (unnormalised, by its corners' order). For a ray
   * inside the surface, `orientation` skips the triangles it meets from outside: 1 where every
   * triangle is counter-clockwise seen from outside, -1 where every one is clockwise, 0 (none
   * skipped) where that is not known.
   */
  bool Intersect(const double origin[3], const double direction[3], double tMin, double tMax,
    double& t, double normal[3], double faceNormal[3] = nullptr, int orientation = 0) const;

protected:
  vtkIceTriangleBVH() = default;
  ~vtkIceTriangleBVH() override = default;

  std::vector<float> Nodes;
  std::vector<float> Triangles;
  int Depth = 0;
  double Diagonal = 0.0;

private:
  vtkIceTriangleBVH(const vtkIceTriangleBVH&) = delete;
  void operator=(const vtkIceTriangleBVH&) = delete;
};

#endif
