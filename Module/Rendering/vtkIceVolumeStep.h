// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the volume step of vtkIcePass's default delegate: the renderer's volumes,
// unless depth peeling drew them with the translucent geometry (vtkIceTranslucentStep).
#ifndef vtkIceVolumeStep_h
#define vtkIceVolumeStep_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for members

class vtkIceTranslucentStep;
class vtkVolumetricPass;

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
