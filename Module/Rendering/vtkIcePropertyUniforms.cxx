// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIcePropertyUniforms.h"

#include "vtkIcePrefilteredEnvironment.h"
#include "vtkIceProperty.h"

#include "vtkShaderProgram.h"

//------------------------------------------------------------------------------
void vtkIcePropertyUniforms::Set(vtkIceProperty* property, vtkShaderProgram* program)
{
  for (const vtkIceProperty::ShaderValue& value : property->GetShaderValues())
  {
    if (value.Optional && !program->IsUniformUsed(value.Name))
    {
      continue;
    }
    if (value.Components == 3)
    {
      program->SetUniform3f(value.Name, value.Value);
    }
    else
    {
      program->SetUniformf(value.Name, value.Value[0]);
    }
  }
  // The level is the prefiltered environment's mip layout, not the look's.
  if (program->IsUniformUsed("iceRoughnessLevel"))
  {
    program->SetUniformf("iceRoughnessLevel",
      static_cast<float>(vtkIcePrefilteredEnvironment::LevelOf(property->GetRoughness())));
  }
  if (program->IsUniformUsed("iceRoughnessAlpha"))
  {
    const double roughness = property->GetRoughness();
    program->SetUniformf("iceRoughnessAlpha", static_cast<float>(roughness * roughness));
  }
}
