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
// What of the interior the look has, as the quad's #defines: the milky core and bubbles, the air
// planes, the cracks; only those are compiled in (llvmpipe would run the code of the others
// anyway). Empty: the look has no interior, and the quad would add nothing.
std::string InteriorParts(vtkIceProperty* look)
{
  return std::string(look->HasMilkyCore() || look->GetBubbleDensity() > 0.0
                       ? "#define ICE_INTERIOR_CLOUD\n"
                       : "") +
    (look->GetNumberOfAirPlanes() > 0 ? "#define ICE_INTERIOR_AIR\n" : "") +
    (look->GetNumberOfCracks() > 0 ? "#define ICE_INTERIOR_CRACKS\n" : "");
}

// The quad's fragment shader for the renderer's lights (VTK's declarations and light loop, as
// the surface's), an environment sampled rough or sharp, and the interior's parts.
std::string QuadShader(vtkOpenGLRenderer* renderer, vtkIceProperty* look, const std::string& parts)
{
  using vtkIceShaderSections::Get;
  const int complexity = renderer->GetLightingCount() > 0 ? renderer->GetLightingComplexity() : 0;
  std::string declarations =
    std::string(look->GetRoughness() > 0.0 ? "#define ICE_ROUGH_ENVIRONMENT\n" : "") + parts +
    renderer->GetLightingUniforms() + vtkIceOptics + Get(vtkIceWorldSpaceFS, "Uniforms") +
    Get(vtkIceSurfaceFS, "Environment") + "uniform float iceRefractionRatio;\n" +
    Get(vtkIceDepthIntervalFS, "Normal") +
    Get(vtkIceScreenInteriorFS, "Tiles") + vtkIceInteriorTable::Declarations() +
    vtkIceInteriorTable::Functions(complexity, renderer->GetLightingCount()) +
    Get(vtkIceScreenInteriorFS, "Dec") + Get(vtkIceExitPointFS, "Exit");
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", declarations);
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", Get(vtkIceScreenInteriorFS, "Impl"));
  return fs;
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
  // The quad at the far plane passes where the front faces are nearer; their depth stays.
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDepthFunc(GL_GREATER);

  const std::string parts = InteriorParts(mapper->GetIceProperty());
  if (parts.empty())
  {
    return; // cleared: nothing added, all of the ice colour kept
  }
  const std::string source = QuadShader(renderer, mapper->GetIceProperty(), parts);
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Quads[source];
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(window, QuadVertexShader().c_str(), source.c_str(), ""));
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
  // One prop: its own front faces are the nearest (the test never discards).
  frame->Textures.BindScreen(program, renderer, "iceNearestFront", nearest ? nearest : frontDepth);
  frame->BindCubeMap(program, actor);
  renderer->UpdateLightingUniforms(program);
  const vtkIceInteriorTable* interior = mapper->BeginScreenInterior(renderer, actor, program);
  if (!interior)
  {
    return;
  }
  this->Tiles.Update(renderer, actor, *interior, width, height, covered);
  this->Tiles.SetUniforms(program);
  quad->Render();
  this->Tiles.Finish();
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
  this->Tiles.ReleaseGraphicsResources(window);
  this->Target.ReleaseGraphicsResources(window);
}
