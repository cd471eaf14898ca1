#include "vtkIceBackfaceNormalPass.h"

#include "vtkIceBackfaceNormalFS.h"
#include "vtkIceMapper.h"
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
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

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
