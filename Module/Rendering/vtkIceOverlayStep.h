// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: the step of vtkIcePass's default delegate that draws the ice's air and
// cracks right after the opaque geometry, so translucent geometry in front of the ice is
// composited over them. What it draws is its owner's (Draw, given the ice props' state).
#ifndef vtkIceOverlayStep_h
#define vtkIceOverlayStep_h

#include "vtkRenderPass.h"

#include <functional> // for Draw

class vtkIceOverlayStep : public vtkRenderPass
{
public:
  static vtkIceOverlayStep* New();
  vtkTypeMacro(vtkIceOverlayStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override;

  // The owner's RenderOverlays; the ice props while the frame renders.
  std::function<void(const vtkRenderState*, const vtkRenderState*)> Draw;
  const vtkRenderState* IceState = nullptr;

protected:
  vtkIceOverlayStep() = default;
  ~vtkIceOverlayStep() override = default;

private:
  vtkIceOverlayStep(const vtkIceOverlayStep&) = delete;
  void operator=(const vtkIceOverlayStep&) = delete;
};

#endif
