// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The uniforms of a vtkIceProperty's parameters that the surface's shaders read directly, set
// beside the parameters themselves (vtkIceProperty.cxx), so that a new parameter of that kind
// touches the property, its GLSL and the look table only. Inside the module: not wrapped.
#ifndef vtkIcePropertyUniforms_h
#define vtkIcePropertyUniforms_h

class vtkIceProperty;
class vtkShaderProgram;

class vtkIcePropertyUniforms
{
public:
  // iceTint, iceRefractionRatio, iceAttenuationColor, iceInverseAttenuationDistance,
  // iceFresnelPower, and where the program has them iceBackNormalWeight, iceBumpStrength,
  // iceRoughnessLevel.
  static void Set(vtkIceProperty* property, vtkShaderProgram* program);
};

#endif
