// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The ground the ice stands on in a photographed environment: a disc of stone under the model,
// coloured as the panorama's own ground, with its soft contact shadow, fading into the panorama at
// its rim.
#ifndef IceGround_h
#define IceGround_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkTexture;

namespace IceGround
{
// How dark the ground is under `model` (its triangles, y up), standing on the plane at the
// model's lowest y: the texels of a square of half size `halfSize` around the origin in x and
// z, `texels` a side, 0 (open ground) to 1 (what the ice's bottom covers), softened with the
// distance a surface lies above the plane, none well under the ice; (the second component) how
// wet the ground is around the ice's foot, 0 to 1, with an uneven edge and a trickle running off;
// and (the third) the light the ice gathers on the ground under it, 0 to 1. Three components,
// double.
vtkSmartPointer<vtkImageData> ContactShadow(vtkPolyData* model, double halfSize, int texels);

// The mean colour of faces of a cube-map environment (OpenGL's order: +X, -X, +Y, -Y, +Z, -Z; -Y is
// the ground it shows, the four sides its horizon), as displayed: gamma-corrected where the
// environment holds linear light (HDR), as the skybox shows it. Grey where it has no such faces.
void EnvironmentColour(vtkTexture* environment, const std::vector<int>& faces, double colour[3]);

// A ground actor at the model's lowest y: stone of `colour` (as displayed, red, green, blue in
// [0, 1]) with a grain, unlit (ambient only, so lights meant for the scene do not brighten it
// twice), darkened by ContactShadow, wet around the ice's foot (darker, with a sheen of `sheen`,
// what the water mirrors) and fading out towards its rim.
vtkSmartPointer<vtkActor> MakeGround(
  vtkPolyData* model, const double colour[3], const double sheen[3]);
}

#endif
