// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVIceRenderView.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIcePass.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVIceCubeMapCompositor.h"
#include "vtkPVIceCubeMapPass.h"
#include "vtkRenderer.h"
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
  // On several ranks each renders its part of the scene: the cube-map faces are composited.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->CubeMapPass->SetCompositor(this->Compositor);
  }
}

//------------------------------------------------------------------------------
void vtkPVIceRenderView::Render(bool interactive, bool skip_rendering)
{
  // A server paints the background black while it draws (IceT on several ranks, pvserver for a
  // client's remote rendering); the faces show the user's, which UpdateBackground sets on the
  // renderer (the superclass calls it again).
  this->UpdateBackground();
  this->CubeMapPass->SetFaceBackground(this->GetRenderer());
  this->Superclass::Render(interactive, skip_rendering);
}

//------------------------------------------------------------------------------
vtkPVIceCubeMapCompositor* vtkPVIceRenderView::GetCubeMapCompositor()
{
  return this->Compositor;
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
