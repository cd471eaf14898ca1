// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the translucent step of vtkIcePass's default delegate, following the
// renderer's settings every frame: order-independent translucency, or dual depth peeling
// (UseDepthPeeling) with the renderer's MaximumNumberOfPeels and OcclusionRatio, volumes peeled
// with the translucent geometry (UseDepthPeelingForVolumes); skipped when no prop has translucent
// polygons. Inside another pass's framebuffer (vtkToneMappingPass around vtkIcePass) it draws
// as vtkRenderStepsPass does there, with vtkTranslucentPass: VTK's order-independent pass takes
// the opaque depth by a blit from that framebuffer, which fails when the depth formats differ,
// and its translucent geometry then covers everything. Then FXAA (UseFXAA, FXAAOptions), before volumes and overlays as the renderer applies
// it. It owns the VTK passes it runs; ReleaseGraphicsResources frees them.
#ifndef vtkIceTranslucentStep_h
#define vtkIceTranslucentStep_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for members

class vtkDualDepthPeelingPass;
class vtkOpenGLFXAAFilter;
class vtkOrderIndependentTranslucentPass;
class vtkTranslucentPass;
class vtkVolumetricPass;

class vtkIceTranslucentStep : public vtkRenderPass
{
public:
  static vtkIceTranslucentStep* New();
  vtkTypeMacro(vtkIceTranslucentStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // Whether the last Render drew the volumes (depth peeling for volumes).
  bool DrewVolumes = false;

protected:
  vtkIceTranslucentStep();
  ~vtkIceTranslucentStep() override;

private:
  vtkSmartPointer<vtkOrderIndependentTranslucentPass> OrderIndependent;
  vtkSmartPointer<vtkTranslucentPass> Plain;
  vtkSmartPointer<vtkDualDepthPeelingPass> Peeling;
  vtkSmartPointer<vtkVolumetricPass> PeeledVolumes;
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;

  vtkIceTranslucentStep(const vtkIceTranslucentStep&) = delete;
  void operator=(const vtkIceTranslucentStep&) = delete;
};

#endif
