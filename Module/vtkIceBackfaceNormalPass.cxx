#include "vtkIceBackfaceNormalPass.h"

#include "vtkIceBackfaceNormalFS.h"
#include "vtkIceMapper.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"

#include "vtkActor.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkIceBackfaceNormalPass);

class vtkIceBackfaceNormalPass::vtkInternals
{
public:
  vtkIceScreenRegion::Tracker Normals; // what of NormalTexture may not hold the clear value
  vtkOpenGLState* State = nullptr;     // while Render runs
};

//------------------------------------------------------------------------------
vtkIceBackfaceNormalPass::vtkIceBackfaceNormalPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkIceBackfaceNormalPass::~vtkIceBackfaceNormalPass() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceBackfaceNormalPass::GetNormalTexture()
{
  return this->NormalTexture;
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::AllocateResources(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->NormalTexture || this->NormalTexture->GetWidth() != static_cast<unsigned int>(width) ||
    this->NormalTexture->GetHeight() != static_cast<unsigned int>(height))
  {
    // New or resized: the whole texture is cleared once.
    this->Internals->Normals.Reset();
  }
  if (!this->NormalTexture)
  {
    this->NormalTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->NormalTexture->SetContext(window);
    this->NormalTexture->SetFormat(GL_RGBA);
    this->NormalTexture->SetInternalFormat(GL_RGBA32F);
    this->NormalTexture->SetDataType(GL_FLOAT);
    // Sampled texel for pixel, never filtered.
    this->NormalTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->NormalTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->NormalTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->NormalTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->NormalTexture->Allocate2D(width, height, 4, VTK_FLOAT);
  }
  if (!this->DepthTexture)
  {
    this->DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->DepthTexture->SetContext(window);
    this->DepthTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
  }
  this->NormalTexture->Resize(width, height);
  this->DepthTexture->Resize(width, height);
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLRenderWindow* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  int width;
  int height;
  int x;
  int y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  this->AllocateResources(window, width, height);

  // Clear only where the ice can be now or was in the frame before; nothing is drawn elsewhere.
  int covered[4];
  vtkIceScreenRegion::Covered(s, width, height, covered);
  int normalsToClear[4];
  this->Internals->Normals.ToClear(covered, width, height, normalsToClear);

  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);

  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, this->NormalTexture);
  this->FrameBuffer->ActivateDrawBuffers(1);
  this->FrameBuffer->AddDepthAttachment(this->DepthTexture);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClearDepth(1.0);
  {
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglScissor(normalsToClear[0], normalsToClear[1], normalsToClear[2] - normalsToClear[0],
      normalsToClear[3] - normalsToClear[1]);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    // The depth buffer serves this pass only: its covered part is enough.
    state->vtkglScissor(covered[0], covered[1], covered[2] - covered[0], covered[3] - covered[1]);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }
  state->vtkglScissor(0, 0, width, height);

  // SetShaderParameters culls the front faces of the ice; the actors' own culling comes back
  // with the next vtkProperty::Render, and the saved state when the pass ends.
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  int cullMode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  this->Internals->State = state;

  this->PreRender(s);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    this->NumberOfRenderedProps += s->GetPropArray()[i]->RenderOpaqueGeometry(renderer);
  }
  // Cracks that perturb the refraction stand in for the back face where they are nearer.
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (vtkIceMapper* mapper = vtkIceMapper::GetIceMapperOf(prop))
    {
      mapper->RenderCracks(renderer, static_cast<vtkActor*>(prop), false);
    }
  }
  this->PostRender(s);
  this->Internals->State = nullptr;
  state->vtkglCullFace(static_cast<unsigned int>(cullMode));

  this->FrameBuffer->RemoveColorAttachments(1);
  this->FrameBuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkIceBackfaceNormalPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  vtkShaderProgram::Substitute(fragmentShader, "//ICEHOOK::Output",
    vtkIceShaderSections::Get(vtkIceBackfaceNormalFS, "Impl"));
  vtkShaderProgram::Substitute(fragmentShader, "//ICEHOOK::CrackOutput",
    vtkIceShaderSections::Get(vtkIceBackfaceNormalFS, "Crack"));
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceBackfaceNormalPass::SetShaderParameters(
  vtkShaderProgram*, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  // Called for each draw after the actor's property has set its culling: the ice surface draws
  // only its back faces (the shader still discards front faces, now none reach it). Cracks
  // drawn into this pass are left alone (vtkIceMapper::RenderCracks draws them unculled).
  if (this->Internals->State && vtkIceMapper::SafeDownCast(mapper))
  {
    this->Internals->State->vtkglCullFace(GL_FRONT);
    this->Internals->State->vtkglEnable(GL_CULL_FACE);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->FrameBuffer)
  {
    this->FrameBuffer->ReleaseGraphicsResources(w);
  }
  for (vtkTextureObject* texture : { this->NormalTexture.Get(), this->DepthTexture.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  }
  this->FrameBuffer = nullptr;
  this->NormalTexture = nullptr;
  this->DepthTexture = nullptr;
}

//------------------------------------------------------------------------------
void vtkIceBackfaceNormalPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalTexture: " << this->NormalTexture.Get() << "\n";
}
