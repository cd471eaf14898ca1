// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceAirMapper.h"

#include "vtkIceAirFS.h"
#include "vtkIceAirVS.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceInteriorLookFS.h"
#include "vtkIceShaderSections.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkIceAirMapper);

//------------------------------------------------------------------------------
vtkIceAirMapper::vtkIceAirMapper()
{
  this->MapDataArrayToVertexAttribute(
    "iceAirUVMC", "vtkIceAirUV", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkIceAirMapper::~vtkIceAirMapper() = default;

//------------------------------------------------------------------------------
void vtkIceAirMapper::SetAirTexture(vtkTexture* texture)
{
  if (this->AirTexture != texture)
  {
    this->AirTexture = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceAirMapper::GetAirTexture()
{
  return this->AirTexture;
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  if (this->AirTexture)
  {
    this->AirTexture->Render(ren);
  }
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  if (this->AirTexture)
  {
    this->AirTexture->PostRender(ren);
  }
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer*, vtkActor*)
{
  using vtkIceShaderSections::Get;
  parts.VertexDeclarations += Get(vtkIceAirVS, "Dec");
  parts.VertexImpl += Get(vtkIceAirVS, "Impl");
  parts.FragmentDeclarations +=
    vtkIceInteriorLook::Defines() + Get(vtkIceInteriorLookFS, "Dec") + Get(vtkIceAirFS, "Dec");
  parts.FragmentImpl += Get(vtkIceAirFS, "Impl");
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer*, vtkActor*)
{
  if (this->AirTexture)
  {
    program->SetUniformi("iceAirAtlas", this->AirTexture->GetTextureUnit());
  }
  program->SetUniformf("iceMilkiness", static_cast<float>(this->Milkiness));
  program->SetUniformi("iceAirDebug", this->DebugColor ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->AirTexture)
  {
    this->AirTexture->ReleaseGraphicsResources(win);
  }
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkIceAirMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Milkiness: " << this->Milkiness << "\n";
  os << indent << "DebugColor: " << this->DebugColor << "\n";
}
