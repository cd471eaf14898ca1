// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceScreenRegion.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkIceScreenRegion
{
//------------------------------------------------------------------------------
void Covered(const vtkRenderState* s, int width, int height, int rect[4])
{
  Covered(s->GetRenderer(), s->GetPropArray(), s->GetPropArrayCount(), width, height, rect);
}

//------------------------------------------------------------------------------
void Covered(
  vtkRenderer* renderer, vtkProp* const* props, int count, int width, int height, int rect[4])
{
  std::vector<double> corners;
  for (int i = 0; i < count; ++i)
  {
    const double* b = props[i]->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      rect[0] = 0;
      rect[1] = 0;
      rect[2] = width;
      rect[3] = height;
      return;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      corners.insert(
        corners.end(), { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)] });
    }
  }
  Projected(renderer, corners.data(), count * 8, width, height, rect);
}

//------------------------------------------------------------------------------
void Projected(
  vtkRenderer* renderer, const double* points, int count, int width, int height, int rect[4])
{
  rect[0] = 0;
  rect[1] = 0;
  rect[2] = width;
  rect[3] = height;
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (window && (window->GetTileScale()[0] != 1 || window->GetTileScale()[1] != 1))
  {
    return;
  }
  // The projection the mappers use (vtkOpenGLCamera::GetKeyMatrices): world to clip space.
  vtkMatrix4x4* worldToClip = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1.0, 1.0);
  double lower[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double upper[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < count; ++i)
  {
    const double p[4] = { points[3 * i], points[3 * i + 1], points[3 * i + 2], 1.0 };
    double clip[4];
    worldToClip->MultiplyPoint(p, clip);
    // At or behind the plane of the eye the points may project anywhere.
    if (!(clip[3] > 1e-6 * (std::abs(clip[0]) + std::abs(clip[1]) + std::abs(clip[2]))))
    {
      return;
    }
    for (int k = 0; k < 2; ++k)
    {
      const double ndc = clip[k] / clip[3];
      lower[k] = std::min(lower[k], ndc);
      upper[k] = std::max(upper[k], ndc);
    }
  }
  if (count == 0)
  {
    rect[2] = rect[0];
    rect[3] = rect[1];
    return;
  }
  const int size[2] = { width, height };
  for (int k = 0; k < 2; ++k)
  {
    // NDC -1..1 spans pixels 0..size; two pixels of margin for rounding and multisampling.
    const double from = std::floor(0.5 * (lower[k] + 1.0) * size[k]) - 2.0;
    const double to = std::ceil(0.5 * (upper[k] + 1.0) * size[k]) + 2.0;
    rect[k] = static_cast<int>(std::max(0.0, std::min(from, static_cast<double>(size[k]))));
    rect[k + 2] = static_cast<int>(std::max(0.0, std::min(to, static_cast<double>(size[k]))));
    rect[k + 2] = std::max(rect[k + 2], rect[k]);
  }
}

//------------------------------------------------------------------------------
void Tracker::ToClear(const int drawn[4], int width, int height, int rect[4])
{
  if (!this->Known || width != this->Width || height != this->Height)
  {
    rect[0] = 0;
    rect[1] = 0;
    rect[2] = width;
    rect[3] = height;
  }
  else
  {
    rect[0] = std::min(drawn[0], this->Last[0]);
    rect[1] = std::min(drawn[1], this->Last[1]);
    rect[2] = std::max(drawn[2], this->Last[2]);
    rect[3] = std::max(drawn[3], this->Last[3]);
  }
  this->Known = true;
  this->Width = width;
  this->Height = height;
  std::copy(drawn, drawn + 4, this->Last);
}
}
