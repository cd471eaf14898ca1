// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCrackMapper.h"

#include "vtkIceCrackFS.h"
#include "vtkIceValueNoise.h"
#include "vtkIceShaderSections.h"

#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkIceCrackMapper);

//------------------------------------------------------------------------------
vtkIceCrackMapper::vtkIceCrackMapper() = default;

//------------------------------------------------------------------------------
vtkIceCrackMapper::~vtkIceCrackMapper() = default;

//------------------------------------------------------------------------------
void vtkIceCrackMapper::AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer*, vtkActor*)
{
  using vtkIceShaderSections::Get;
  parts.FragmentDeclarations += Get(vtkIceValueNoise, "Dec") + Get(vtkIceCrackFS, "Dec");
  // The bump mapping tilts VTK's lighting normal, which the shader has only when the actor is lit:
  // before a renderer's first frame has created its automatic light, cracks drawn into the
  // back-face pass are not (and show no highlight anyway).
  const bool lit = this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity > 0;
  parts.FragmentNormalImpl +=
    Get(vtkIceCrackFS, "Interval") + (lit ? Get(vtkIceCrackFS, "Normal") : std::string());
  parts.FragmentImpl += Get(vtkIceCrackFS, "Impl");
}

//------------------------------------------------------------------------------
void vtkIceCrackMapper::SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer*, vtkActor*)
{
  program->SetUniformi("iceCrackClip", this->ClipToInterval ? 1 : 0);
  program->SetUniformi("iceCrackDebug", this->DebugColor ? 1 : 0);
  program->SetUniformf("iceCrackIntensity", static_cast<float>(this->Intensity));
  program->SetUniformf("iceBumpStrength", static_cast<float>(this->BumpStrength));
  program->SetUniformf("iceBumpFrequency", static_cast<float>(this->BumpFrequency));
}

//------------------------------------------------------------------------------
void vtkIceCrackMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ClipToInterval: " << this->ClipToInterval << "\n";
  os << indent << "DebugColor: " << this->DebugColor << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "BumpStrength: " << this->BumpStrength << "\n";
  os << indent << "BumpFrequency: " << this->BumpFrequency << "\n";
}
