// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceInteriorDrawer.h"

#include "vtkIceInterior.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceInteriorTable.h"
#include "vtkIceMapper.h"
#include "vtkIcePropertyUniforms.h"

#include "vtkPolyData.h"

//------------------------------------------------------------------------------
void vtkIceInteriorDrawer::DrawCracks(
  vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor, bool overlay)
{
  const int view = mapper->DebugView;
  const bool debugCracks =
    view == vtkIceMapper::DebugCracksUnclipped || view == vtkIceMapper::DebugCracksClipped;
  const bool otherDebug = view == vtkIceMapper::DebugFrontDepth ||
    view == vtkIceMapper::DebugBackDepth || view == vtkIceMapper::DebugAir;
  if (otherDebug || (!overlay && (!mapper->CracksPerturbRefraction || debugCracks)) ||
    (overlay && mapper->UsesScreenInterior()))
  {
    return;
  }
  vtkPolyData* geometry = mapper->GetCrackGeometry();
  if (!geometry || geometry->GetNumberOfPolys() == 0)
  {
    return;
  }
  const bool unclipped = view == vtkIceMapper::DebugCracksUnclipped;
  vtkIceInterior::CrackLook look;
  look.ClipToInterval = mapper->UsableCrackClipping() == vtkIceMapper::DepthInterval && !unclipped;
  look.Debug = debugCracks;
  look.Unclipped = unclipped;
  look.Intensity = mapper->GetIceProperty()->GetCrackIntensity();
  look.BumpFrequency = vtkIceInteriorLook::CrackBumpFrequency(mapper->InputExtent());
  mapper->HelpersSawPass = true;
  mapper->Interior->DrawCracks(ren, actor, look, overlay);
  ++mapper->NumberOfCrackDraws;
}

//------------------------------------------------------------------------------
void vtkIceInteriorDrawer::DrawAir(vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor)
{
  const int view = mapper->DebugView;
  const bool debugAir = view == vtkIceMapper::DebugAir;
  vtkIceProperty* look = mapper->GetIceProperty();
  if (look->GetNumberOfAirPlanes() == 0 || (view != vtkIceMapper::DebugOff && !debugAir) ||
    mapper->UsesScreenInterior())
  {
    return;
  }
  vtkPolyData* input = mapper->GetInput();
  if (!input || !mapper->PrepareInput(input))
  {
    return;
  }
  mapper->HelpersSawPass = true;
  double bounds[6];
  mapper->GetLookBounds(bounds);
  mapper->Interior->DrawAir(ren, actor, mapper->PreparedInput, bounds, look->GetNumberOfAirPlanes(),
    look->GetAirSeed(), look->GetMilkiness(), debugAir);
}

//------------------------------------------------------------------------------
const vtkIceInteriorTable* vtkIceInteriorDrawer::BeginScreenInterior(
  vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program)
{
  vtkPolyData* input = mapper->GetInput();
  if (!input || !mapper->PrepareInput(input))
  {
    return nullptr;
  }
  vtkIceMapper::SetCameraUniforms(program, ren, actor);
  vtkIcePropertyUniforms::Set(mapper->GetIceProperty(), program);
  mapper->BindEnvironment(ren, actor);
  mapper->SetEnvironmentUniforms(program);
  mapper->PrepareInterior(ren, actor, program);
  return mapper->InteriorTable.get();
}

//------------------------------------------------------------------------------
void vtkIceInteriorDrawer::EndScreenInterior(vtkIceMapper* mapper, vtkRenderer* ren)
{
  mapper->FinishInterior(ren);
  mapper->UnbindEnvironment(ren);
}
