// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceBackfaceNormalPass.h"

#include "vtkIceBackfaceNormalFS.h"
#include "vtkIceMapperAccess.h"
#include "vtkIceScreenTarget.h"
#include "vtkIceShaderSections.h"

#include "vtkActor.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkIceVTKCompat.h"

vtkStandardNewMacro(vtkIceBackfaceNormalPass);

//------------------------------------------------------------------------------
vtkIceBackfaceNormalPass::vtkIceBackfaceNormalPass()
  : Target(new vtkIceScreenTarget)
{
}

//------------------------------------------------------------------------------
vtkIceBackfaceNormalPass::~vtkIceBackfaceNormalPass() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceBackfaceNormalPass::GetNormalTexture()
{
  return this->Target->GetColorTexture();
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkIceScreenTarget::Drawing drawing(*this->Target, s, 4);
  drawing.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  drawing.ClearDepth(1.0);

  this->PreRender(s);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    this->NumberOfRenderedProps += s->GetPropArray()[i]->RenderOpaqueGeometry(renderer);
  }
  // Cracks that perturb the refraction stand in for the back face where they are nearer.
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (vtkIceMapper* mapper = vtkIceMapperAccess::Of(prop))
    {
      mapper->DrawPaperCracks(renderer, static_cast<vtkActor*>(prop), false);
    }
  }
  this->PostRender(s);
  ++this->NumberOfGeometryPasses;
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkIceBackfaceNormalPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  vtkIceShaderSections::FillHook(
    fragmentShader, "Output", vtkIceShaderSections::Get(vtkIceBackfaceNormalFS, "Impl"));
  vtkIceShaderSections::FillHook(
    fragmentShader, "CrackOutput", vtkIceShaderSections::Get(vtkIceBackfaceNormalFS, "Crack"));
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceBackfaceNormalPass::SetShaderParameters(
  vtkShaderProgram*, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  // Only back faces are wanted: culled in OpenGL rather than rasterised and discarded (the
  // shader still discards front faces; none reach it). Cracks drawn here stay unculled.
  if (vtkIceMapper::SafeDownCast(mapper))
  {
    this->Target->Cull(GL_FRONT);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Target->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalTexture: " << this->Target->GetColorTexture() << "\n";
}
