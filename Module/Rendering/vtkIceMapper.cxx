// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceMapper.h"

#include "vtkIceBackfaceCulling.h"
#include "vtkIceBackNormalsFS.h"
#include "vtkIceBumpFS.h"
#include "vtkIceDebugDepthFS.h"
#include "vtkIceExitPointFS.h"
#include "vtkIceFrame.h"
#include "vtkIceGlistening.h"
#include "vtkIceGlisteningTexture.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceInteriorSources.h"
#include "vtkIceOptics.h"
#include "vtkIcePrefilteredEnvironment.h"
#include "vtkIcePropertyUniforms.h"
#include "vtkIceShaderSections.h"
#include "vtkIceInteriorTable.h"
#include "vtkIceLateDepthTest.h"
#include "vtkIceStaticEnvironment.h"
#include "vtkIceSurfaceCheck.h"
#include "vtkIceScreenInteriorFS.h"
#include "vtkIceSurfaceFS.h"
#include "vtkIceSurfaceVS.h"
#include "vtkIceTraceFS.h"
#include "vtkIceCracksFS.h"
#include "vtkIceTraceTextures.h"
#include "vtkIceTriangleBVH.h"
#include "vtkIceTwoSidedFS.h"
#include "vtkIceNormalMapFS.h"
#include "vtkIceValueNoise.h"

#include "vtkActor.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkIceMapper);

namespace
{
enum ShaderParts
{
  BumpPart = 4,
  NormalMapPart = 8,
  GlisteningPart = 16,
  RoughPart = 64,
  TracePart = 128,
  TraceCracksPart = 256,
  TraceBubblesPart = 512,
  TraceAirPart = 1024,
  EncodedEnvironmentPart = 2048, // the environment shown gamma-corrected (ICE_ENVIRONMENT_SPACE)
  TraceWetBasePart = 4096,
  LateDepthTestPart = 8192 // llvmpipe into a multisampled target (vtkIceLateDepthTest)
};

}

//------------------------------------------------------------------------------
vtkIceMapper::vtkIceMapper()
  : IceProperty(vtkSmartPointer<vtkIceProperty>::New())
  , InteriorTable(new vtkIceInteriorTable)
  , Interior(new vtkIceInteriorSources)
  , Environment(new vtkIceStaticEnvironment)
  , Prefiltered(new vtkIcePrefilteredEnvironment)
  , Culling(new vtkIceBackfaceCulling)
{
  // Tinting by scalars is asked for, not inherited: filters hand their scalars on (an iso-surface
  // carries the contoured array), and VTK's default would replace the ice colour by them.
  this->ScalarVisibilityOff();
}

//------------------------------------------------------------------------------
vtkIceMapper::~vtkIceMapper() = default;

//------------------------------------------------------------------------------
void vtkIceMapper::SetIceProperty(vtkIceProperty* property)
{
  if (property && property == this->IceProperty)
  {
    return;
  }
  this->IceProperty = property ? property : vtkSmartPointer<vtkIceProperty>::New().Get();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIcePaperInterior* vtkIceMapper::GetPaperInterior()
{
  if (!this->PaperInterior)
  {
    this->PaperInterior = vtkSmartPointer<vtkIcePaperInterior>::New();
  }
  return this->PaperInterior;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetPaperInterior(vtkIcePaperInterior* interior)
{
  if (interior && interior == this->PaperInterior)
  {
    return;
  }
  this->PaperInterior = interior ? interior : vtkSmartPointer<vtkIcePaperInterior>::New().Get();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkIceMapper::CracksPerturbRefraction() const
{
  return this->PaperInterior && this->PaperInterior->GetCracksPerturbRefraction();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkIceMapper::GetMTime()
{
  // A change of the look rebuilds what a change of the mapper does (shaders, buffers, the cube
  // map's OnChange test through the actor's redraw time).
  return std::max(this->Superclass::GetMTime(), this->IceProperty->GetMTime());
}

//------------------------------------------------------------------------------
void vtkIceMapper::GetLookBounds(double bounds[6])
{
  if (vtkMath::AreBoundsInitialized(this->PlacementBounds))
  {
    std::copy(this->PlacementBounds, this->PlacementBounds + 6, bounds);
    return;
  }
  this->PreparedInput->GetBounds(bounds);
}

//------------------------------------------------------------------------------
bool vtkIceMapper::EmptyInputIsPiece()
{
  return vtkMath::AreBoundsInitialized(this->PlacementBounds);
}

//------------------------------------------------------------------------------
double* vtkIceMapper::GetBounds()
{
  double* own = this->Superclass::GetBounds();
  if (!this->EmptyInputIsPiece())
  {
    return own;
  }
  std::copy(this->PlacementBounds, this->PlacementBounds + 6, this->Bounds);
  return this->Bounds;
}

//------------------------------------------------------------------------------
double vtkIceMapper::InputExtent()
{
  double bounds[6];
  this->GetLookBounds(bounds);
  return std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-12 });
}

//------------------------------------------------------------------------------
bool vtkIceMapper::HasInterior() const
{
  const int view = this->DebugView;
  if (view == DebugCracksClipped || view == DebugCracksUnclipped || view == DebugAir)
  {
    return true;
  }
  return view == DebugOff &&
    (this->IceProperty->GetNumberOfCracks() > 0 || this->IceProperty->GetNumberOfAirPlanes() > 0 ||
      ((this->IceProperty->HasMilkyCore() || this->IceProperty->GetBubbleDensity() > 0.0) &&
        this->InteriorMethod != InteriorPaperPasses));
}

//------------------------------------------------------------------------------
bool vtkIceMapper::UsesScreenInterior() const
{
  return this->InteriorMethod == InteriorScreenSpace && this->DebugView != DebugCracksUnclipped &&
    this->HasInterior();
}

//------------------------------------------------------------------------------
int vtkIceMapper::GetFrameNeeds()
{
  int needs = 0;
  if (this->TwoSidedRefraction)
  {
    needs |= vtkIceFrame::NeedsBackfaceNormals;
  }
  if (this->IceProperty->Absorbs())
  {
    needs |= vtkIceFrame::NeedsPathLength;
  }
  const int view = this->DebugView;
  if (view == DebugFrontDepth || view == DebugBackDepth ||
    (this->CracksPerturbRefraction() && this->IceProperty->GetNumberOfCracks() > 0))
  {
    needs |= vtkIceFrame::NeedsDepthIntervalBeforeScene;
  }
  if (this->UsesScreenInterior())
  {
    needs |= vtkIceFrame::NeedsBackDepthForInterior | vtkIceFrame::NeedsScreenInterior;
  }
  else if (this->HasInterior())
  {
    // The paper's cracks and air are clipped by the interval and drawn at the ice's front depth.
    needs |= vtkIceFrame::NeedsDepthIntervalForInterior;
  }
  return needs;
}

//------------------------------------------------------------------------------
int vtkIceMapper::GetFrameInputs(vtkProp* prop)
{
  vtkIceFrame* frame = vtkIceFrame::Of(prop);
  const int view = this->DebugView;
  return frame
    ? frame->InputsOf(prop, this->GetFrameNeeds(), this->TwoSidedMethod == TwoSidedExitPoint,
        view == DebugFrontDepth || view == DebugBackDepth)
    : 0;
}

//------------------------------------------------------------------------------
int vtkIceMapper::ShaderVariant() const
{
  int variant = 0;
  if (this->IceProperty->GetBumpStrength() > 0.0)
  {
    variant |= this->IceProperty->GetNormalMap() ? NormalMapPart : BumpPart;
  }
  if (this->IceProperty->GetGlistening())
  {
    variant |= GlisteningPart;
  }
  if (this->IceProperty->GetRoughness() > 0.0)
  {
    variant |= RoughPart;
  }
  if (this->TracesInterior())
  {
    variant |= TracePart;
  }
  if (this->TracesCracks())
  {
    variant |= TraceCracksPart;
  }
  if (this->TracesBubbles())
  {
    variant |= TraceBubblesPart;
  }
  if (this->TracesAir())
  {
    variant |= TraceAirPart;
  }
  if (this->WetBase && (variant & TracePart))
  {
    variant |= TraceWetBasePart;
  }
  // Known from BindEnvironment, before VTK picks the shader.
  if (this->ActiveEnvironmentObject &&
    this->Environment->GetColorSpace() != vtkIceStaticEnvironment::AsSampled)
  {
    variant |= EncodedEnvironmentPart;
  }
  // Known from RenderPieceStart, as the environment.
  if (this->LateDepthTest)
  {
    variant |= LateDepthTestPart;
  }
  return variant;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::TracesInterior() const
{
  return this->MaxBounces > 1 && this->TwoSidedRefraction &&
    this->TwoSidedMethod == TwoSidedExitPoint;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The superclass must always run: it also updates the light complexity.
  const bool superclassNeeds = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  auto built = this->ShaderVariantBuilt.find(&cellBO);
  const bool variantChanged =
    built != this->ShaderVariantBuilt.end() && built->second != this->ShaderVariant();
  return superclassNeeds || variantChanged;
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  // The frame of vtkIcePass drawing this ice now, if any.
  vtkIceFrame* frame = vtkIceFrame::Of(act);
  this->ActiveFrameInputs = this->GetFrameInputs(act);
  if (this->HelpersSawPass && !frame)
  {
    // The pass is gone from this ice: its cracks and air, drawn only by it, let it go.
    if (this->PaperInterior)
    {
      this->PaperInterior->ForgetRenderPasses();
    }
    this->HelpersSawPass = false;
  }
  this->BindEnvironment(ren, act);
  // The framebuffer drawn into is bound: the sub-passes' are single-sampled, the scene's may not.
  this->LateDepthTest = vtkIceLateDepthTest::Wanted();
  if (this->IceProperty->GetNormalMap() && this->IceProperty->GetBumpStrength() > 0.0)
  {
    this->IceProperty->GetNormalMap()->Render(ren);
  }
  this->WarnSettingsWithoutEffect(frame != nullptr);
  this->Superclass::RenderPieceStart(ren, act);
  // The closure check costs about a frame of a large input (1M triangles: 0.3-0.7 s), once per
  // input: a still input pays it at its second frame in the main scene, an input changed every
  // frame (an animation) never.
  bool cull = false;
  if (!vtkIceBackfaceCulling::InSubPass(act))
  {
    if (this->CullHiddenBackfaces && (this->InputOpenEdges >= 0 || this->InputDrawnBefore))
    {
      this->CheckInputClosure();
      cull = vtkIceBackfaceCulling::BackfacesHidden(ren, act, this, this->InputClosedOutward);
    }
    this->InputDrawnBefore = true;
    this->LastDrawCulledBackfaces = cull;
  }
  if (cull)
  {
    this->Culling->Begin(ren);
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::WarnSettingsWithoutEffect(bool withPass)
{
  if (this->IceProperty->GetSnowAmount() > 0.0 && !this->IceProperty->GetGlistening() &&
    !this->WarnedSnowWithoutGlistening)
  {
    vtkWarningMacro(<< "SnowAmount " << this->IceProperty->GetSnowAmount()
                    << " shows nothing: the glistening part draws the snow. Turn Glistening on "
                       "to see it.");
    this->WarnedSnowWithoutGlistening = true;
  }
  if (this->IceProperty->Absorbs() && !withPass && !this->WarnedAbsorptionWithoutPass)
  {
    vtkWarningMacro(<< "AttenuationColor and AttenuationDistance show nothing without vtkIcePass "
                       "on the renderer: its back faces give the path in the ice.");
    this->WarnedAbsorptionWithoutPass = true;
  }
  if (this->IceProperty->HasMilkyCore() && this->InteriorMethod == InteriorPaperPasses &&
    !this->WarnedCoreWithPaperPasses)
  {
    vtkWarningMacro(<< "MilkyCoreRadius " << this->IceProperty->GetMilkyCoreRadius()
                    << " shows nothing with InteriorPaperPasses: the screen-space interior draws "
                       "the milky core. Set InteriorMethod to InteriorScreenSpace to see it.");
    this->WarnedCoreWithPaperPasses = true;
  }
  if (this->IceProperty->GetBubbleDensity() > 0.0 && this->InteriorMethod == InteriorPaperPasses &&
    !this->WarnedBubblesWithPaperPasses)
  {
    vtkWarningMacro(<< "BubbleDensity " << this->IceProperty->GetBubbleDensity()
                    << " shows nothing with InteriorPaperPasses: the screen-space interior draws "
                       "the bubbles. Set InteriorMethod to InteriorScreenSpace to see them.");
    this->WarnedBubblesWithPaperPasses = true;
  }
  if (this->MaxBounces > 1 && this->TwoSidedMethod != TwoSidedExitPoint &&
    !this->WarnedBouncesWithoutExitPoint)
  {
    vtkWarningMacro(<< "MaxBounces " << this->MaxBounces
                    << " shows nothing with TwoSidedBlendedNormals: the light is traced from the "
                       "exit point's refraction. Call SetTwoSidedMethodToExitPoint() to see it.");
    this->WarnedBouncesWithoutExitPoint = true;
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Culling->End();
  this->Superclass::RenderPieceFinish(ren, act);
  if (this->IceProperty->GetNormalMap() && this->IceProperty->GetBumpStrength() > 0.0)
  {
    this->IceProperty->GetNormalMap()->PostRender(ren);
  }
  this->UnbindEnvironment(ren);
  this->FinishInterior(ren);
}

//------------------------------------------------------------------------------
void vtkIceMapper::BindEnvironment(vtkRenderer* ren, vtkActor* act)
{
  // A dynamic cube map is handed to the shader by the pass that rendered it.
  vtkIceFrame* frame = vtkIceFrame::Of(act);
  vtkTextureObject* dynamicCubeMap = frame ? frame->CubeMapOf(act) : nullptr;
  this->EnvironmentEncoded = vtkIceStaticEnvironment::ShowsEncodedLight(ren);
  this->ActiveEnvironmentObject = dynamicCubeMap
    ? nullptr
    : this->Environment->Bind(ren, this->WarnWithoutEnvironment ? this : nullptr);
  if (this->IceProperty->GetRoughness() > 0.0)
  {
    this->ActiveRoughEnvironment =
      this->Prefiltered->Update(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()),
        dynamicCubeMap ? dynamicCubeMap : this->ActiveEnvironmentObject,
        dynamicCubeMap ? frame->CubeMapVersion : this->Environment->GetVersion());
    this->ActiveRoughEnvironment->Activate();
    this->Prefiltered->BeginSampling(
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState());
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::UnbindEnvironment(vtkRenderer* ren)
{
  this->Environment->Unbind(ren);
  this->ActiveEnvironmentObject = nullptr;
  if (this->ActiveRoughEnvironment)
  {
    this->ActiveRoughEnvironment->Deactivate();
    this->Prefiltered->EndSampling(
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState());
    this->ActiveRoughEnvironment = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetEnvironmentUniforms(vtkShaderProgram* program)
{
  // A dynamic cube map holds the scene at the raw world direction.
  static const float identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  float lookup[9];
  const float* matrix =
    this->ActiveEnvironmentObject ? this->Environment->GetLookupMatrix() : identity;
  std::copy(matrix, matrix + 9, lookup);
  if (this->MirroredEnvironment)
  {
    // The lookup of the mirrored direction (x, -y, z): the matrix's second column negated.
    lookup[3] = -lookup[3];
    lookup[4] = -lookup[4];
    lookup[5] = -lookup[5];
  }
  program->SetUniformMatrix3x3("iceEnvironmentMatrix", lookup);
  program->SetUniformi("iceEnvironmentColorSpace",
    this->ActiveEnvironmentObject ? this->Environment->GetColorSpace() : 0);
  // Beer-Lambert's factor acts on light: on gamma-encoded colours it is its own 1/2.2th power
  // (else a path absorbs as if 2.2 times as long: measured against Mitsuba in ice-render's scene).
  if (program->IsUniformUsed("iceAbsorptionPower"))
  {
    program->SetUniformf("iceAbsorptionPower", this->EnvironmentEncoded ? 1.0f / 2.2f : 1.0f);
  }
  if (this->ActiveEnvironmentObject)
  {
    program->SetUniformi("iceEnvironment", this->ActiveEnvironmentObject->GetTextureUnit());
  }
  if (this->ActiveRoughEnvironment)
  {
    program->SetUniformi(
      "iceEnvironmentPrefiltered", this->ActiveRoughEnvironment->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
bool vtkIceMapper::DrawsScalarColors()
{
  // The conditions of VTK's ReplaceShaderColor (the copy drawn has no cell scalars).
  return this->VBOs->GetNumberOfComponents("scalarColor") != 0 ||
    (this->InterpolateScalarsBeforeMapping && this->ColorCoordinates);
}

//------------------------------------------------------------------------------
void vtkIceMapper::AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act)
{
  using vtkIceShaderSections::Get;
  const std::string optics = vtkIceOptics;
  const int variant = this->ShaderVariant();
  this->ShaderVariantBuilt[this->LastBoundBO] = variant;

  // What vtkIcePass's frame gives the program, as #defines (vtkIceFrame::Defines).
  parts.FragmentDeclarations += "//ICEHOOK::FrameInputs\n";
  parts.VertexDeclarations += optics + Get(vtkIceSurfaceVS, "Dec");
  parts.VertexImpl += Get(vtkIceSurfaceVS, "Impl");
  if (variant & RoughPart)
  {
    parts.FragmentDeclarations += "#define ICE_ROUGH_ENVIRONMENT\n";
  }
  parts.FragmentDeclarations += std::string("#define ICE_ENVIRONMENT_SPACE ") +
    (variant & EncodedEnvironmentPart ? "1\n" : "0\n");
  parts.FragmentDeclarations +=
    optics + Get(vtkIceSurfaceFS, "Environment") + Get(vtkIceSurfaceFS, "Dec");
  parts.FragmentImpl += Get(vtkIceSurfaceFS, "Impl");
  if (variant & LateDepthTestPart)
  {
    parts.FragmentExtensions += vtkIceLateDepthTest::Extension();
    parts.FragmentDeclarations += vtkIceLateDepthTest::Declarations();
    parts.FragmentImpl += vtkIceLateDepthTest::Code();
  }
  if (this->DrawsScalarColors())
  {
    // VTK's colour code (before the lighting) holds the mapped colour times the diffuse
    // intensity; the mapped colour replaces IceColor as the tint.
    parts.Hooks.emplace_back(
      "ScalarColor", "iceColor = diffuseColor / max(diffuseIntensity, 1.0e-6);");
  }
  if (variant & BumpPart)
  {
    parts.FragmentDeclarations += Get(vtkIceValueNoise, "Dec") + Get(vtkIceBumpFS, "Dec");
    parts.Hooks.emplace_back("SurfaceNormal", Get(vtkIceBumpFS, "Impl"));
  }
  if (variant & NormalMapPart)
  {
    parts.FragmentDeclarations += Get(vtkIceNormalMapFS, "Dec");
    parts.Hooks.emplace_back("SurfaceNormal", Get(vtkIceNormalMapFS, "Impl"));
  }
  if (variant & GlisteningPart)
  {
    parts.FragmentDeclarations += vtkIceGlistening::Declarations();
    // The light calls follow VTK's light loop (set by the superclass's GetNeedToRebuildShaders).
    const auto& lights = this->PrimitiveInfo[this->LastBoundBO];
    parts.Hooks.emplace_back("Glistening",
      vtkIceGlistening::Code(
        lights.LastLightCount > 0 ? lights.LastLightComplexity : 0, lights.LastLightCount));
  }
  this->AddFrameInputParts(parts);
  if (variant & TracePart)
  {
    // With the exit point's frame inputs only: it replaces that estimate's light.
    // The cracks on the segments after a reflection inside: their search before the trace.
    // The bubbles and the air planes need the interior's declarations whole (its uniforms,
    // noise, grid walk, air atlas).
    std::string cracks = std::string(variant & TraceWetBasePart ? "#define ICE_TRACE_WET_BASE\n" : "") +
      (variant & TraceCracksPart ? "#define ICE_TRACE_CRACKS\n" : "");
    if (variant & (TraceBubblesPart | TraceAirPart))
    {
      cracks += std::string(variant & TraceBubblesPart ? "#define ICE_TRACE_BUBBLES\n" : "") +
        (variant & TraceAirPart ? "#define ICE_TRACE_AIR\n" : "") +
        vtkIceInteriorTable::Declarations();
    }
    else if (variant & TraceCracksPart)
    {
      cracks += vtkIceInteriorLook::Defines() + Get(vtkIceCracksFS, "Dec");
    }
    parts.FragmentFunctions +=
      "\n#ifdef ICE_FRAME_EXIT_POINT\n" + cracks + Get(vtkIceTraceFS, "Dec") + "\n#endif\n";
    parts.Hooks.emplace_back("Refracted",
      "#ifdef ICE_FRAME_EXIT_POINT\n    if (iceTraceMaxBounces > 0)\n    {\n" +
        Get(vtkIceTraceFS, "Impl") + "    }\n#endif");
  }
  if (this->DrawingEdges(ren, act))
  {
    // VTK's edge code (before the lighting) weighs edge pixels by emix; the ice colour replaces
    // the lit colour, so the edges go over it here.
    parts.Hooks.emplace_back(
      "Edges", "gl_FragData[0].rgb = mix(gl_FragData[0].rgb, edgeColor, emix);");
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::AddFrameInputParts(vtkIceShaderParts& parts)
{
  // Each compiled where vtkIcePass's frame defines its input (vtkIceFrame::Input), after the
  // surface's own functions; the back-face target's sampler declared once, before what samples it.
  using vtkIceShaderSections::Get;
  auto guarded = [](const char* input, const std::string& code) {
    return std::string("\n#ifdef ") + input + "\n" + code + "\n#endif\n";
  };
  parts.FragmentFunctions += guarded("ICE_FRAME_BACK_NORMALS", Get(vtkIceBackNormalsFS, "Dec")) +
    guarded("ICE_FRAME_EXIT_POINT",
      Get(vtkIceExitPointFS, "Exit") + Get(vtkIceExitPointFS, "Dec")) +
    guarded("ICE_FRAME_TWO_SIDED", Get(vtkIceTwoSidedFS, "Dec")) +
    guarded("ICE_FRAME_DEPTH_DEBUG", Get(vtkIceDebugDepthFS, "Dec"));
  parts.Hooks.emplace_back(
    "RefractionNormal", guarded("ICE_FRAME_TWO_SIDED", Get(vtkIceTwoSidedFS, "Impl")));
  parts.Hooks.emplace_back(
    "RefractionDirection", guarded("ICE_FRAME_EXIT_POINT", Get(vtkIceExitPointFS, "Impl")));
  // The exit point's own path; else the eye ray's between the front and back faces.
  parts.Hooks.emplace_back("PathLength",
    guarded("ICE_FRAME_PATH_LENGTH",
      "#ifdef ICE_FRAME_EXIT_POINT\n"
      "    icePathLength = iceExitPathLength;\n"
      "#else\n"
      "    icePathLength = iceEyePathLength(e, iceViewDirectionWC, iceViewDepth(),\n"
      "      texelFetch(iceBackNormals, iceScreenTexel(), 0).a);\n"
      "#endif"));
  // The screen-space step's result.
  parts.FragmentFunctions +=
    guarded("ICE_FRAME_SCREEN_INTERIOR", Get(vtkIceScreenInteriorFS, "SurfaceDec"));
  parts.Hooks.emplace_back(
    "Interior", guarded("ICE_FRAME_SCREEN_INTERIOR", Get(vtkIceScreenInteriorFS, "SurfaceCall")));
  parts.Hooks.emplace_back(
    "Debug", guarded("ICE_FRAME_DEPTH_DEBUG", Get(vtkIceDebugDepthFS, "Impl")));
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetIceShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act)
{
  vtkIcePropertyUniforms::Set(this->IceProperty, program);
  this->SetEnvironmentUniforms(program);
  // The parameter of the depth debug views vtkIcePass adds.
  if (program->IsUniformUsed("iceDebugChannel"))
  {
    program->SetUniformi("iceDebugChannel", this->DebugView == DebugFrontDepth ? 0 : 1);
  }

  const int variant = this->ShaderVariant();
  if ((variant & TracePart) && program->IsUniformUsed("iceTraceMaxBounces"))
  {
    this->SetTraceUniforms(program, ren, act);
  }
  if (variant & (BumpPart | NormalMapPart))
  {
    program->SetUniformf("iceBumpFrequency",
      static_cast<float>(1.0 / (this->IceProperty->GetBumpScale() * this->InputExtent())));
  }
  if (variant & NormalMapPart)
  {
    program->SetUniformi("iceNormalMap", this->IceProperty->GetNormalMap()->GetTextureUnit());
  }
  if (variant & GlisteningPart)
  {
    if (!this->GlisteningNoise)
    {
      this->GlisteningNoise = vtkSmartPointer<vtkIceGlisteningTexture>::New();
    }
    vtkTextureObject* noise = this->GlisteningNoise->GetTextureObject(
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()));
    noise->Activate();
    // Deactivated after the draw.
    if (std::find(this->DrawTextures.begin(), this->DrawTextures.end(), noise) ==
      this->DrawTextures.end())
    {
      this->DrawTextures.push_back(noise);
    }
    vtkIceGlistening::SetUniforms(program, this->IceProperty, noise->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetTraceUniforms(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act)
{
  if (!this->Trace)
  {
    this->Trace.reset(new vtkIceTraceTextures);
  }
  if (!this->Trace->Update(this->PreparedInput, vtkIceWorldSpaceMapper::GetPreparedNormalsName()))
  {
    // 0 bounces: the shader keeps the exit point's estimate.
    program->SetUniformi("iceTraceMaxBounces", 0);
    if (!this->WarnedTraceUnusable)
    {
      vtkWarningMacro(<< "MaxBounces " << this->MaxBounces
                      << " cannot trace this input (no triangles, or more than "
                      << vtkIceTriangleBVH::MaximumTriangles
                      << "): the exit point is estimated in image space instead.");
      this->WarnedTraceUnusable = true;
    }
    return;
  }
  // The milky core along the reflected segments, where the screen-space interior shows it.
  double bounds[6];
  this->GetLookBounds(bounds);
  float coreCenter[3];
  float coreScale[3];
  vtkIceInteriorLook::CoreFrame(
    bounds, this->IceProperty->GetMilkyCoreRadius(), coreCenter, coreScale);
  const bool core = this->InteriorMethod == InteriorScreenSpace &&
    this->IceProperty->HasMilkyCore() && this->DebugView == DebugOff;
  const float coreColour[3] = { static_cast<float>(vtkIceInteriorLook::CoreColour[0]),
    static_cast<float>(vtkIceInteriorLook::CoreColour[1]),
    static_cast<float>(vtkIceInteriorLook::CoreColour[2]) };
  program->SetUniform3f("iceTraceCoreCenter", coreCenter);
  program->SetUniform3f("iceTraceCoreScale", coreScale);
  program->SetUniformf("iceTraceCoreDensity",
    core ? static_cast<float>(vtkIceInteriorLook::CoreDensity(this->IceProperty->GetMilkiness()))
         : 0.0f);
  program->SetUniform3f("iceTraceCoreColour", coreColour);
  this->CheckInputClosure();
  program->SetUniformf("iceTraceOrientation", static_cast<float>(this->InputOrientation));
  program->SetUniformi("iceTraceAntiAliasing", this->TraceAntiAliasing ? 1 : 0);
  if (program->IsUniformUsed("iceTraceWetBase"))
  {
    // Wet up to 6 % of the height, drying by 10 %: melt water held by capillarity in the wedge
    // between a rounded bottom edge and the ground wets that edge, not only the flat base.
    const double height = bounds[3] - bounds[2];
    const float wetBase[2] = { static_cast<float>(bounds[2] + 0.06 * height),
      static_cast<float>(bounds[2] + 0.1 * height) };
    program->SetUniform2f("iceTraceWetBase", wetBase);
    // The ice's centre in the world: the water film is thin, so the light that leaves into it
    // comes from the ground where it leaves, seen from there (the dynamic cube map's centre).
    double centre[4] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
      0.5 * (bounds[4] + bounds[5]), 1.0 };
    if (!act->GetIsIdentity())
    {
      act->GetMatrix()->MultiplyPoint(centre, centre);
    }
    const float centreWorld[3] = { static_cast<float>(centre[0] / centre[3]),
      static_cast<float>(centre[1] / centre[3]), static_cast<float>(centre[2] / centre[3]) };
    program->SetUniform3f("iceTraceWetBaseCentre", centreWorld);
  }

  vtkTextureObject* active[6] = { nullptr, nullptr, nullptr, nullptr, nullptr, nullptr };
  this->Trace->Activate(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()), program, act,
    this->MaxBounces, active);
  if (program->IsUniformUsed("iceTraceCrackShare") || program->IsUniformUsed("iceBubbleCell") ||
    program->IsUniformUsed("iceAirCount"))
  {
    this->PrepareTraceInterior(ren, program, active + 2);
  }
  for (vtkTextureObject* texture : active)
  {
    if (!texture)
    {
      continue;
    }
    if (std::find(this->DrawTextures.begin(), this->DrawTextures.end(), texture) ==
      this->DrawTextures.end())
    {
      this->DrawTextures.push_back(texture);
    }
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkIceMapper::GetCrackGeometry()
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    return nullptr;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (!this->PrepareInput(input))
  {
    return nullptr;
  }
  // Ice without volume has no inside to hold cracks.
  const int cracks = this->InputFlat ? 0 : this->IceProperty->GetNumberOfCracks();
  double bounds[6];
  this->GetLookBounds(bounds);
  return this->Interior->UpdateCracks(this->PreparedInput, bounds, cracks,
    this->IceProperty->GetCrackSeed(),
    cracks > 0 && this->UsableCrackClipping() == vtkIcePaperInterior::Geometry);
}

//------------------------------------------------------------------------------
void vtkIceMapper::InputPrepared()
{
  this->Superclass::InputPrepared();
  double thickness;
  double size;
  vtkIceSurfaceCheck::Extents(this->PreparedInput->GetPoints(), thickness, size);
  this->InputFlat = vtkIceSurfaceCheck::IsFlat(thickness, size);
  this->InputOpenEdges = -1;
  this->InputDrawnBefore = false;
  this->WarnedOpenInput = false;
  if (this->InputFlat)
  {
    vtkWarningMacro(<< "Input is flat (thickness " << thickness << " for a size of " << size
                    << "): ice without volume has no inside; it is drawn as a surface, without "
                       "cracks.");
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::CheckInputClosure()
{
  if (this->InputOpenEdges < 0)
  {
    const vtkIceSurfaceCheck::Closure closure =
      vtkIceSurfaceCheck::CheckClosure(this->PreparedInput);
    this->InputOpenEdges = closure.OpenEdges;
    this->InputClosedOutward = closure.IsClosedOutward() && !this->InputFlat;
    // Which way every triangle faces, where they agree (open edges allowed: the trace's rays
    // start inside all the same).
    const bool consistent = closure.MisorientedEdges == 0 && !this->InputFlat;
    this->InputOrientation = !consistent ? 0
      : closure.InwardComponents == 0 && closure.OutwardComponents > 0 ? 1
      : closure.OutwardComponents == 0 && closure.InwardComponents > 0 ? -1
                                                                        : 0;
  }
}

//------------------------------------------------------------------------------
int vtkIceMapper::UsableCrackClipping()
{
  const int asked = this->PaperInterior ? this->PaperInterior->GetCrackClipping()
                                        : vtkIcePaperInterior::DepthInterval;
  if (asked != vtkIcePaperInterior::Geometry)
  {
    return asked;
  }
  this->CheckInputClosure();
  if (this->InputOpenEdges == 0)
  {
    return vtkIcePaperInterior::Geometry;
  }
  if (!this->WarnedOpenInput)
  {
    vtkWarningMacro(<< "Input is not a closed surface (" << this->InputOpenEdges
                    << " open edges): Geometry crack clipping needs an inside; its cracks are "
                       "clipped to the depth interval instead.");
    this->WarnedOpenInput = true;
  }
  return vtkIcePaperInterior::DepthInterval;
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Environment->ReleaseGraphicsResources(win);
  this->Prefiltered->ReleaseGraphicsResources(win);
  this->Interior->ReleaseGraphicsResources(win);
  if (this->PaperInterior)
  {
    this->PaperInterior->ReleaseGraphicsResources(win);
  }
  this->InteriorTable->ReleaseGraphicsResources(win);
  if (this->Trace)
  {
    this->Trace->ReleaseGraphicsResources(win);
  }
  if (this->GlisteningNoise)
  {
    this->GlisteningNoise->ReleaseGraphicsResources(win);
  }
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkIceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IceProperty:\n";
  this->IceProperty->PrintSelf(os, indent.GetNextIndent());
  os << indent << "PlacementBounds: " << this->PlacementBounds[0];
  for (int i = 1; i < 6; ++i)
  {
    os << ", " << this->PlacementBounds[i];
  }
  os << "\n";
  os << indent << "TwoSidedRefraction: " << (this->TwoSidedRefraction ? "On" : "Off") << "\n";
  os << indent << "TwoSidedMethod: "
     << (this->TwoSidedMethod == TwoSidedExitPoint ? "ExitPoint" : "BlendedNormals") << "\n";
  os << indent << "MaxBounces: " << this->MaxBounces << "\n";
  os << indent << "TraceAntiAliasing: " << (this->TraceAntiAliasing ? "On" : "Off") << "\n";
  os << indent << "WetBase: " << (this->WetBase ? "On" : "Off") << "\n";
  os << indent << "MirroredEnvironment: " << (this->MirroredEnvironment ? "On" : "Off") << "\n";
  os << indent << "CullHiddenBackfaces: " << (this->CullHiddenBackfaces ? "On" : "Off") << "\n";
  os << indent << "LastDrawCulledBackfaces: " << this->LastDrawCulledBackfaces << "\n";
  static const char* const interiorMethods[] = { "PaperPasses", "ScreenSpace" };
  os << indent << "InteriorMethod: " << interiorMethods[this->InteriorMethod] << "\n";
  os << indent << "PaperInterior: " << this->PaperInterior.Get() << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
}
