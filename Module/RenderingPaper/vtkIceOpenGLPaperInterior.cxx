// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceOpenGLPaperInterior.h"

#include "vtkIceAirGeometry.h"
#include "vtkIceAirMapper.h"
#include "vtkIceAirTextureSource.h"
#include "vtkIceBackToFront.h"
#include "vtkIceCrackMapper.h"
#include "vtkIceInteriorLook.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkIceVTKCompat.h"

vtkStandardNewMacro(vtkIceOpenGLPaperInterior);

namespace
{
enum class Overlay
{
  Add,   // highlights: additive
  Blend, // bubbles: alpha blending
  Opaque // debug colours
};

// Draws `helper` over the rendered scene: the fragment shaders test their fragments at the ice's
// front depth, so the depth test keeps them where the ice is seen; no depth writes. `helper`
// takes `ice`'s matrix and render passes (vtkIcePass hands the depth interval through them).
void DrawOverScene(
  vtkRenderer* ren, vtkActor* helper, vtkActor* ice, Overlay overlay, bool depthTest)
{
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  state->vtkglDisable(GL_CULL_FACE);
  if (overlay == Overlay::Opaque)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    if (overlay == Overlay::Add)
    {
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    }
    else
    {
      state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
  }
  if (depthTest)
  {
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
  }
  else
  {
    state->vtkglDisable(GL_DEPTH_TEST);
  }
  state->vtkglDepthMask(GL_FALSE);
  helper->SetUserMatrix(ice->GetMatrix());
  helper->SetPropertyKeys(ice->GetPropertyKeys());
  helper->GetMapper()->Render(ren, helper);
  helper->SetPropertyKeys(nullptr);
}
}

//------------------------------------------------------------------------------
vtkIceOpenGLPaperInterior::vtkIceOpenGLPaperInterior()
{
  vtkProperty* property = this->CrackActor->GetProperty();
  property->SetAmbient(0.0);
  property->SetDiffuse(0.0);
  property->SetSpecular(1.0);
  property->SetSpecularPower(vtkIceInteriorLook::CrackSpecularPower);
  property->SetSpecularColor(1.0, 1.0, 1.0);
  this->CrackActor->SetMapper(this->CrackMapper);
  this->CrackMapper->ScalarVisibilityOff();

  this->AirActor->GetProperty()->LightingOff();
  this->AirActor->SetMapper(this->AirMapper);
  this->AirMapper->ScalarVisibilityOff();
  this->AirOrder->SetInputConnection(this->Air->GetOutputPort());
  this->AirMapper->SetInputConnection(this->AirOrder->GetOutputPort());
  this->AirTexture->SetInputConnection(this->AirImages->GetOutputPort());
  this->AirTexture->InterpolateOn();
  this->AirTexture->MipmapOn();
  this->AirTexture->RepeatOff();
  this->AirTexture->EdgeClampOn();
  this->AirTexture->SetColorModeToDirectScalars();
  this->AirMapper->SetAirTexture(this->AirTexture);
}

//------------------------------------------------------------------------------
vtkIceOpenGLPaperInterior::~vtkIceOpenGLPaperInterior() = default;

//------------------------------------------------------------------------------
void vtkIceOpenGLPaperInterior::DrawCracks(
  vtkRenderer* renderer, vtkActor* ice, vtkPolyData* cracks, const CrackLook& look, bool overlay)
{
  this->CrackMapper->SetInputData(cracks);
  this->CrackMapper->SetClipToInterval(look.ClipToInterval);
  this->CrackMapper->SetDebugColor(look.Debug);
  this->CrackMapper->SetIntensity(look.Intensity);
  this->CrackMapper->SetBumpFrequency(look.BumpFrequency);
  if (overlay)
  {
    DrawOverScene(renderer, this->CrackActor, ice, look.Debug ? Overlay::Opaque : Overlay::Add,
      !look.Unclipped);
    return;
  }
  vtkOpenGLState* state =
    static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);
  this->CrackActor->SetUserMatrix(ice->GetMatrix());
  this->CrackActor->SetPropertyKeys(ice->GetPropertyKeys());
  this->CrackMapper->Render(renderer, this->CrackActor);
  this->CrackActor->SetPropertyKeys(nullptr);
}

//------------------------------------------------------------------------------
void vtkIceOpenGLPaperInterior::DrawAir(vtkRenderer* renderer, vtkActor* ice, vtkPolyData* iceInput,
  const double bounds[6], int number, int seed, double milkiness, bool debug)
{
  // Back to front for this camera: the eye in the ice's model coordinates.
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  renderer->GetActiveCamera()->GetPosition(eye);
  vtkNew<vtkMatrix4x4> worldToModel;
  vtkMatrix4x4::Invert(ice->GetMatrix(), worldToModel);
  worldToModel->MultiplyPoint(eye, eye);
  this->Air->SetInputData(iceInput);
  this->Air->SetPlacementBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  this->Air->SetNumberOfPlanes(number);
  this->Air->SetSeed(seed);
  this->AirOrder->SetEye(eye);
  this->AirImages->SetSeed(seed);
  this->AirMapper->SetMilkiness(milkiness);
  this->AirMapper->SetDebugColor(debug);
  DrawOverScene(renderer, this->AirActor, ice, debug ? Overlay::Opaque : Overlay::Blend, true);
}

//------------------------------------------------------------------------------
void vtkIceOpenGLPaperInterior::ForgetRenderPasses()
{
  this->CrackMapper->ForgetRenderPasses();
  this->AirMapper->ForgetRenderPasses();
}

//------------------------------------------------------------------------------
void vtkIceOpenGLPaperInterior::ReleaseGraphicsResources(vtkWindow* window)
{
  this->CrackMapper->ReleaseGraphicsResources(window);
  this->AirMapper->ReleaseGraphicsResources(window);
  this->AirTexture->ReleaseGraphicsResources(window);
}
