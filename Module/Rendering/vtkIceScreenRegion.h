// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the part of a viewport-sized texture that the ice sub-passes draw into,
// so that they clear only that part instead of the whole viewport every frame.
#ifndef vtkIceScreenRegion_h
#define vtkIceScreenRegion_h

class vtkProp;
class vtkRenderState;
class vtkRenderer;

namespace vtkIceScreenRegion
{
// Pixel rectangle { x0, y0, x1, y1 } (x1, y1 exclusive) of the renderer's viewport, `width` x
// `height`, that holds every pixel the props of `s` can cover: their bounding boxes projected
// with the renderer's active camera, two pixels wider on each side. The whole viewport when a
// box reaches behind the camera, the window is tiled, or a prop has no bounds.
void Covered(const vtkRenderState* s, int width, int height, int rect[4]);
void Covered(
  vtkRenderer* renderer, vtkProp* const* props, int count, int width, int height, int rect[4]);
// The same rectangle for `count` world points (x, y, z after each other): the pixels their
// convex hull can cover.
void Projected(
  vtkRenderer* renderer, const double* points, int count, int width, int height, int rect[4]);

// Tracks which part of a viewport-sized texture may hold anything but its clear value.
class Tracker
{
public:
  // The texture's contents are unknown (new, resized): the next Clear covers all of it.
  void Reset() { this->Known = false; }

  // The rectangle to clear before drawing inside `drawn` this frame: `drawn` together with what
  // was drawn in the frame before, or the whole texture. Remembers `drawn` for the next frame.
  void ToClear(const int drawn[4], int width, int height, int rect[4]);

private:
  bool Known = false;
  int Width = 0;
  int Height = 0;
  int Last[4] = { 0, 0, 0, 0 };
};
}

#endif
