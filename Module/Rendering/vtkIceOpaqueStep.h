// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the opaque step of vtkIcePass's default delegate, as vtkOpenGLRenderer
// renders opaque geometry without any pass, following the renderer's settings every frame: hidden
// line removal (UseHiddenLineRemoval, when wireframe props exist), else screen-space ambient
// occlusion (UseSSAO and its SSAO parameters), else plain opaque geometry. It owns the VTK passes
// it runs; ReleaseGraphicsResources frees them.
#ifndef vtkIceOpaqueStep_h
#define vtkIceOpaqueStep_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for members

class vtkHiddenLineRemovalPass;
class vtkOpaquePass;
class vtkSSAOPass;

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

#endif
