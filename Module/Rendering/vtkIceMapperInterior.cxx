// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceMapper's interior as vtkIcePass and its sub-passes ask for it: the paper's crack and air
// draws, and the screen-space interior's records and uniforms.
#include "vtkIceMapper.h"

#include "vtkIceInteriorLook.h"
#include "vtkIceInteriorSources.h"
#include "vtkIceInteriorTable.h"
#include "vtkIcePropertyUniforms.h"

#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

namespace
{
// What the interior's table needs beside the look and the bounds: the model's extent, the debug
// view (the cracks alone or the air alone) and whether the input is flat.
void PlaceInterior(vtkIceInteriorTable::Placement& placement, double extent, int view, bool flat)
{
  placement.Extent = extent;
  placement.Debug = view == vtkIceMapper::DebugCracksClipped ? vtkIceInteriorLook::DebugCracks
    : view == vtkIceMapper::DebugAir                         ? vtkIceInteriorLook::DebugAir
                                                             : vtkIceInteriorLook::DebugNone;
  placement.Flat = flat;
}
}

//------------------------------------------------------------------------------
void vtkIceMapper::DrawPaperCracks(vtkRenderer* ren, vtkActor* actor, bool overlay)
{
  const int view = this->DebugView;
  const bool debugCracks =
    view == vtkIceMapper::DebugCracksUnclipped || view == vtkIceMapper::DebugCracksClipped;
  const bool otherDebug = view == vtkIceMapper::DebugFrontDepth ||
    view == vtkIceMapper::DebugBackDepth || view == vtkIceMapper::DebugAir;
  if (otherDebug || (!overlay && (!this->CracksPerturbRefraction() || debugCracks)) ||
    (overlay && this->UsesScreenInterior()))
  {
    return;
  }
  vtkPolyData* geometry = this->GetCrackGeometry();
  if (!geometry || geometry->GetNumberOfPolys() == 0)
  {
    return;
  }
  const bool unclipped = view == vtkIceMapper::DebugCracksUnclipped;
  vtkIcePaperInterior::CrackLook look;
  look.ClipToInterval =
    this->UsableCrackClipping() == vtkIcePaperInterior::DepthInterval && !unclipped;
  look.Debug = debugCracks;
  look.Unclipped = unclipped;
  look.Intensity = this->GetIceProperty()->GetCrackIntensity();
  look.BumpFrequency = vtkIceInteriorLook::CrackBumpFrequency(this->InputExtent());
  this->HelpersSawPass = true;
  this->GetPaperInterior()->DrawCracks(ren, actor, geometry, look, overlay);
  ++this->NumberOfCrackDraws;
}

//------------------------------------------------------------------------------
void vtkIceMapper::DrawPaperAir(vtkRenderer* ren, vtkActor* actor)
{
  const int view = this->DebugView;
  const bool debugAir = view == vtkIceMapper::DebugAir;
  vtkIceProperty* look = this->GetIceProperty();
  if (look->GetNumberOfAirPlanes() == 0 || (view != vtkIceMapper::DebugOff && !debugAir) ||
    this->UsesScreenInterior())
  {
    return;
  }
  vtkPolyData* input = this->GetInput();
  if (!input || !this->PrepareInput(input))
  {
    return;
  }
  this->HelpersSawPass = true;
  double bounds[6];
  this->GetLookBounds(bounds);
  this->GetPaperInterior()->DrawAir(ren, actor, this->PreparedInput, bounds,
    look->GetNumberOfAirPlanes(), look->GetAirSeed(), look->GetMilkiness(), debugAir);
}

//------------------------------------------------------------------------------
const vtkIceInteriorTable* vtkIceMapper::BeginScreenInterior(
  vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program)
{
  vtkPolyData* input = this->GetInput();
  if (!input || !this->PrepareInput(input))
  {
    return nullptr;
  }
  this->BindEnvironment(ren, actor);
  this->PrepareInterior(ren, actor);
  this->SetScreenInteriorUniforms(ren, actor, program);
  return this->InteriorTable.get();
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetScreenInteriorUniforms(
  vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program)
{
  this->SetCameraUniforms(program, ren, actor);
  vtkIcePropertyUniforms::Set(this->GetIceProperty(), program);
  this->SetEnvironmentUniforms(program);
  this->InteriorTable->SetUniforms(program);
}

//------------------------------------------------------------------------------
void vtkIceMapper::EndScreenInterior(vtkRenderer* ren)
{
  this->FinishInterior(ren);
  this->UnbindEnvironment(ren);
}

//------------------------------------------------------------------------------
void vtkIceMapper::PrepareInterior(vtkRenderer* ren, vtkActor* act)
{
  if (!this->InteriorPrepared)
  {
    vtkIceInteriorTable::Placement placement;
    this->GetLookBounds(placement.Bounds);
    PlaceInterior(placement, this->InputExtent(), this->DebugView, this->InputFlat);
    this->InteriorTable->Prepare(ren, act, this->PreparedInput, this->IceProperty, placement,
      this->Interior->GetAirAtlas(this->IceProperty->GetAirSeed()));
    this->InteriorPrepared = true;
  }
}

//------------------------------------------------------------------------------
bool vtkIceMapper::TracesInteriorLook() const
{
  return this->TracesInterior() && this->InteriorMethod == InteriorScreenSpace &&
    this->DebugView == DebugOff && !this->InputFlat;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::TracesCracks() const
{
  vtkIceProperty* look = this->IceProperty.Get();
  return this->TracesInteriorLook() && look->GetNumberOfCracks() > 0 &&
    look->GetCrackIntensity() * look->GetCrackReflection() > 0.0;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::TracesBubbles() const
{
  return this->TracesInteriorLook() && this->IceProperty->GetBubbleDensity() > 0.0;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::TracesAir() const
{
  return this->TracesInteriorLook() && this->IceProperty->GetNumberOfAirPlanes() > 0;
}

//------------------------------------------------------------------------------
void vtkIceMapper::PrepareTraceInterior(
  vtkRenderer* ren, vtkShaderProgram* program, vtkTextureObject* active[4])
{
  vtkIceInteriorTable::Placement placement;
  this->GetLookBounds(placement.Bounds);
  PlaceInterior(placement, this->InputExtent(), this->DebugView, this->InputFlat);
  if (program->IsUniformUsed("iceBubbleCell") || program->IsUniformUsed("iceAirCount"))
  {
    this->InteriorTable->PrepareTraceAir(ren, this->PreparedInput, this->IceProperty, placement,
      program, active,
      this->TracesAir() ? this->Interior->GetAirAtlas(this->IceProperty->GetAirSeed()) : nullptr);
  }
  else
  {
    this->InteriorTable->PrepareCracks(
      ren, this->PreparedInput, this->IceProperty, placement, program, active);
  }
  if (program->IsUniformUsed("iceTraceCrackShare"))
  {
    program->SetUniformf("iceTraceCrackShare", static_cast<float>(this->IceProperty->GetCrackIntensity() *
      this->IceProperty->GetCrackReflection()));
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::FinishInterior(vtkRenderer* ren)
{
  if (this->InteriorPrepared)
  {
    this->InteriorTable->Finish(ren);
    this->InteriorPrepared = false;
  }
}
