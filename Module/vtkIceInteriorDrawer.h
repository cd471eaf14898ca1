// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Draws an ice prop's cracks and air planes as separate geometry for vtkIcePass and its back-face
// sub-pass: the paper's passes, the crack and air debug views, cracks in the back-face normals;
// and readies the screen-space interior's program for a prop (vtkIceScreenInterior).
// What to draw is the prop's mapper's (its debug view, interior method, look and input); the
// drawing is its vtkIceInterior's. Not the mapper's public API, neither wrapped nor installed:
// the mapper grants its state to this class. Inside the module.
#ifndef vtkIceInteriorDrawer_h
#define vtkIceInteriorDrawer_h

class vtkActor;
class vtkIceMapper;
class vtkIceInteriorTable;
class vtkRenderer;
class vtkShaderProgram;

class vtkIceInteriorDrawer
{
public:
  // The cracks of `actor`. `overlay`: over the rendered scene, with additive blending; otherwise
  // with the current state (into the back-face normal texture, CracksPerturbRefraction).
  static void DrawCracks(vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor, bool overlay);

  // The air planes of `actor` over the rendered scene, back to front for the camera.
  static void DrawAir(vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor);

  // The interior's table, textures, environment and look of `actor` ready for `program` (the
  // screen-space interior's), until EndScreenInterior; returns the interior prepared, or null
  // (nothing readied, no EndScreenInterior) when the mapper has no input it draws.
  static const vtkIceInteriorTable* BeginScreenInterior(
    vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program);
  static void EndScreenInterior(vtkIceMapper* mapper, vtkRenderer* ren);
};

#endif
