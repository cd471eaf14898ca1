// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceDepthIntervalPass.h"

#include "vtkIceDepthIntervalFS.h"
#include "vtkIceMapper.h"
#include "vtkIceScreenTarget.h"
#include "vtkIceShaderSections.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <cfloat>

vtkStandardNewMacro(vtkIceDepthIntervalPass);

namespace
{
// View-depth range of the props' bounding boxes, for the camera at `eye` looking along `direction`.
bool FitDepthRange(
  const vtkRenderState* s, const double eye[3], const double direction[3], double range[2])
{
  range[0] = VTK_DOUBLE_MAX;
  range[1] = -VTK_DOUBLE_MAX;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    const double* b = s->GetPropArray()[i]->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      const double p[3] = { b[corner & 1] - eye[0], b[2 + ((corner >> 1) & 1)] - eye[1],
        b[4 + ((corner >> 2) & 1)] - eye[2] };
      const double depth = vtkMath::Dot(p, direction);
      range[0] = std::min(range[0], depth);
      range[1] = std::max(range[1], depth);
    }
  }
  return range[0] <= range[1];
}
}

//------------------------------------------------------------------------------
vtkIceDepthIntervalPass::vtkIceDepthIntervalPass()
  : Target(new vtkIceScreenTarget)
{
}

//------------------------------------------------------------------------------
vtkIceDepthIntervalPass::~vtkIceDepthIntervalPass() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceDepthIntervalPass::GetDepthTexture()
{
  return this->Target->GetColorTexture();
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceDepthIntervalPass::GetDepthBufferTexture()
{
  return this->Target->GetDepthTexture();
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkCamera* camera = renderer->GetActiveCamera();

  // The texture stores linear view depth, so the user's near and far planes serve the depth test
  // as they are: where two faces tie within the depth buffer's precision, the depths stored for
  // either differ by as little. The camera is never touched (its observers would re-render).
  FitDepthRange(s, camera->GetPosition(), camera->GetDirectionOfProjection(), this->DepthRange);

  {
    vtkIceScreenTarget::Drawing drawing(*this->Target, s, 4);
    vtkOpenGLState* state = drawing.State;
    // Empty interval where there is no ice: front beyond back.
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    drawing.ClearColor(FLT_MAX, -FLT_MAX, 0.0f, 0.0f);

    this->PreRender(s);
    // Stage 0: nearest front face into R, its normal into B and A. Stage 1: farthest back face
    // into G.
    for (this->Stage = 0; this->Stage < (this->FrontOnly ? 1 : 2); ++this->Stage)
    {
      const bool front = this->Stage == 0;
      state->vtkglColorMask(front, !front, front, front);
      drawing.ClearDepth(front ? 1.0 : 0.0);
      state->vtkglDepthFunc(front ? GL_LESS : GL_GREATER);
      for (int i = 0; i < s->GetPropArrayCount(); ++i)
      {
        this->NumberOfRenderedProps += s->GetPropArray()[i]->RenderOpaqueGeometry(renderer);
      }
      ++this->NumberOfGeometryPasses;
    }
    this->Stage = 0;
    this->PostRender(s);
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkIceDepthIntervalPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  vtkIceShaderSections::InsertDeclarations(fragmentShader,
    vtkIceShaderSections::Get(vtkIceDepthIntervalFS, "Normal") +
      vtkIceShaderSections::Get(vtkIceDepthIntervalFS, "Dec"));
  vtkIceShaderSections::FillHook(
    fragmentShader, "Output", vtkIceShaderSections::Get(vtkIceDepthIntervalFS, "Impl"));
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceDepthIntervalPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  // Stage 0 wants front faces, stage 1 back faces: the others are culled in OpenGL rather than
  // rasterised and discarded (the shader still discards them; none reach it).
  if (vtkIceMapper::SafeDownCast(mapper))
  {
    this->Target->Cull(this->Stage == 0 ? GL_BACK : GL_FRONT);
  }
  if (program->IsUniformUsed("iceDepthStage"))
  {
    program->SetUniformi("iceDepthStage", this->Stage);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Target->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthRange: " << this->DepthRange[0] << ", " << this->DepthRange[1] << "\n";
  os << indent << "FrontOnly: " << this->FrontOnly << "\n";
  os << indent << "NumberOfGeometryPasses: " << this->NumberOfGeometryPasses << "\n";
}
