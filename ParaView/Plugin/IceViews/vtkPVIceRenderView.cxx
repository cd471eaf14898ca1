#include "vtkPVIceRenderView.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIcePass.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVSynchronizedRenderer.h"

vtkStandardNewMacro(vtkPVIceRenderView);

//------------------------------------------------------------------------------
vtkPVIceRenderView::vtkPVIceRenderView()
{
  // ParaView's camera pass sets up the camera and clears; its default pass renders the props
  // (lights, opaque, translucent, volumes, overlays), as in the ordinary render view.
  vtkNew<vtkPVDefaultPass> geometry;
  this->IcePass->SetDelegatePass(geometry);
  this->SynchronizedRenderers->SetRenderPass(this->IcePass);
}

//------------------------------------------------------------------------------
vtkPVIceRenderView::~vtkPVIceRenderView() = default;

//------------------------------------------------------------------------------
vtkIcePass* vtkPVIceRenderView::GetIcePass()
{
  return this->IcePass;
}

//------------------------------------------------------------------------------
void vtkPVIceRenderView::SetDynamicEnvironment(bool dynamic)
{
  if (this->DynamicEnvironment == dynamic)
  {
    return;
  }
  this->DynamicEnvironment = dynamic;
  this->IcePass->SetCubeMapPass(dynamic ? this->CubeMapPass.Get() : nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVIceRenderView::SetCubeMapFaceSize(int size)
{
  this->CubeMapPass->SetFaceSize(size);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVIceRenderView::SetCubeMapUpdateMode(int mode)
{
  this->CubeMapPass->SetUpdateMode(mode);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVIceRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DynamicEnvironment: " << this->DynamicEnvironment << "\n";
}
