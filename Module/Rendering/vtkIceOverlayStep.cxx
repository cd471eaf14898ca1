// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceOverlayStep.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkIceOverlayStep);

//------------------------------------------------------------------------------
void vtkIceOverlayStep::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (this->Draw && this->IceState)
  {
    this->Draw(s, this->IceState);
  }
}
