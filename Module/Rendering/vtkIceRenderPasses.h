// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The render passes drawing a prop: VTK lists them on the prop (vtkOpenGLRenderPass::RenderPasses)
// while they render it. Inside the module only.
#ifndef vtkIceRenderPasses_h
#define vtkIceRenderPasses_h

#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkProp.h"

namespace vtkIceRenderPasses
{
// The first render pass drawing `prop` for which `wanted(pass)` holds, or nullptr.
template <class Predicate>
vtkObjectBase* Find(vtkProp* prop, Predicate wanted)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  const int passes = keys && keys->Has(vtkOpenGLRenderPass::RenderPasses())
    ? keys->Length(vtkOpenGLRenderPass::RenderPasses())
    : 0;
  for (int i = 0; i < passes; ++i)
  {
    vtkObjectBase* pass = keys->Get(vtkOpenGLRenderPass::RenderPasses(), i);
    if (wanted(pass))
    {
      return pass;
    }
  }
  return nullptr;
}
}

#endif
