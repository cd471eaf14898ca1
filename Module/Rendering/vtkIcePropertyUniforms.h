// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Sets a vtkIceProperty's uniforms on a program of the mapper's or of the screen-space interior:
// every value of the property's GetShaderValues (so that a new parameter of that kind touches
// the property and the look table only), and the prefiltered environment's level of the
// property's Roughness. Inside the module: not wrapped.
#ifndef vtkIcePropertyUniforms_h
#define vtkIcePropertyUniforms_h

class vtkIceProperty;
class vtkShaderProgram;

class vtkIcePropertyUniforms
{
public:
  static void Set(vtkIceProperty* property, vtkShaderProgram* program);
};

#endif
