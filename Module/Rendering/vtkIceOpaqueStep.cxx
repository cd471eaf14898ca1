// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceOpaqueStep.h"

#include "vtkHiddenLineRemovalPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"

vtkStandardNewMacro(vtkIceOpaqueStep);

//------------------------------------------------------------------------------
vtkIceOpaqueStep::vtkIceOpaqueStep()
  : Opaque(vtkSmartPointer<vtkOpaquePass>::New())
{
}

vtkIceOpaqueStep::~vtkIceOpaqueStep() = default;

void vtkIceOpaqueStep::Render(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  vtkRenderPass* pass = this->Opaque;
  if (renderer->GetUseHiddenLineRemoval() &&
    vtkHiddenLineRemovalPass::WireframePropsExist(s->GetPropArray(), s->GetPropArrayCount()))
  {
    if (!this->HiddenLineRemoval)
    {
      this->HiddenLineRemoval = vtkSmartPointer<vtkHiddenLineRemovalPass>::New();
    }
    pass = this->HiddenLineRemoval;
  }
  else if (renderer->GetUseSSAO())
  {
    if (!this->AmbientOcclusion)
    {
      this->AmbientOcclusion = vtkSmartPointer<vtkSSAOPass>::New();
      this->AmbientOcclusion->SetDelegatePass(this->Opaque);
    }
    this->AmbientOcclusion->SetRadius(renderer->GetSSAORadius());
    this->AmbientOcclusion->SetBias(renderer->GetSSAOBias());
    this->AmbientOcclusion->SetKernelSize(renderer->GetSSAOKernelSize());
    this->AmbientOcclusion->SetBlur(renderer->GetSSAOBlur());
    pass = this->AmbientOcclusion;
  }
  pass->Render(s);
  this->NumberOfRenderedProps = pass->GetNumberOfRenderedProps();
}

void vtkIceOpaqueStep::ReleaseGraphicsResources(vtkWindow* w)
{
  for (vtkRenderPass* pass : { static_cast<vtkRenderPass*>(this->Opaque),
         static_cast<vtkRenderPass*>(this->HiddenLineRemoval),
         static_cast<vtkRenderPass*>(this->AmbientOcclusion) })
  {
    if (pass)
    {
      pass->ReleaseGraphicsResources(w);
    }
  }
}
