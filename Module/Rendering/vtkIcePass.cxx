// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIcePass.h"

#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceFrame.h"
#include "vtkIceMapper.h"
#include "vtkIceMapperAccess.h"
#include "vtkIceRenderPasses.h"
#include "vtkIceOpaqueStep.h"
#include "vtkIceOverlayStep.h"
#include "vtkIceScreenInterior.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"
#include "vtkIceStepTimers.h"
#include "vtkIceTranslucentStep.h"
#include "vtkIceVolumeStep.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkFrameBufferObjectBase.h"
#include "vtkHardwareSelector.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

vtkStandardNewMacro(vtkIcePass);
vtkCxxSetObjectMacro(vtkIcePass, DelegatePass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkIcePass, CubeMapPass, vtkIceCubeMapPass);

namespace
{
// The renderer's pick list during vtkRenderer::PickPropFrom (vtkViewport::PickFromProps, which
// has no getter): a pointer to the protected member, taken in a derived class's scope, applied to
// any renderer.
struct vtkIcePickListAccess : vtkRenderer
{
  static vtkPropCollection* vtkViewport::* Member() { return &vtkIcePickListAccess::PickFromProps; }
};

vtkPropCollection* PickFromProps(vtkRenderer* renderer)
{
  return renderer->*vtkIcePickListAccess::Member();
}

}

//------------------------------------------------------------------------------
vtkIcePass::vtkIcePass()
  : Frame(vtkIceFrame::New())
  , ScreenInterior(new vtkIceScreenInterior)
{
  // The steps of the renderer's own rendering, with its settings (vtkIceOpaqueStep,
  // vtkIceTranslucentStep, vtkIceVolumeStep), and the ice's air and cracks right after the opaque
  // geometry (vtkIceOverlayStep).
  this->OpaqueStep = vtkIceOpaqueStep::New();
  this->TranslucentStep = vtkIceTranslucentStep::New();
  this->VolumeStep = vtkIceVolumeStep::New();
  this->VolumeStep->Translucent = this->TranslucentStep;
  this->OverlayStep = vtkIceOverlayStep::New();
  this->OverlayStep->Draw = [this](const vtkRenderState* s, const vtkRenderState* iceState) {
    this->RenderOverlays(s, iceState);
  };
  vtkRenderStepsPass* steps = vtkRenderStepsPass::New();
  this->DefaultDelegate = steps;
  this->SetDelegatePass(this->DefaultDelegate);
  vtkNew<vtkSequencePass> opaqueThenOverlays;
  vtkNew<vtkRenderPassCollection> opaqueSteps;
  opaqueSteps->AddItem(this->OpaqueStep);
  opaqueSteps->AddItem(this->OverlayStep);
  opaqueThenOverlays->SetPasses(opaqueSteps);
  steps->SetOpaquePass(opaqueThenOverlays);
  steps->SetTranslucentPass(this->TranslucentStep);
  steps->SetVolumetricPass(this->VolumeStep);

  this->BackfaceNormalPass = vtkIceBackfaceNormalPass::New();
  this->DepthIntervalPass = vtkIceDepthIntervalPass::New();
  this->PropFrontPass = vtkIceDepthIntervalPass::New();
  this->PropFrontPass->FrontOnlyOn();
}

//------------------------------------------------------------------------------
vtkIcePass::~vtkIcePass()
{
  this->SetDelegatePass(nullptr);
  this->SetCubeMapPass(nullptr);
  this->DefaultDelegate->Delete();
  this->OverlayStep->Delete();
  this->OpaqueStep->Delete();
  this->TranslucentStep->Delete();
  this->VolumeStep->Delete();
  this->BackfaceNormalPass->Delete();
  this->DepthIntervalPass->Delete();
  this->PropFrontPass->Delete();
  delete this->StepTimers;
  delete this->ScreenInterior;
  this->Frame->Delete();
}

//------------------------------------------------------------------------------
void vtkIcePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  // Hardware picking and selection (vtkHardwareSelector, vtkPropPicker, the interactor's picks):
  // a renderer without a pass renders the selection itself, and a pass in its place must do so
  // through the selector's own entry point. The ice is picked like any prop.
  if (vtkHardwareSelector* selector = s->GetRenderer()->GetSelector())
  {
    // As the renderer does without a pass: the camera (viewport, clear), then the props, or only
    // the visible ones of a pick list (vtkRenderer::PickPropFrom, vtkPicker's PickFromList).
    vtkRenderer* renderer = s->GetRenderer();
    renderer->GetActiveCamera()->Render(renderer);
    this->NumberOfIceProps = 0;
    std::vector<vtkProp*> props(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
    if (vtkPropCollection* pickFrom = PickFromProps(renderer))
    {
      props.clear();
      vtkCollectionSimpleIterator it;
      pickFrom->InitTraversal(it);
      while (vtkProp* prop = pickFrom->GetNextProp(it))
      {
        if (prop->GetVisibility())
        {
          props.push_back(prop);
        }
      }
    }
    this->NumberOfRenderedProps =
      props.empty() ? 0 : selector->Render(renderer, props.data(), static_cast<int>(props.size()));
    return;
  }
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  // Only the OpenGL camera's own Render switches its stereo projection on or off (VTK's camera
  // pass does not): a window in stereo drew both eyes from the middle. It also sets the viewport
  // and clears, which the delegate does again; that happens only when stereo is switched.
  vtkRenderer* renderer = s->GetRenderer();
  if (renderer->GetActiveCamera()->GetStereo() != renderer->GetRenderWindow()->GetStereoRender())
  {
    renderer->GetActiveCamera()->Render(renderer);
  }
  if (this->MeasureStepTimes)
  {
    if (!this->StepTimers)
    {
      this->StepTimers = new vtkIceStepTimers;
    }
    this->StepTimers->BeginFrame();
  }

  std::vector<vtkProp*> iceProps;
  int needs = 0;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (vtkIceMapper* mapper = vtkIceMapperAccess::Of(s->GetPropArray()[i]))
    {
      iceProps.push_back(s->GetPropArray()[i]);
      needs |= mapper->GetFrameNeeds();
    }
  }
  this->NumberOfIceProps = static_cast<int>(iceProps.size());

  vtkRenderState iceState(s->GetRenderer());
  iceState.SetPropArrayAndCount(iceProps.data(), static_cast<int>(iceProps.size()));
  iceState.SetFrameBuffer(s->GetFrameBuffer());
  if (!iceProps.empty())
  {
    this->RenderIce(&iceState, needs);
  }

  // The default delegate draws air and cracks after the opaque geometry; another delegate gets
  // them over its finished frame.
  const bool overlaysInDelegate = this->DelegatePass == this->DefaultDelegate;
  this->OverlayStep->IceState = this->Frame->Active() && overlaysInDelegate ? &iceState : nullptr;
  this->StartStep(SceneStep);
  this->DelegatePass->Render(s);
  this->StopStep(SceneStep);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->OverlayStep->IceState = nullptr;
  if (this->Frame->Active() && !overlaysInDelegate)
  {
    this->RenderOverlays(s, &iceState);
  }
  this->EndFrame();
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderIce(const vtkRenderState* iceState, int needs)
{
  // From here to the end of the frame this pass is one of the ice props' render passes: it
  // hands its textures to their shaders (and to their cracks' and air's, which share the keys);
  // the frame is published on them for their mappers.
  if (vtkIceCubeMapPass* cubeMaps = this->CubeMapPass)
  {
    this->Frame->CubeMaps = [cubeMaps](vtkProp* prop) { return cubeMaps->GetCubeMap(prop); };
  }
  this->Frame->Begin(iceState, needs);
  this->PreRender(iceState);
  if (this->CubeMapPass)
  {
    this->StartStep(CubeMapStep);
    this->CubeMapPass->Render(iceState);
    this->StopStep(CubeMapStep);
    this->Frame->CubeMapVersion =
      static_cast<vtkMTimeType>(this->CubeMapPass->GetNumberOfFaceRenders());
  }
  if (needs & vtkIceFrame::NeedsDepthIntervalBeforeScene)
  {
    this->StartStep(DepthIntervalStep);
    this->RenderDepthInterval(iceState);
    this->StopStep(DepthIntervalStep);
  }
  if (needs &
    (vtkIceFrame::NeedsBackfaceNormals | vtkIceFrame::NeedsBackDepthForInterior |
      vtkIceFrame::NeedsPathLength))
  {
    this->StartStep(BackfaceNormalStep);
    this->BackfaceNormalPass->Render(iceState);
    this->StopStep(BackfaceNormalStep);
    this->Frame->BackfaceNormals = this->BackfaceNormalPass->GetNormalTexture();
  }
  if (needs & vtkIceFrame::NeedsScreenInterior)
  {
    // Timed as the interior when no paper passes' interior shares the step this frame.
    const bool timed = !(needs & vtkIceFrame::NeedsDepthIntervalForInterior);
    if (timed)
    {
      this->StartStep(InteriorStep);
    }
    this->RenderScreenInterior(iceState);
    if (timed)
    {
      this->StopStep(InteriorStep);
    }
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderScreenInterior(const vtkRenderState* iceState)
{
  std::vector<vtkProp*> props;
  for (int i = 0; i < iceState->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = iceState->GetPropArray()[i];
    if (vtkIceMapperAccess::Of(prop)->GetFrameNeeds() & vtkIceFrame::NeedsScreenInterior)
    {
      props.push_back(prop);
    }
  }
  // Where several ice props have one, each pixel takes the interior of the nearest: the nearest
  // front faces of all the ice (the depth interval's R, rendered for the frame already or now).
  vtkTextureObject* nearest = nullptr;
  if (props.size() > 1)
  {
    if (!this->Frame->DepthInterval)
    {
      this->DepthIntervalPass->FrontOnlyOn();
      this->RenderDepthInterval(iceState);
      this->DepthIntervalPass->FrontOnlyOff();
    }
    nearest = this->Frame->DepthInterval;
  }
  this->ScreenInterior->Begin();
  for (vtkProp* prop : props)
  {
    vtkRenderState propState(iceState->GetRenderer());
    propState.SetPropArrayAndCount(&prop, 1);
    propState.SetFrameBuffer(iceState->GetFrameBuffer());
    this->PropFrontPass->Render(&propState);
    this->ScreenInterior->Draw(iceState, static_cast<vtkActor*>(prop), vtkIceMapperAccess::Of(prop),
      this->Frame, this->PropFrontPass, nearest);
    this->Frame->Textures.Release(this->PropFrontPass->GetDepthTexture());
  }
  this->Frame->ScreenInterior = this->ScreenInterior->GetTexture();
}

//------------------------------------------------------------------------------
void vtkIcePass::EndFrame()
{
  if (this->Frame->Active())
  {
    const vtkRenderState* iceState = this->Frame->IceState;
    this->Frame->End();
    this->PostRender(iceState);
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderOverlays(const vtkRenderState* s, const vtkRenderState* iceState)
{
  // Timed only when some ice has an interior to draw here.
  const bool interior =
    this->Frame->Active() && (this->Frame->Needs & vtkIceFrame::NeedsDepthIntervalForInterior);
  if (interior)
  {
    this->StartStep(InteriorStep);
  }
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLState* state =
    static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
  state->vtkglEnable(GL_SCISSOR_TEST);
  // The renderer's area of the target the delegate drew into, as vtkCameraPass sets it.
  int size[2];
  int origin[2] = { 0, 0 };
  if (vtkFrameBufferObjectBase* target = s->GetFrameBuffer())
  {
    target->GetLastSize(size);
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  }
  state->vtkglViewport(origin[0], origin[1], size[0], size[1]);
  state->vtkglScissor(origin[0], origin[1], size[0], size[1]);
  // Prop by prop: its own depth interval, then its air (blended back to front), then its cracks'
  // highlights added on top. Both show only inside the ice's projected bounding box (elsewhere
  // the depth interval is empty, or the crack geometry is already cut to the ice): scissored
  // there, the parts of the planes and sheets that stick out are never rasterised.
  const auto scissorToIce = [&](vtkProp* prop, bool unclipped) {
    int covered[4] = { 0, 0, size[0], size[1] };
    if (!unclipped)
    {
      vtkIceScreenRegion::Covered(renderer, &prop, 1, size[0], size[1], covered);
    }
    state->vtkglScissor(origin[0] + covered[0], origin[1] + covered[1], covered[2] - covered[0],
      covered[3] - covered[1]);
  };
  for (int i = 0; i < iceState->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = iceState->GetPropArray()[i];
    vtkIceMapper* mapper = vtkIceMapperAccess::Of(prop);
    if (!(mapper->GetFrameNeeds() & vtkIceFrame::NeedsDepthIntervalForInterior))
    {
      continue;
    }
    vtkRenderState propState(renderer);
    propState.SetPropArrayAndCount(&prop, 1);
    propState.SetFrameBuffer(s->GetFrameBuffer());
    this->RenderDepthInterval(&propState);
    scissorToIce(prop, false);
    mapper->DrawPaperAir(renderer, static_cast<vtkActor*>(prop));
    scissorToIce(prop, mapper->GetDebugView() == vtkIceMapper::DebugCracksUnclipped);
    mapper->DrawPaperCracks(renderer, static_cast<vtkActor*>(prop), true);
  }
  if (interior)
  {
    this->StopStep(InteriorStep);
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::StartStep(int step)
{
  if (this->MeasureStepTimes && this->StepTimers)
  {
    this->StepTimers->Start(step);
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::StopStep(int step)
{
  if (this->MeasureStepTimes && this->StepTimers)
  {
    this->StepTimers->Stop(step);
  }
}

//------------------------------------------------------------------------------
double vtkIcePass::GetStepTime(int step)
{
  if (!this->MeasureStepTimes || !this->StepTimers || step < 0 || step >= NumberOfSteps)
  {
    return -1.0;
  }
  return this->StepTimers->Get(step);
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderDepthInterval(const vtkRenderState* s)
{
  // Not sampled while it is drawn into.
  this->Frame->Textures.Release(this->DepthIntervalPass->GetDepthTexture());
  this->Frame->DepthInterval = nullptr;
  this->DepthIntervalPass->Render(s);
  this->Frame->DepthInterval = this->DepthIntervalPass->GetDepthTexture();
}

//------------------------------------------------------------------------------
bool vtkIcePass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fs, vtkAbstractMapper* abstractMapper, vtkProp* prop)
{
  // The surface's code for each of the frame's inputs is in its program; the pass publishes
  // which inputs it has (textures ready in this stage, not while a sub-pass renders them, and
  // needed by the ice) as #defines. What is ready in a stage is the same every frame, and a
  // change of needs modifies the mapper: the program is rebuilt whenever the answer changes.
  vtkIceMapper* mapper = vtkIceMapper::SafeDownCast(abstractMapper);
  if (mapper)
  {
    vtkIceShaderSections::FillHook(
      fs, "FrameInputs", vtkIceFrame::Defines(mapper->GetFrameInputs(prop)));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIcePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  vtkIceFrame* frame = this->Frame;
  if (!frame->Active())
  {
    return true;
  }
  vtkRenderer* renderer = frame->IceState->GetRenderer();
  frame->Textures.BindScreen(program, renderer, "iceBackNormals", frame->BackfaceNormals);
  if (frame->Textures.BindScreen(program, renderer, "iceDepthInterval", frame->DepthInterval))
  {
    const double* range = this->DepthIntervalPass->GetDepthRange();
    program->SetUniform2f("iceDepthRange",
      std::array<float, 2>{ static_cast<float>(range[0]), static_cast<float>(range[1]) }.data());
  }
  frame->Textures.BindScreen(program, renderer, "iceScreenInterior", frame->ScreenInterior);
  frame->BindCubeMap(program, prop);
  return true;
}

//------------------------------------------------------------------------------
void vtkIcePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Frame->Textures.ReleaseAll();
  this->BackfaceNormalPass->ReleaseGraphicsResources(w);
  this->DepthIntervalPass->ReleaseGraphicsResources(w);
  this->PropFrontPass->ReleaseGraphicsResources(w);
  this->ScreenInterior->ReleaseGraphicsResources(w);
  if (this->StepTimers)
  {
    this->StepTimers->ReleaseGraphicsResources();
  }
  if (this->CubeMapPass)
  {
    this->CubeMapPass->ReleaseGraphicsResources(w);
  }
  for (vtkRenderPass* pass :
    { this->DelegatePass, this->DefaultDelegate, static_cast<vtkRenderPass*>(this->OpaqueStep),
      static_cast<vtkRenderPass*>(this->TranslucentStep),
      static_cast<vtkRenderPass*>(this->VolumeStep) })
  {
    if (pass)
    {
      pass->ReleaseGraphicsResources(w);
    }
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "CubeMapPass: " << this->CubeMapPass << "\n";
  os << indent << "NumberOfIceProps: " << this->NumberOfIceProps << "\n";
  os << indent << "MeasureStepTimes: " << this->MeasureStepTimes << "\n";
}
