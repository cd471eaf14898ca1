// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Which props vtkIcePass and its sub-passes treat as ice: the visible actors that a vtkIceMapper
// draws. Inside the module.
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
};

#endif
