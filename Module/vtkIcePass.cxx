#include "vtkIcePass.h"

#include "vtkIceBackfaceNormalPass.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceDebugDepthFS.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceExitPointFS.h"
#include "vtkIceFrameTextures.h"
#include "vtkIceMapper.h"
#include "vtkIceRenderPasses.h"
#include "vtkIceRendererSteps.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSinglePassInterior.h"
#include "vtkIceTwoSidedFS.h"

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
#include <vector>

vtkStandardNewMacro(vtkIcePass);
vtkCxxSetObjectMacro(vtkIcePass, DelegatePass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkIcePass, CubeMapPass, vtkIceCubeMapPass);

// The step of the default delegate that draws the ice's air and cracks right after the opaque
// geometry, so translucent geometry in front of the ice is composited over them.
class vtkIceOverlayStep : public vtkRenderPass
{
public:
  static vtkIceOverlayStep* New();
  vtkTypeMacro(vtkIceOverlayStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Owner && this->IceState)
    {
      this->Owner->RenderOverlays(s, this->IceState);
    }
  }
  vtkIcePass* Owner = nullptr;              // not counted: the owner holds this step
  const vtkRenderState* IceState = nullptr; // the ice props, while the frame renders
};
vtkStandardNewMacro(vtkIceOverlayStep);

namespace
{
// The renderer's pick list during vtkRenderer::PickPropFrom (vtkViewport::PickFromProps, which
// has no getter): a pointer to the protected member, taken in a derived class's scope, applied to
// any renderer.
struct vtkIcePickListAccess : vtkRenderer
{
  static vtkPropCollection* vtkViewport::*Member() { return &vtkIcePickListAccess::PickFromProps; }
};

vtkPropCollection* PickFromProps(vtkRenderer* renderer)
{
  return renderer->*vtkIcePickListAccess::Member();
}

// The sub-passes draw the ice with outputs of their own: the surface's optics would be dead code
// in their programs, which NVIDIA's driver still compiled with the textures' samplers active
// (Mesa drops them).
bool DrawnByIceSubPass(vtkProp* prop)
{
  return vtkIceRenderPasses::Find(prop, [](vtkObjectBase* pass) {
    return vtkIceDepthIntervalPass::SafeDownCast(pass) ||
      vtkIceBackfaceNormalPass::SafeDownCast(pass);
  }) != nullptr;
}
}

//------------------------------------------------------------------------------
vtkIcePass::vtkIcePass()
  : FrameTextures(new vtkIceFrameTextures)
{
  // The steps of the renderer's own rendering, with its settings (vtkIceRendererSteps.h), and
  // the ice's air and cracks right after the opaque geometry.
  this->OpaqueStep = vtkIceOpaqueStep::New();
  this->TranslucentStep = vtkIceTranslucentStep::New();
  this->VolumeStep = vtkIceVolumeStep::New();
  this->VolumeStep->Translucent = this->TranslucentStep;
  this->OverlayStep = vtkIceOverlayStep::New();
  this->OverlayStep->Owner = this;
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

  std::vector<vtkProp*> iceProps;
  int needs = 0;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (vtkIceMapper* mapper = vtkIceMapper::GetIceMapperOf(s->GetPropArray()[i]))
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
  this->OverlayStep->IceState = this->IceState && overlaysInDelegate ? &iceState : nullptr;
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->OverlayStep->IceState = nullptr;
  if (this->IceState && !overlaysInDelegate)
  {
    this->RenderOverlays(s, &iceState);
  }
  this->EndFrame();
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderIce(const vtkRenderState* iceState, int needs)
{
  // From here to the end of the frame this pass is one of the ice props' render passes: it
  // hands its textures to their shaders (and to their cracks' and air's, which share the keys).
  this->IceState = iceState;
  this->PreRender(iceState);
  if (this->CubeMapPass)
  {
    this->CubeMapPass->Render(iceState);
  }
  if (needs & vtkIceMapper::NeedsDepthIntervalBeforeScene)
  {
    this->RenderDepthInterval(iceState);
  }
  if (needs &
    (vtkIceMapper::NeedsBackfaceNormals | vtkIceMapper::NeedsBackDepthForInterior |
      vtkIceMapper::NeedsPathLength))
  {
    this->BackfaceNormalPass->Render(iceState);
    this->BackfaceNormals = this->BackfaceNormalPass->GetNormalTexture();
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::EndFrame()
{
  this->FrameTextures->ReleaseAll();
  this->BoundCubeMap = nullptr;
  this->BackfaceNormals = nullptr;
  this->DepthInterval = nullptr;
  if (this->IceState)
  {
    this->PostRender(this->IceState);
    this->IceState = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderOverlays(const vtkRenderState* s, const vtkRenderState* iceState)
{
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
    vtkIceMapper* mapper = vtkIceMapper::GetIceMapperOf(prop);
    if (!(mapper->GetFrameNeeds() & vtkIceMapper::NeedsDepthIntervalForInterior))
    {
      continue;
    }
    vtkRenderState propState(renderer);
    propState.SetPropArrayAndCount(&prop, 1);
    propState.SetFrameBuffer(s->GetFrameBuffer());
    this->RenderDepthInterval(&propState);
    scissorToIce(prop, false);
    mapper->RenderAir(renderer, static_cast<vtkActor*>(prop));
    scissorToIce(prop, mapper->GetDebugView() == vtkIceMapper::DebugCracksUnclipped);
    mapper->RenderCracks(renderer, static_cast<vtkActor*>(prop), true);
  }
}

//------------------------------------------------------------------------------
void vtkIcePass::RenderDepthInterval(const vtkRenderState* s)
{
  // Not sampled while it is drawn into.
  this->FrameTextures->Release(this->DepthIntervalPass->GetDepthTexture());
  this->DepthInterval = nullptr;
  this->DepthIntervalPass->Render(s);
  this->DepthInterval = this->DepthIntervalPass->GetDepthTexture();
}

//------------------------------------------------------------------------------
vtkIcePass* vtkIcePass::GetIcePassOf(vtkProp* prop)
{
  return vtkIcePass::SafeDownCast(vtkIceRenderPasses::Find(
    prop, [](vtkObjectBase* pass) { return vtkIcePass::SafeDownCast(pass) != nullptr; }));
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIcePass::GetCubeMapOf(vtkProp* prop)
{
  return this->IceState && this->CubeMapPass ? this->CubeMapPass->GetCubeMap(prop) : nullptr;
}

//------------------------------------------------------------------------------
bool vtkIcePass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fs, vtkAbstractMapper* abstractMapper, vtkProp* prop)
{
  // The surface's hooks for the parts that sample this pass's textures, filled when the texture
  // is ready (not while a sub-pass renders it) and the ice needs it. What is ready in a stage is
  // the same every frame, and a change of needs modifies the mapper: the program is rebuilt
  // whenever this answer changes.
  vtkIceMapper* mapper = vtkIceMapper::SafeDownCast(abstractMapper);
  if (!mapper || DrawnByIceSubPass(prop))
  {
    return true;
  }
  using vtkIceShaderSections::Get;
  const int needs = mapper->GetFrameNeeds();
  // The back-face target's sampler, unless a snippet inserted here declared it already.
  const auto declareBackNormals = [&fs]() {
    if (fs.find("uniform sampler2D iceBackNormals;") == std::string::npos)
    {
      vtkIceShaderSections::InsertDeclarations(fs, "uniform sampler2D iceBackNormals;\n");
    }
  };
  const bool exitPoint = this->BackfaceNormals && (needs & vtkIceMapper::NeedsBackfaceNormals) &&
    mapper->GetTwoSidedMethod() == vtkIceMapper::TwoSidedExitPoint;
  if (exitPoint)
  {
    vtkIceShaderSections::InsertDeclarations(fs, Get(vtkIceExitPointFS, "Dec"));
    vtkIceShaderSections::FillHook(fs, "RefractionDirection", Get(vtkIceExitPointFS, "Impl"));
  }
  else if (this->BackfaceNormals && (needs & vtkIceMapper::NeedsBackfaceNormals))
  {
    vtkIceShaderSections::InsertDeclarations(fs, Get(vtkIceTwoSidedFS, "Dec"));
    vtkIceShaderSections::FillHook(fs, "RefractionNormal", Get(vtkIceTwoSidedFS, "Impl"));
  }
  if (this->BackfaceNormals && (needs & vtkIceMapper::NeedsPathLength))
  {
    // The exit point's own path; else the eye ray's between the front and back faces.
    declareBackNormals();
    vtkIceShaderSections::FillHook(fs, "PathLength",
      exitPoint ? "icePathLength = iceExitPathLength;"
                : "icePathLength = iceEyePathLength(e, iceViewDirectionWC, iceViewDepth(),\n"
                  "      texelFetch(iceBackNormals, iceScreenTexel(), 0).a);");
  }
  if (this->BackfaceNormals && (needs & vtkIceMapper::NeedsBackDepthForInterior))
  {
    declareBackNormals();
    vtkIceShaderSections::FillHook(fs, "Interior", vtkIceSinglePassInterior::Call());
  }
  const int view = mapper->GetDebugView();
  if (this->DepthInterval &&
    (view == vtkIceMapper::DebugFrontDepth || view == vtkIceMapper::DebugBackDepth))
  {
    vtkIceShaderSections::InsertDeclarations(fs, Get(vtkIceDebugDepthFS, "Dec"));
    vtkIceShaderSections::FillHook(fs, "Debug", Get(vtkIceDebugDepthFS, "Impl"));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkIcePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!this->IceState)
  {
    return true;
  }
  vtkRenderer* renderer = this->IceState->GetRenderer();
  this->FrameTextures->BindScreen(program, renderer, "iceBackNormals", this->BackfaceNormals);
  if (this->FrameTextures->BindScreen(program, renderer, "iceDepthInterval", this->DepthInterval))
  {
    const double* range = this->DepthIntervalPass->GetDepthRange();
    program->SetUniform2f("iceDepthRange",
      std::array<float, 2>{ static_cast<float>(range[0]), static_cast<float>(range[1]) }.data());
  }
  if (vtkTextureObject* cubeMap = this->GetCubeMapOf(prop))
  {
    // One prop's cube map at a time keeps one texture unit however many ice props there are.
    if (this->BoundCubeMap && this->BoundCubeMap != cubeMap)
    {
      this->FrameTextures->Release(this->BoundCubeMap);
    }
    this->BoundCubeMap = cubeMap;
    this->FrameTextures->Bind(program, "iceEnvironment", cubeMap);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIcePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->FrameTextures->ReleaseAll();
  this->BackfaceNormalPass->ReleaseGraphicsResources(w);
  this->DepthIntervalPass->ReleaseGraphicsResources(w);
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
}
