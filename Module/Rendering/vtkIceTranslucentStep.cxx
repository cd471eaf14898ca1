// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceTranslucentStep.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
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

vtkStandardNewMacro(vtkIceTranslucentStep);

//------------------------------------------------------------------------------
vtkIceTranslucentStep::vtkIceTranslucentStep()
{
  vtkNew<vtkTranslucentPass> translucent;
  this->Plain = translucent;
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
    if (s->GetFrameBuffer() && !renderer->GetUseDepthPeeling())
    {
      pass = this->Plain;
    }
    else if (renderer->GetUseDepthPeeling())
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
