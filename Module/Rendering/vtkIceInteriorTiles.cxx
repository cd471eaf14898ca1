// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceInteriorTiles.h"

#include "vtkIceScreenRegion.h"
#include "vtkIceInteriorTable.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
// The convex hull (counter-clockwise) of the projected corners of a record's box, in pixels; empty
// when a corner is at or behind the plane of the eye (the box then reaches its whole bounding
// rectangle).
std::vector<std::array<double, 2>> ProjectedHull(
  vtkMatrix4x4* worldToClip, const double corners[24], int width, int height)
{
  std::vector<std::array<double, 2>> points;
  for (int c = 0; c < 8; ++c)
  {
    const double p[4] = { corners[3 * c], corners[3 * c + 1], corners[3 * c + 2], 1.0 };
    double clip[4];
    worldToClip->MultiplyPoint(p, clip);
    if (!(clip[3] > 1e-6 * (std::abs(clip[0]) + std::abs(clip[1]) + std::abs(clip[2]))))
    {
      return {};
    }
    points.push_back(
      { 0.5 * (clip[0] / clip[3] + 1.0) * width, 0.5 * (clip[1] / clip[3] + 1.0) * height });
  }
  std::sort(points.begin(), points.end());
  const auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                       const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<std::array<double, 2>> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) // lower chain
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) // upper chain
  {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

// Whether the pixels [x0, x1] x [y0, y1] (a tile, with a pixel of margin) may meet the convex
// polygon `hull`: no edge of the polygon has the whole rectangle outside it.
bool Meets(
  const std::vector<std::array<double, 2>>& hull, double x0, double y0, double x1, double y1)
{
  if (hull.size() < 3)
  {
    return true; // degenerate (edge-on): its bounding rectangle decides
  }
  for (size_t i = 0; i < hull.size(); ++i)
  {
    const std::array<double, 2>& a = hull[i];
    const std::array<double, 2>& b = hull[(i + 1) % hull.size()];
    bool allOutside = true;
    for (const double x : { x0, x1 })
    {
      for (const double y : { y0, y1 })
      {
        allOutside = allOutside && (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) < 0.0;
      }
    }
    if (allOutside)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
void vtkIceInteriorTiles::Update(vtkRenderer* renderer, vtkActor* actor,
  const vtkIceInteriorTable& interior, int width, int height, const int rect[4])
{
  // Tiles from a multiple of TileSize below the rectangle, so that 2 x 2 pixel quads (whose
  // derivatives the air's texture lookups take) never straddle two tiles.
  this->Origin[0] = rect[0] - rect[0] % TileSize;
  this->Origin[1] = rect[1] - rect[1] % TileSize;
  this->TilesAcross = std::max(1, (rect[2] - this->Origin[0] + TileSize - 1) / TileSize);
  this->TilesUp = std::max(1, (rect[3] - this->Origin[1] + TileSize - 1) / TileSize);
  const int tiles = this->TilesAcross * this->TilesUp;

  // Each record's tiles: those of its box's projected bounding rectangle (in tile units, clamped
  // to the grid) that its projected hull reaches.
  vtkMatrix4x4* worldToClip = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1.0, 1.0);
  std::vector<std::vector<std::array<double, 2>>> hulls;
  const int records = interior.GetNumberOfRecords();
  const int cracks = interior.GetNumberOfCracks();
  const int air = interior.GetNumberOfAirPlanes();
  std::vector<std::array<int, 4>> reach;
  std::vector<int> listed;
  vtkMatrix4x4* modelToWorld = actor->GetMatrix();
  for (int position = cracks; position < std::min(records, cracks + air); ++position)
  {
    double corners[24];
    interior.GetCorners(position, corners);
    for (int c = 0; c < 8; ++c)
    {
      double p[4] = { corners[3 * c], corners[3 * c + 1], corners[3 * c + 2], 1.0 };
      modelToWorld->MultiplyPoint(p, p);
      std::copy(p, p + 3, corners + 3 * c);
    }
    int covered[4];
    vtkIceScreenRegion::Projected(renderer, corners, 8, width, height, covered);
    std::array<int, 4> tileRange = {
      std::max(0, (covered[0] - this->Origin[0]) / TileSize),
      std::max(0, (covered[1] - this->Origin[1]) / TileSize),
      std::min(this->TilesAcross, (covered[2] - this->Origin[0] + TileSize - 1) / TileSize),
      std::min(this->TilesUp, (covered[3] - this->Origin[1] + TileSize - 1) / TileSize),
    };
    reach.push_back(tileRange);
    listed.push_back(position);
    hulls.push_back(ProjectedHull(worldToClip, corners, width, height));
  }
  const auto reaches = [&](size_t r, int tx, int ty) {
    const double x0 = this->Origin[0] + tx * TileSize - 1.0;
    const double y0 = this->Origin[1] + ty * TileSize - 1.0;
    return Meets(hulls[r], x0, y0, x0 + TileSize + 2.0, y0 + TileSize + 2.0);
  };

  // Count first (the stride is the longest list), then fill.
  std::vector<int> counts(static_cast<size_t>(tiles), 0);
  for (size_t r = 0; r < reach.size(); ++r)
  {
    for (int ty = reach[r][1]; ty < reach[r][3]; ++ty)
    {
      for (int tx = reach[r][0]; tx < reach[r][2]; ++tx)
      {
        counts[static_cast<size_t>(ty) * this->TilesAcross + tx] += reaches(r, tx, ty) ? 1 : 0;
      }
    }
  }
  int longest = 0;
  this->Entries = 0;
  for (int t = 0; t < tiles; ++t)
  {
    longest = std::max(longest, counts[t]);
    this->Entries += counts[t];
  }
  this->Stride = 1 + longest;
  // The lists one after the other, in rows of RowTexels (within every GPU's width limit).
  const size_t total = static_cast<size_t>(tiles) * this->Stride;
  const int rows = static_cast<int>((total + RowTexels - 1) / RowTexels);
  this->Texels.assign(static_cast<size_t>(rows) * RowTexels, 0.0f);
  std::vector<int> filled(static_cast<size_t>(tiles), 0);
  for (int t = 0; t < tiles; ++t)
  {
    this->Texels[static_cast<size_t>(t) * this->Stride] = static_cast<float>(counts[t]);
  }
  // Records in the table's order, so each tile's air stays back to front.
  for (size_t r = 0; r < reach.size(); ++r)
  {
    for (int ty = reach[r][1]; ty < reach[r][3]; ++ty)
    {
      for (int tx = reach[r][0]; tx < reach[r][2]; ++tx)
      {
        const size_t t = static_cast<size_t>(ty) * this->TilesAcross + tx;
        if (reaches(r, tx, ty))
        {
          this->Texels[t * this->Stride + 1 + filled[t]++] = static_cast<float>(listed[r]);
        }
      }
    }
  }

  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (!this->Lists || this->Lists->GetContext() != window)
  {
    this->Lists = vtkSmartPointer<vtkTextureObject>::New();
    this->Lists->SetContext(window);
    this->Lists->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Lists->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  this->Lists->Create2DFromRaw(RowTexels, rows, 1, VTK_FLOAT, this->Texels.data());
  this->Lists->Activate();
}

//------------------------------------------------------------------------------
void vtkIceInteriorTiles::SetUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("iceTileLists", this->Lists->GetTextureUnit());
  program->SetUniform2i("iceTileOrigin", this->Origin);
  program->SetUniformi("iceTilesAcross", this->TilesAcross);
  program->SetUniformi("iceTileStride", this->Stride);
}

//------------------------------------------------------------------------------
void vtkIceInteriorTiles::Finish()
{
  if (this->Lists)
  {
    this->Lists->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkIceInteriorTiles::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Lists)
  {
    this->Lists->ReleaseGraphicsResources(window);
    this->Lists = nullptr;
  }
}
