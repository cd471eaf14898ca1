// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkIcePass and its sub-passes ask of the ice mappers in a frame: which props are ice, what
// each needs rendered and what the frame gives its program (its cracks and air:
// vtkIceInteriorDrawer). These are not vtkIceMapper's public API
// (neither wrapped nor installed): the mapper grants them to this class only. Inside the module.
#ifndef vtkIceMapperAccess_h
#define vtkIceMapperAccess_h

#include "vtkActor.h"
#include "vtkIceMapper.h"

class vtkIceMapperAccess
{
public:
  // The vtkIceMapper of `prop` if it is a visible vtkActor drawn by one, else null.
  static vtkIceMapper* Of(vtkProp* prop)
  {
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    return actor && actor->GetVisibility() ? vtkIceMapper::SafeDownCast(actor->GetMapper())
                                           : nullptr;
  }

  // What the ice needs the pass to render for it this frame: vtkIceFrame::Need bits.
  static int FrameNeeds(vtkIceMapper* mapper) { return mapper->GetFrameNeeds(); }

  // What the frame gives the surface program of `prop` now (vtkIceFrame::Input bits).
  static int FrameInputs(vtkIceMapper* mapper, vtkProp* prop)
  {
    return mapper->GetFrameInputs(prop);
  }
};

#endif
