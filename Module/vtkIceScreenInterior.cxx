#include "vtkIceScreenInterior.h"

#include "vtkIceFrame.h"
#include "vtkIceInteriorDrawer.h"
#include "vtkIceMapper.h"
#include "vtkIceOptics.h"
#include "vtkIceScreenInteriorFS.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSinglePassInterior.h"
#include "vtkIceSurfaceFS.h"
#include "vtkIceWorldSpaceFS.h"

#include "vtkActor.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkIceVTKCompat.h"

#include <array>

//------------------------------------------------------------------------------
vtkIceScreenInterior::vtkIceScreenInterior() = default;

//------------------------------------------------------------------------------
vtkIceScreenInterior::~vtkIceScreenInterior() = default;

namespace
{
// The quad's fragment shader for the renderer's lights (VTK's declarations and light loop, as
// the surface's) and an environment sampled rough or sharp.
std::string QuadShader(vtkOpenGLRenderer* renderer, bool rough)
{
  using vtkIceShaderSections::Get;
  const int complexity = renderer->GetLightingCount() > 0 ? renderer->GetLightingComplexity() : 0;
  std::string declarations = std::string(rough ? "#define ICE_ROUGH_ENVIRONMENT\n" : "") +
    renderer->GetLightingUniforms() + vtkIceOptics + Get(vtkIceWorldSpaceFS, "Uniforms") +
    Get(vtkIceSurfaceFS, "Environment") + "uniform float iceRefractionRatio;\n" +
    vtkIceSinglePassInterior::Declarations() +
    vtkIceSinglePassInterior::Functions(complexity, renderer->GetLightingCount()) +
    Get(vtkIceScreenInteriorFS, "Dec");
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", declarations);
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", Get(vtkIceScreenInteriorFS, "Impl"));
  return fs;
}
}

//------------------------------------------------------------------------------
void vtkIceScreenInterior::Draw(const vtkRenderState* iceState, vtkActor* actor,
  vtkIceMapper* mapper, vtkIceFrame* frame, vtkTextureObject* frontDepth)
{
  auto* renderer = static_cast<vtkOpenGLRenderer*>(iceState->GetRenderer());
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkIceScreenTarget::Drawing drawing(this->Target, iceState, 4);
  vtkOpenGLState* state = drawing.State;
  if (!this->Cleared)
  {
    // Nothing added, all of the ice colour kept, no ice nearer than the far plane.
    drawing.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    drawing.ClearDepth(1.0);
    this->Cleared = true;
  }
  state->vtkglDepthFunc(GL_LESS);

  const std::string source = QuadShader(renderer, mapper->GetIceProperty()->GetRoughness() > 0.0);
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Quads[source];
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(window, nullptr, source.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  vtkShaderProgram* program = quad->Program;
  if (!program)
  {
    return;
  }

  // Only inside the prop's projected bounding box: elsewhere it has no front face.
  int width;
  int height;
  int x;
  int y;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  int covered[4];
  vtkProp* prop = actor;
  vtkIceScreenRegion::Covered(renderer, &prop, 1, width, height, covered);
  state->vtkglScissor(covered[0], covered[1], covered[2] - covered[0], covered[3] - covered[1]);

  frame->Textures.BindScreen(program, renderer, "iceDepthInterval", frontDepth);
  frame->Textures.BindScreen(program, renderer, "iceBackNormals", frame->BackfaceNormals);
  frame->BindCubeMap(program, actor);
  renderer->UpdateLightingUniforms(program);
  vtkIceInteriorDrawer::BeginScreenInterior(mapper, renderer, actor, program);
  quad->Render();
  vtkIceInteriorDrawer::EndScreenInterior(mapper, renderer);
}

//------------------------------------------------------------------------------
void vtkIceScreenInterior::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& quad : this->Quads)
  {
    quad.second->ReleaseGraphicsResources(window);
  }
  this->Quads.clear();
  this->Target.ReleaseGraphicsResources(window);
}
