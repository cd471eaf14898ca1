#include "vtkIceGlistening.h"

#include "vtkIceGlisteningFS.h"
#include "vtkIceShaderSections.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <sstream>

namespace vtkIceGlistening
{
namespace
{
// VTK uploads a vtkMatrix4x4 as is; GLSL reads it column by column, so the transpose of a matrix
// gives the GLSL matrix that multiplies column vectors like the VTK one.
void SetMatrix(vtkShaderProgram* program, const char* name, vtkMatrix4x4* matrix)
{
  vtkNew<vtkMatrix4x4> transposed;
  vtkMatrix4x4::Transpose(matrix, transposed);
  program->SetUniformMatrix(name, transposed);
}
}

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
    lights << "      iceGlisteningAddLight(glisten, normalize(mat3(iceGlisteningVCWC) * vec3(0.0, "
              "0.0, 1.0)), lightColor0, glistenSums);\n";
  }
  else if (lightComplexity == 2)
  {
    for (int i = 0; i < lightCount; ++i)
    {
      lights << "      iceGlisteningAddLight(glisten, -normalize(mat3(iceGlisteningVCWC) * "
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
void SetUniforms(
  vtkShaderProgram* program, vtkRenderer* renderer, vtkActor* actor, const Parameters& parameters)
{
  program->SetUniformi("iceGlisteningNoise", parameters.NoiseTextureUnit);
  program->SetUniformf("iceGlisteningScale", static_cast<float>(parameters.Scale));
  program->SetUniformf("iceGlisteningIntensity", static_cast<float>(parameters.Intensity));
  program->SetUniformf("iceGlisteningAlignmentGain", static_cast<float>(parameters.AlignmentGain));
  program->SetUniformf("iceSnowAmount", static_cast<float>(parameters.SnowAmount));

  vtkNew<vtkMatrix4x4> worldToModel;
  vtkMatrix4x4::Invert(actor->GetMatrix(), worldToModel);
  SetMatrix(program, "iceGlisteningWCMC", worldToModel);

  // VTK's light uniforms are in the view space of GetModelViewTransformMatrix.
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(renderer->GetActiveCamera()->GetModelViewTransformMatrix(), viewToWorld);
  SetMatrix(program, "iceGlisteningVCWC", viewToWorld);
}
}
