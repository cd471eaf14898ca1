// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceRendererSteps.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkHiddenLineRemovalPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkSSAOPass.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"

namespace
{
// VTK 9.1's vtkOrderIndependentTranslucentPass creates its final blend (a vtkOpenGLQuadHelper
// with a vertex array object) on first use and deletes it only in ReleaseGraphicsResources, not
// in its destructor: a pass deleted without that call leaks the helper and its vertex array.
// Applications drop passes without releasing them (vtkRenderer::SetPass does not release the old
// pass either), so the one used here deletes it when it dies.
class vtkIceOrderIndependentTranslucentPass : public vtkOrderIndependentTranslucentPass
{
public:
  static vtkIceOrderIndependentTranslucentPass* New();
  vtkTypeMacro(vtkIceOrderIndependentTranslucentPass, vtkOrderIndependentTranslucentPass);

protected:
  vtkIceOrderIndependentTranslucentPass() = default;
  ~vtkIceOrderIndependentTranslucentPass() override
  {
    delete this->FinalBlend;
    this->FinalBlend = nullptr;
  }

private:
  vtkIceOrderIndependentTranslucentPass(const vtkIceOrderIndependentTranslucentPass&) = delete;
  void operator=(const vtkIceOrderIndependentTranslucentPass&) = delete;
};
vtkStandardNewMacro(vtkIceOrderIndependentTranslucentPass);

bool HasTranslucentPolygonalGeometry(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (s->GetPropArray()[i]->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}
}

vtkStandardNewMacro(vtkIceOpaqueStep);
vtkStandardNewMacro(vtkIceTranslucentStep);
vtkStandardNewMacro(vtkIceVolumeStep);

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

//------------------------------------------------------------------------------
vtkIceTranslucentStep::vtkIceTranslucentStep()
{
  vtkNew<vtkTranslucentPass> translucent;
  this->OrderIndependent = vtkSmartPointer<vtkIceOrderIndependentTranslucentPass>::New();
  this->OrderIndependent->SetTranslucentPass(translucent);
  this->Peeling = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
  this->Peeling->SetTranslucentPass(translucent);
}

vtkIceTranslucentStep::~vtkIceTranslucentStep() = default;

void vtkIceTranslucentStep::Render(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  this->NumberOfRenderedProps = 0;
  this->DrewVolumes = false;
  if (HasTranslucentPolygonalGeometry(s))
  {
    vtkRenderPass* pass = this->OrderIndependent;
    if (renderer->GetUseDepthPeeling())
    {
      // The Set macros change nothing when the values are the same.
      this->Peeling->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
      this->Peeling->SetOcclusionRatio(renderer->GetOcclusionRatio());
      if (renderer->GetUseDepthPeelingForVolumes() && !this->PeeledVolumes)
      {
        this->PeeledVolumes = vtkSmartPointer<vtkVolumetricPass>::New();
      }
      this->Peeling->SetVolumetricPass(
        renderer->GetUseDepthPeelingForVolumes() ? this->PeeledVolumes.Get() : nullptr);
      this->DrewVolumes = renderer->GetUseDepthPeelingForVolumes();
      pass = this->Peeling;
    }
    pass->Render(s);
    this->NumberOfRenderedProps = pass->GetNumberOfRenderedProps();
  }
  // Before volumes and overlays, as the renderer applies it.
  if (renderer->GetUseFXAA())
  {
    if (!this->FXAA)
    {
      this->FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    }
    if (renderer->GetFXAAOptions())
    {
      this->FXAA->UpdateConfiguration(renderer->GetFXAAOptions());
    }
    this->FXAA->Execute(static_cast<vtkOpenGLRenderer*>(renderer));
  }
}

void vtkIceTranslucentStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->OrderIndependent->ReleaseGraphicsResources(w);
  this->Peeling->ReleaseGraphicsResources(w);
  if (this->PeeledVolumes)
  {
    this->PeeledVolumes->ReleaseGraphicsResources(w);
  }
  if (this->FXAA)
  {
    this->FXAA->ReleaseGraphicsResources();
  }
}

//------------------------------------------------------------------------------
vtkIceVolumeStep::vtkIceVolumeStep()
  : Volumes(vtkSmartPointer<vtkVolumetricPass>::New())
{
}

vtkIceVolumeStep::~vtkIceVolumeStep() = default;

void vtkIceVolumeStep::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (this->Translucent && this->Translucent->DrewVolumes)
  {
    return;
  }
  this->Volumes->Render(s);
  this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
}

void vtkIceVolumeStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Volumes->ReleaseGraphicsResources(w);
}
