// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceFrame.h"
#include "vtkIceRenderPasses.h"

#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkIceFrame);
vtkInformationKeyMacro(vtkIceFrame, FRAME, ObjectBase);

//------------------------------------------------------------------------------
void vtkIceFrame::Begin(const vtkRenderState* iceState, int needs)
{
  this->IceState = iceState;
  this->Needs = needs;
  for (int i = 0; i < iceState->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = iceState->GetPropArray()[i];
    vtkInformation* keys = prop->GetPropertyKeys();
    if (!keys)
    {
      keys = vtkInformation::New();
      prop->SetPropertyKeys(keys);
      keys->Delete();
    }
    keys->Set(vtkIceFrame::FRAME(), this);
  }
}

//------------------------------------------------------------------------------
void vtkIceFrame::End()
{
  this->Textures.ReleaseAll();
  this->BoundCubeMap = nullptr;
  this->BackfaceNormals = nullptr;
  this->DepthInterval = nullptr;
  this->ScreenInterior = nullptr;
  this->CubeMaps = nullptr;
  if (this->IceState)
  {
    for (int i = 0; i < this->IceState->GetPropArrayCount(); ++i)
    {
      if (vtkInformation* keys = this->IceState->GetPropArray()[i]->GetPropertyKeys())
      {
        keys->Remove(vtkIceFrame::FRAME());
      }
    }
    this->IceState = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkIceFrame* vtkIceFrame::Of(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys ? vtkIceFrame::SafeDownCast(keys->Get(vtkIceFrame::FRAME())) : nullptr;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceFrame::CubeMapOf(vtkProp* prop) const
{
  return this->IceState && this->CubeMaps ? this->CubeMaps(prop) : nullptr;
}

//------------------------------------------------------------------------------
void vtkIceFrame::BindCubeMap(vtkShaderProgram* program, vtkProp* prop)
{
  if (vtkTextureObject* cubeMap = this->CubeMapOf(prop))
  {
    if (this->BoundCubeMap && this->BoundCubeMap != cubeMap)
    {
      this->Textures.Release(this->BoundCubeMap);
    }
    this->BoundCubeMap = cubeMap;
    this->Textures.Bind(program, "iceEnvironment", cubeMap);
  }
}

//------------------------------------------------------------------------------
int vtkIceFrame::InputsOf(vtkProp* prop, int needs, bool exitPoint, bool depthDebug) const
{
  // The sub-passes that draw the ice (by name: they use the frame) replace its output: the
  // surface's optics would be dead code in their programs, which NVIDIA's driver still compiled
  // with the textures' samplers active (Mesa drops them).
  const bool inSubPass = vtkIceRenderPasses::Find(prop, [](vtkObjectBase* pass) {
    return pass->IsA("vtkIceDepthIntervalPass") || pass->IsA("vtkIceBackfaceNormalPass");
  }) != nullptr;
  if (!this->Active() || inSubPass)
  {
    return 0;
  }
  int inputs = 0;
  if (this->BackfaceNormals)
  {
    if (needs & NeedsBackfaceNormals)
    {
      inputs |= exitPoint ? ExitPointInput : TwoSidedInput;
    }
    inputs |= (needs & NeedsPathLength) ? PathLengthInput : 0;
    inputs |= inputs ? BackNormalsInput : 0;
  }
  if (this->ScreenInterior && (needs & NeedsScreenInterior))
  {
    inputs |= ScreenInteriorInput;
  }
  if (this->DepthInterval && depthDebug)
  {
    inputs |= DepthDebugInput;
  }
  return inputs;
}

//------------------------------------------------------------------------------
std::string vtkIceFrame::Defines(int inputs)
{
  static const std::pair<int, const char*> names[] = {
    { BackNormalsInput, "ICE_FRAME_BACK_NORMALS" },
    { TwoSidedInput, "ICE_FRAME_TWO_SIDED" },
    { ExitPointInput, "ICE_FRAME_EXIT_POINT" },
    { PathLengthInput, "ICE_FRAME_PATH_LENGTH" },
    { DepthDebugInput, "ICE_FRAME_DEPTH_DEBUG" },
    { ScreenInteriorInput, "ICE_FRAME_SCREEN_INTERIOR" },
  };
  std::string defines;
  for (const auto& name : names)
  {
    if (inputs & name.first)
    {
      defines += std::string("#define ") + name.second + "\n";
    }
  }
  return defines;
}
