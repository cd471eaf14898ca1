// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the steps of vtkIcePass's default delegate that do what
// vtkOpenGLRenderer does without any pass, following the renderer's settings every frame:
// - opaque: hidden line removal (UseHiddenLineRemoval, when wireframe props exist), else screen-
//   space ambient occlusion (UseSSAO and its SSAO parameters), else plain opaque geometry;
// - translucent: order-independent translucency, or dual depth peeling (UseDepthPeeling) with the
//   renderer's MaximumNumberOfPeels and OcclusionRatio, volumes peeled with the translucent
//   geometry (UseDepthPeelingForVolumes); skipped when no prop has translucent polygons; then FXAA
//   (UseFXAA, FXAAOptions), before volumes and overlays as the renderer applies it;
// - volumes: unless depth peeling drew them with the translucent geometry.
// Each owns the VTK passes it runs; ReleaseGraphicsResources frees them.
#ifndef vtkIceRendererSteps_h
#define vtkIceRendererSteps_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for members

class vtkDualDepthPeelingPass;
class vtkHiddenLineRemovalPass;
class vtkOpaquePass;
class vtkOpenGLFXAAFilter;
class vtkOrderIndependentTranslucentPass;
class vtkSSAOPass;
class vtkVolumetricPass;

class vtkIceOpaqueStep : public vtkRenderPass
{
public:
  static vtkIceOpaqueStep* New();
  vtkTypeMacro(vtkIceOpaqueStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkIceOpaqueStep();
  ~vtkIceOpaqueStep() override;

private:
  vtkSmartPointer<vtkOpaquePass> Opaque;
  vtkSmartPointer<vtkHiddenLineRemovalPass> HiddenLineRemoval;
  vtkSmartPointer<vtkSSAOPass> AmbientOcclusion;

  vtkIceOpaqueStep(const vtkIceOpaqueStep&) = delete;
  void operator=(const vtkIceOpaqueStep&) = delete;
};

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
  vtkSmartPointer<vtkDualDepthPeelingPass> Peeling;
  vtkSmartPointer<vtkVolumetricPass> PeeledVolumes;
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;

  vtkIceTranslucentStep(const vtkIceTranslucentStep&) = delete;
  void operator=(const vtkIceTranslucentStep&) = delete;
};

class vtkIceVolumeStep : public vtkRenderPass
{
public:
  static vtkIceVolumeStep* New();
  vtkTypeMacro(vtkIceVolumeStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  vtkIceTranslucentStep* Translucent = nullptr; // not counted: the same owner holds both

protected:
  vtkIceVolumeStep();
  ~vtkIceVolumeStep() override;

private:
  vtkSmartPointer<vtkVolumetricPass> Volumes;

  vtkIceVolumeStep(const vtkIceVolumeStep&) = delete;
  void operator=(const vtkIceVolumeStep&) = delete;
};

#endif
