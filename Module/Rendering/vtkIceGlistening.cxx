// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceGlistening.h"

#include "vtkIceGlisteningFS.h"
#include "vtkIceProperty.h"
#include "vtkIceShaderSections.h"

#include "vtkShaderProgram.h"

#include <sstream>

namespace vtkIceGlistening
{
//------------------------------------------------------------------------------
std::string Declarations()
{
  return vtkIceShaderSections::Get(vtkIceGlisteningFS, "Dec");
}

//------------------------------------------------------------------------------
std::string Code(int lightComplexity, int lightCount)
{
  std::ostringstream lights;
  if (lightComplexity == 1 && lightCount > 0)
  {
    // VTK's headlight shines along the view direction: towards the light is +z in view space.
    lights << "      iceGlisteningAddLight(glisten, normalize(mat3(iceVCWCMatrix) * vec3(0.0, "
              "0.0, 1.0)), lightColor0, glistenSums);\n";
  }
  else if (lightComplexity == 2)
  {
    for (int i = 0; i < lightCount; ++i)
    {
      lights << "      iceGlisteningAddLight(glisten, -normalize(mat3(iceVCWCMatrix) * "
                "lightDirectionVC"
             << i << "), lightColor" << i << ", glistenSums);\n";
    }
  }
  else if (lightComplexity == 3)
  {
    for (int i = 0; i < lightCount; ++i)
    {
      lights << "      iceGlisteningAddSceneLight(glisten, icePositionWCVSOutput, lightPositional"
             << i << ", lightDirectionVC" << i << ", lightPositionVC" << i << ", lightAttenuation"
             << i << ", lightConeAngle" << i << ", lightExponent" << i << ", lightColor" << i
             << ", glistenSums);\n";
    }
  }
  std::string code = vtkIceShaderSections::Get(vtkIceGlisteningFS, "Impl");
  vtkShaderProgram::Substitute(code, "//ICEHOOK::GlisteningLights", lights.str());
  return code;
}

//------------------------------------------------------------------------------
void SetUniforms(vtkShaderProgram* program, vtkIceProperty* look, int noiseTextureUnit)
{
  program->SetUniformi("iceGlisteningNoise", noiseTextureUnit);
  program->SetUniformf("iceGlisteningScale", static_cast<float>(look->GetGlisteningScale()));
  program->SetUniformf(
    "iceGlisteningIntensity", static_cast<float>(look->GetGlisteningIntensity()));
  program->SetUniformf(
    "iceGlisteningAlignmentGain", static_cast<float>(look->GetGlisteningAlignmentGain()));
  program->SetUniformf("iceSnowAmount", static_cast<float>(look->GetSnowAmount()));
}
}
