#include "vtkIcePass.h"

#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"

#include <vector>

vtkStandardNewMacro(vtkIcePass);
vtkCxxSetObjectMacro(vtkIcePass, DelegatePass, vtkRenderPass);

namespace
{
vtkIceMapper* IceMapperOf(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetVisibility() ? vtkIceMapper::SafeDownCast(actor->GetMapper()) : nullptr;
}
}

//------------------------------------------------------------------------------
vtkIcePass::vtkIcePass()
{
  vtkRenderStepsPass* steps = vtkRenderStepsPass::New();
  this->SetDelegatePass(steps);
  steps->Delete();
  this->BackfaceNormalPass = vtkIceBackfaceNormalPass::New();
}

//------------------------------------------------------------------------------
vtkIcePass::~vtkIcePass()
{
  this->SetDelegatePass(nullptr);
  this->BackfaceNormalPass->Delete();
}

//------------------------------------------------------------------------------
void vtkIcePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }

  std::vector<vtkProp*> iceProps;
  std::vector<vtkIceMapper*> iceMappers;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (vtkIceMapper* mapper = IceMapperOf(s->GetPropArray()[i]))
    {
      iceProps.push_back(s->GetPropArray()[i]);
      iceMappers.push_back(mapper);
    }
  }
  this->NumberOfIceProps = static_cast<int>(iceProps.size());

  // Picking renders ids, not ice: the sub-passes are not needed then.
  const bool runIcePasses = !iceProps.empty() && !s->GetRenderer()->GetSelector();
  if (runIcePasses)
  {
    vtkRenderState iceState(s->GetRenderer());
    iceState.SetPropArrayAndCount(iceProps.data(), static_cast<int>(iceProps.size()));
    iceState.SetFrameBuffer(s->GetFrameBuffer());
    this->BackfaceNormalPass->Render(&iceState);
    for (vtkIceMapper* mapper : iceMappers)
    {
      mapper->SetBackfaceNormalTexture(this->BackfaceNormalPass->GetNormalTexture());
    }
  }

  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();

  if (runIcePasses)
  {
    for (vtkIceMapper* mapper : iceMappers)
    {
      mapper->SetBackfaceNormalTexture(nullptr);
    }
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->BackfaceNormalPass->ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "NumberOfIceProps: " << this->NumberOfIceProps << "\n";
}
