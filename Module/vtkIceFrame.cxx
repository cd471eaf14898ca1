#include "vtkIceFrame.h"

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
