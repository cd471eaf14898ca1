#include "vtkIceDepthIntervalPass.h"

#include "vtkIceDepthIntervalFS.h"
#include "vtkIceMapper.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"

#include "vtkCamera.h"
#include "vtkMath.h"
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

#include <algorithm>
#include <cfloat>

vtkStandardNewMacro(vtkIceDepthIntervalPass);

namespace
{
// View-depth range of the props' bounding boxes, for the camera at `eye` looking along `direction`.
bool FitDepthRange(const vtkRenderState* s, const double eye[3], const double direction[3],
  double range[2])
{
  range[0] = VTK_DOUBLE_MAX;
  range[1] = -VTK_DOUBLE_MAX;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    const double* b = s->GetPropArray()[i]->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      const double p[3] = { b[corner & 1] - eye[0], b[2 + ((corner >> 1) & 1)] - eye[1],
        b[4 + ((corner >> 2) & 1)] - eye[2] };
      const double depth = vtkMath::Dot(p, direction);
      range[0] = std::min(range[0], depth);
      range[1] = std::max(range[1], depth);
    }
  }
  return range[0] <= range[1];
}
}

class vtkIceDepthIntervalPass::vtkInternals
{
public:
  vtkIceScreenRegion::Tracker Interval; // what of DepthTexture may not hold the empty interval
  vtkOpenGLState* State = nullptr;      // while Render runs
};

//------------------------------------------------------------------------------
vtkIceDepthIntervalPass::vtkIceDepthIntervalPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkIceDepthIntervalPass::~vtkIceDepthIntervalPass() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceDepthIntervalPass::GetDepthTexture()
{
  return this->DepthTexture;
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::AllocateResources(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->DepthTexture || this->DepthTexture->GetWidth() != static_cast<unsigned int>(width) ||
    this->DepthTexture->GetHeight() != static_cast<unsigned int>(height))
  {
    // New or resized: the whole texture is cleared once.
    this->Internals->Interval.Reset();
  }
  if (!this->DepthTexture)
  {
    this->DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->DepthTexture->SetContext(window);
    this->DepthTexture->SetFormat(GL_RG);
    this->DepthTexture->SetInternalFormat(GL_RG32F);
    this->DepthTexture->SetDataType(GL_FLOAT);
    this->DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->DepthTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->DepthTexture->Allocate2D(width, height, 2, VTK_FLOAT);
  }
  if (!this->ZBufferTexture)
  {
    this->ZBufferTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->ZBufferTexture->SetContext(window);
    this->ZBufferTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
  }
  this->DepthTexture->Resize(width, height);
  this->ZBufferTexture->Resize(width, height);
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLRenderWindow* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  vtkCamera* camera = renderer->GetActiveCamera();

  int width;
  int height;
  int x;
  int y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  this->AllocateResources(window, width, height);

  // Clear only where the ice can be now or was in the frame before; nothing is drawn elsewhere,
  // so the rest of the texture keeps the empty interval the cracks find outside the ice.
  int covered[4];
  vtkIceScreenRegion::Covered(s, width, height, covered);
  int intervalToClear[4];
  this->Internals->Interval.ToClear(covered, width, height, intervalToClear);

  // Near and far planes on the props' bounding box: the depth test in this pass gets all the
  // depth buffer's precision. The texture stores linear view depth, independent of them.
  double clipping[2];
  camera->GetClippingRange(clipping);
  if (FitDepthRange(s, camera->GetPosition(), camera->GetDirectionOfProjection(), this->DepthRange))
  {
    const double nearest = std::max(this->DepthRange[0], 1e-3 * this->DepthRange[1]);
    camera->SetClippingRange(0.99 * nearest, 1.01 * this->DepthRange[1]);
  }

  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);

  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, this->DepthTexture);
  this->FrameBuffer->ActivateDrawBuffers(1);
  this->FrameBuffer->AddDepthAttachment(this->ZBufferTexture);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDepthMask(GL_TRUE);
  // Empty interval where there is no ice: front beyond back.
  state->vtkglClearColor(FLT_MAX, -FLT_MAX, 0.0, 0.0);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(intervalToClear[0], intervalToClear[1],
    intervalToClear[2] - intervalToClear[0], intervalToClear[3] - intervalToClear[1]);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  // The depth buffer serves this pass only: its covered part is enough, and drawing stays there.
  state->vtkglScissor(covered[0], covered[1], covered[2] - covered[0], covered[3] - covered[1]);

  // SetShaderParameters culls the faces a stage does not want; the actors' own culling comes
  // back with the next vtkProperty::Render, and the saved state when the pass ends.
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  int cullMode = GL_BACK;
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  this->Internals->State = state;

  this->PreRender(s);
  // Stage 0: nearest front face into R. Stage 1: farthest back face into G.
  for (this->Stage = 0; this->Stage < 2; ++this->Stage)
  {
    const bool front = this->Stage == 0;
    state->vtkglColorMask(front, !front, GL_FALSE, GL_FALSE);
    state->vtkglClearDepth(front ? 1.0 : 0.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    state->vtkglDepthFunc(front ? GL_LESS : GL_GREATER);
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      this->NumberOfRenderedProps += s->GetPropArray()[i]->RenderOpaqueGeometry(renderer);
    }
    ++this->NumberOfGeometryPasses;
  }
  this->Stage = 0;
  this->PostRender(s);
  this->Internals->State = nullptr;
  state->vtkglCullFace(static_cast<unsigned int>(cullMode));
  state->vtkglClearDepth(1.0);

  this->FrameBuffer->RemoveColorAttachments(1);
  this->FrameBuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  camera->SetClippingRange(clipping);
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkIceDepthIntervalPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  vtkIceShaderSections::InsertDeclarations(
    fragmentShader, vtkIceShaderSections::Get(vtkIceDepthIntervalFS, "Dec"));
  vtkShaderProgram::Substitute(fragmentShader, "//ICEHOOK::Output",
    vtkIceShaderSections::Get(vtkIceDepthIntervalFS, "Impl"));
  return true;
}

//------------------------------------------------------------------------------
bool vtkIceDepthIntervalPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  // Called for each draw after the actor's property has set its culling: stage 0 wants the
  // front faces, stage 1 the back faces (the shader still discards the others; none reach it).
  if (this->Internals->State && vtkIceMapper::SafeDownCast(mapper))
  {
    this->Internals->State->vtkglCullFace(this->Stage == 0 ? GL_BACK : GL_FRONT);
    this->Internals->State->vtkglEnable(GL_CULL_FACE);
  }
  if (program->IsUniformUsed("iceDepthStage"))
  {
    program->SetUniformi("iceDepthStage", this->Stage);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->FrameBuffer)
  {
    this->FrameBuffer->ReleaseGraphicsResources(w);
  }
  for (vtkTextureObject* texture : { this->DepthTexture.Get(), this->ZBufferTexture.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  }
  this->FrameBuffer = nullptr;
  this->DepthTexture = nullptr;
  this->ZBufferTexture = nullptr;
}

//------------------------------------------------------------------------------
void vtkIceDepthIntervalPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthRange: " << this->DepthRange[0] << ", " << this->DepthRange[1] << "\n";
  os << indent << "NumberOfGeometryPasses: " << this->NumberOfGeometryPasses << "\n";
}
