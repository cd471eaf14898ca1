// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: properties of an ice mapper's input that decide what the ice can do
// with it (vtkIceMapper warns about them once per input).
#ifndef vtkIceSurfaceCheck_h
#define vtkIceSurfaceCheck_h

#include "vtkType.h"

#include <string> // for FindInputProblem

class vtkPoints;
class vtkPolyData;

namespace vtkIceSurfaceCheck
{
// Why `input` cannot be drawn as ice, in one sentence, or "" when it can: no polygons, NaN or
// infinite coordinates, a cell naming a point that does not exist, a polygon or strip of fewer
// than three points, all points in one place, or point arrays shorter than the points. Linear in
// the size of the input; VTK's filters (normals, bounds, cell links) read out of bounds on the
// broken cases, so this runs before any of them.
std::string FindInputProblem(vtkPolyData* input);

// The spread of the points across their flattest direction (the principal axis of least
// variance), `thickness`, and along their longest one, `size`. A flat input (all points in one
// plane, in any orientation) has a thickness of 0 up to rounding.
void Extents(vtkPoints* points, double& thickness, double& size);

// Whether Extents says the points have no volume: thickness at most 1e-5 of the size.
bool IsFlat(double thickness, double size);

// The number of edges of the surface's polygons and strips that only one polygon uses, once
// coincident points are merged (within 1e-6 of the bounding box's diagonal, so that seams with
// duplicated points count as joined): 0 for a closed surface.
vtkIdType CountOpenEdges(vtkPolyData* surface);

// How the surface encloses a volume, points merged as for CountOpenEdges: its open edges, its
// edges where the faces on either side disagree about which side is outside (or more than two
// faces meet), and its connected parts whose faces (counter-clockwise seen from outside) face
// inward (negative signed volume). All 0: every view ray from outside first meets a front face.
struct Closure
{
  vtkIdType OpenEdges = 0;
  vtkIdType MisorientedEdges = 0;
  vtkIdType InwardComponents = 0;
  vtkIdType OutwardComponents = 0; // positive signed volume
  bool IsClosedOutward() const
  {
    return OpenEdges == 0 && MisorientedEdges == 0 && InwardComponents == 0;
  }
};
Closure CheckClosure(vtkPolyData* surface);
}

#endif
