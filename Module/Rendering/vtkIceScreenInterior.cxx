// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceScreenInterior.h"

#include "vtkIceDepthIntervalPass.h"
#include "vtkIceFrame.h"
#include "vtkIceMapper.h"
#include "vtkIceOptics.h"
#include "vtkIceDepthIntervalFS.h"
#include "vtkIceExitPointFS.h"
#include "vtkIceScreenInteriorFS.h"
#include "vtkIceScreenRegion.h"
#include "vtkIceShaderSections.h"
#include "vtkIceInteriorTable.h"
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

//------------------------------------------------------------------------------
vtkIceScreenInterior::vtkIceScreenInterior() = default;

//------------------------------------------------------------------------------
vtkIceScreenInterior::~vtkIceScreenInterior() = default;

namespace
{
// What of the interior the look has: the milky core and bubbles, the air planes, the cracks. Each
// part's code is compiled in only where the look has it (llvmpipe would run the others anyway).
struct Parts
{
  bool Cloud;
  bool Air;
  bool Cracks;
};

Parts InteriorParts(vtkIceProperty* look)
{
  return { look->HasMilkyCore() || look->GetBubbleDensity() > 0.0,
    look->GetNumberOfAirPlanes() > 0, look->GetNumberOfCracks() > 0 };
}

// The programs' declarations for the renderer's lights (VTK's declarations and light loop, as
// the surface's), an environment sampled rough or sharp, and the interior's parts (`defines`).
std::string Declarations(
  vtkOpenGLRenderer* renderer, vtkIceProperty* look, const std::string& defines)
{
  using vtkIceShaderSections::Get;
  const int complexity = renderer->GetLightingCount() > 0 ? renderer->GetLightingComplexity() : 0;
  return std::string(look->GetRoughness() > 0.0 ? "#define ICE_ROUGH_ENVIRONMENT\n" : "") +
    defines + renderer->GetLightingUniforms() + vtkIceOptics + Get(vtkIceWorldSpaceFS, "Uniforms") +
    Get(vtkIceSurfaceFS, "Environment") + "uniform float iceRefractionRatio;\n" +
    Get(vtkIceDepthIntervalFS, "Normal") + vtkIceInteriorTable::Declarations() +
    vtkIceInteriorTable::Functions(complexity, renderer->GetLightingCount()) +
    Get(vtkIceScreenInteriorFS, "Dec") + Get(vtkIceExitPointFS, "Exit");
}

// A quad's fragment shader: `declarations` and `body` in VTK's full-screen-quad template.
std::string QuadShader(const std::string& declarations, const std::string& body)
{
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", declarations);
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", body);
  return fs;
}

// The interior's quad for the programs' `declarations`.
std::string InteriorShader(const std::string& declarations)
{
  return QuadShader(declarations, vtkIceShaderSections::Get(vtkIceScreenInteriorFS, "Impl"));
}

// VTK's full-screen quad on the far plane (window depth 1): depth-tested against the prop's
// front faces' depth, it runs the shader only where they are, before shading.
std::string QuadVertexShader()
{
  std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
  vtkShaderProgram::Substitute(
    vs, "gl_Position = ndCoordIn;", "gl_Position = vec4(ndCoordIn.xy, 1.0, 1.0);");
  return vs;
}
}

//------------------------------------------------------------------------------
vtkOpenGLQuadHelper* vtkIceScreenInterior::ReadyQuad(
  vtkOpenGLRenderWindow* window, const std::string& source)
{
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Quads[source];
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(window, QuadVertexShader().c_str(), source.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program ? quad.get() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkIceScreenInterior::KeepNearest(vtkOpenGLRenderWindow* window, vtkOpenGLState* state,
  vtkIceFrame* frame, vtkTextureObject* front, vtkTextureObject* nearest)
{
  using vtkIceShaderSections::Get;
  vtkOpenGLQuadHelper* quad = this->ReadyQuad(window,
    QuadShader(
      Get(vtkIceScreenInteriorFS, "NearestDec"), Get(vtkIceScreenInteriorFS, "NearestImpl")));
  vtkShaderProgram* program = quad ? quad->Program : nullptr;
  if (!program || !frame->Textures.Bind(program, "iceDepthInterval", front) ||
    !frame->Textures.Bind(program, "iceNearestFront", nearest))
  {
    return false;
  }
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_ALWAYS);
  quad->Render();
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return true;
}

//------------------------------------------------------------------------------
void vtkIceScreenInterior::Draw(const vtkRenderState* iceState, vtkActor* actor,
  vtkIceMapper* mapper, vtkIceFrame* frame, vtkIceDepthIntervalPass* front,
  vtkTextureObject* nearest)
{
  auto* renderer = static_cast<vtkOpenGLRenderer*>(iceState->GetRenderer());
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkTextureObject* frontDepth = front->GetDepthTexture();
  vtkTextureObject* frontWindowDepth = front->GetDepthBufferTexture();
  if (!frontDepth || !frontWindowDepth)
  {
    return;
  }
  this->Target.UseDepthOf(frontWindowDepth);
  vtkIceScreenTarget::Drawing drawing(this->Target, iceState, 4);
  vtkOpenGLState* state = drawing.State;
  if (!this->Cleared)
  {
    // Nothing added, all of the ice colour kept.
    drawing.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    this->Cleared = true;
  }
  vtkIceProperty* look = mapper->GetIceProperty();
  const Parts parts = InteriorParts(look);
  if (!parts.Cloud && !parts.Air && !parts.Cracks)
  {
    return; // cleared: nothing added, all of the ice colour kept
  }

  // The draws, back to front: the milky core behind the air planes, the planes, the rest (the
  // bubbles, the cracks; and the core where no plane lies between). Each composes its
  // vec4(add, keep) in front of what the target holds: colour add + keep * colour, alpha
  // keep * alpha. The quads pass where the prop's front faces are nearer (the far plane's depth
  // against theirs), the planes where they lie behind them; neither writes depth.
  const bool coreFirst = parts.Air && look->HasMilkyCore();
  const bool rest =
    parts.Cracks || (parts.Cloud && (!coreFirst || look->GetBubbleDensity() > 0.0));
  const std::string common = parts.Cloud ? "#define ICE_INTERIOR_CLOUD\n" : "";
  vtkOpenGLQuadHelper* core = coreFirst
    ? this->ReadyQuad(window,
        InteriorShader(Declarations(renderer, look, common + "#define ICE_INTERIOR_CORE_ONLY\n")))
    : nullptr;
  vtkShaderProgram* planes =
    parts.Air ? this->Air.Ready(window, Declarations(renderer, look, common)) : nullptr;
  vtkOpenGLQuadHelper* after = rest
    ? this->ReadyQuad(window, InteriorShader(Declarations(renderer, look, common +
        (parts.Cracks ? "#define ICE_INTERIOR_CRACKS\n" : "") +
        (coreFirst ? "#define ICE_INTERIOR_AFTER_CORE\n" : ""))))
    : nullptr;
  if ((coreFirst && !core) || (parts.Air && !planes) || (rest && !after))
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
  if (nearest && !this->KeepNearest(window, state, frame, frontDepth, nearest))
  {
    return;
  }
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDepthFunc(GL_GREATER);
  vtkOpenGLState::ScopedglBlendFuncSeparate blending(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_SRC_ALPHA);
  vtkOpenGLState::ScopedglEnableDisable culling(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);

  // The first program readies the mapper's table, environment and look; the others get the
  // same uniforms.
  const vtkIceInteriorTable* interior = nullptr;
  auto ready = [&](vtkShaderProgram* program) {
    window->GetShaderCache()->ReadyShaderProgram(program);
    frame->Textures.BindScreen(program, renderer, "iceDepthInterval", frontDepth);
    frame->Textures.BindScreen(program, renderer, "iceBackNormals", frame->BackfaceNormals);
    frame->BindCubeMap(program, actor);
    renderer->UpdateLightingUniforms(program);
    if (interior)
    {
      mapper->SetScreenInteriorUniforms(renderer, actor, program);
      return true;
    }
    interior = mapper->BeginScreenInterior(renderer, actor, program);
    return interior != nullptr;
  };
  if (core)
  {
    if (!ready(core->Program))
    {
      return;
    }
    core->Render();
  }
  if (planes)
  {
    if (!ready(planes))
    {
      return;
    }
    this->Air.Draw(actor, *interior, planes);
  }
  if (after)
  {
    if (!ready(after->Program))
    {
      return;
    }
    after->Render();
  }
  mapper->EndScreenInterior(renderer);
}

//------------------------------------------------------------------------------
void vtkIceScreenInterior::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& quad : this->Quads)
  {
    quad.second->ReleaseGraphicsResources(window);
  }
  this->Quads.clear();
  this->Air.ReleaseGraphicsResources(window);
  this->Target.ReleaseGraphicsResources(window);
}
