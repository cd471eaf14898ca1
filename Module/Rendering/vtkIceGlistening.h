// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The glistening layer of vtkIceMapper (Liquidiced's ice and snow): composes its fragment shader
// code for VTK's lights and sets its uniforms. Private to the module.
#ifndef vtkIceGlistening_h
#define vtkIceGlistening_h

#include <string>

class vtkActor;
class vtkIceProperty;
class vtkRenderer;
class vtkShaderProgram;

namespace vtkIceGlistening
{
// Declarations to append to the ice fragment shader's.
std::string Declarations();

// The code for the hook //ICEHOOK::Glistening of the ice fragment shader: one light call per light
// of VTK's light loop for `lightComplexity` (0: no lighting, 1: headlight, 2: directional lights,
// 3: positional lights) and `lightCount`, reading VTK's light uniforms (lightColor0,
// lightDirectionVC0, ...).
std::string Code(int lightComplexity, int lightCount);

// Sets the layer's uniforms from `look` and the noise texture's unit (vtkIceWorldSpaceMapper sets
// the matrices it reads).
void SetUniforms(vtkShaderProgram* program, vtkIceProperty* look, int noiseTextureUnit);
}

#endif
