// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceBackfaceCulling.h"

#include "vtkIceRenderPasses.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkIceVTKCompat.h"

//------------------------------------------------------------------------------
bool vtkIceBackfaceCulling::BackfacesHidden(
  vtkRenderer* renderer, vtkActor* actor, vtkMapper* mapper, bool closedOutward)
{
  vtkProperty* property = actor->GetProperty();
  // Edges and vertices of back faces show along the silhouette (lines and points have a width).
  if (!closedOutward || property->GetRepresentation() != VTK_SURFACE ||
    property->GetEdgeVisibility() || property->GetVertexVisibility() ||
    property->GetOpacity() < 1.0 || property->GetBackfaceCulling() ||
    property->GetFrontfaceCulling() || mapper->GetNumberOfClippingPlanes() > 0 ||
    actor->GetMatrix()->Determinant() <= 0.0)
  {
    return false;
  }
  // Every corner of the bounds beyond the near plane: the box, and the ice in it, lies wholly
  // in front of the camera, so each view ray meets the closed surface at a front face first.
  vtkCamera* camera = renderer->GetActiveCamera();
  const double* bounds = actor->GetBounds();
  if (!camera || !bounds || !vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }
  double position[3];
  double direction[3];
  camera->GetPosition(position);
  camera->GetDirectionOfProjection(direction);
  const double nearPlane = camera->GetClippingRange()[0];
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[3] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
      bounds[4 + ((corner >> 2) & 1)] };
    const double d[3] = { p[0] - position[0], p[1] - position[1], p[2] - position[2] };
    if (vtkMath::Dot(d, direction) <= nearPlane)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceBackfaceCulling::InSubPass(vtkActor* actor)
{
  // By name, not by its header: vtkIcePass depends on the mapper, which depends on this.
  return vtkIceRenderPasses::Find(
           actor, [](vtkObjectBase* pass) { return !pass->IsA("vtkIcePass"); }) != nullptr;
}

//------------------------------------------------------------------------------
void vtkIceBackfaceCulling::Begin(vtkRenderer* renderer)
{
  this->End();
  if (auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()))
  {
    this->Saved.reset(new vtkIceCullingSaver(window->GetState()));
    this->Saved->Cull(GL_BACK);
  }
}

//------------------------------------------------------------------------------
vtkIceCullingSaver::vtkIceCullingSaver(vtkOpenGLState* state)
  : State(state)
  , Mode(GL_BACK)
  , Enabled(state, GL_CULL_FACE)
{
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &this->Mode);
}

//------------------------------------------------------------------------------
vtkIceCullingSaver::~vtkIceCullingSaver()
{
  this->State->vtkglCullFace(static_cast<unsigned int>(this->Mode));
}

//------------------------------------------------------------------------------
void vtkIceCullingSaver::Cull(unsigned int face)
{
  this->State->vtkglCullFace(face);
  this->State->vtkglEnable(GL_CULL_FACE);
}
