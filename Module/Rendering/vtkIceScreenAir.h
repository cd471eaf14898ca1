// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The air planes of the screen-space interior (vtkIceScreenInterior): each plane of the interior
// table drawn as its own quad into the interior's target, in the table's order (back to front),
// composed over what the target holds (vec4(add, keep), as the quads before and after it). A
// plane's fragment adds its bubbles where it lies between the pixel's front and back faces
// (iceAirPlane): the pixels a plane covers pay for it, where a per-pixel loop paid for every
// plane near them. Inside the module.
#ifndef vtkIceScreenAir_h
#define vtkIceScreenAir_h

#include "vtkSmartPointer.h"

#include <string>

class vtkActor;
class vtkIceInteriorTable;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkWindow;

class vtkIceScreenAir
{
public:
  vtkIceScreenAir();
  ~vtkIceScreenAir();

  // The planes' program with the screen-space interior's declarations (the quad's, which set
  // the same uniforms), ready to draw; null where it failed to compile.
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, const std::string& declarations);
  // Draws the air planes of `interior` (prepared for `actor`) with the program Ready returned,
  // its uniforms set.
  void Draw(vtkActor* actor, const vtkIceInteriorTable& interior, vtkShaderProgram* program);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLVertexArrayObject> Quads;
  vtkShaderProgram* Program = nullptr; // the one Quads was set up for (compared only)

  vtkIceScreenAir(const vtkIceScreenAir&) = delete;
  void operator=(const vtkIceScreenAir&) = delete;
};

#endif
