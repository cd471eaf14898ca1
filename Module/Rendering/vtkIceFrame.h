// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// What one frame of vtkIcePass knows about the ice it draws: the ice props and what they need,
// the textures ready so far and their texture units, the dynamic cube maps. The pass holds one and
// begins and ends it with each frame with ice; in between (from the start of the ice's sub-passes
// to the end of the scene) it is published on each ice prop (Of), where the prop's mapper finds
// it: the mapper knows the frame, not the pass. Inside the module only.
#ifndef vtkIceFrame_h
#define vtkIceFrame_h

#include "vtkIceFrameTextures.h"
#include "vtkObject.h"

#include <functional>
#include <string>

class vtkInformationObjectBaseKey;
class vtkProp;
class vtkRenderState;
class vtkShaderProgram;
class vtkTextureObject;

class vtkIceFrame : public vtkObject
{
public:
  static vtkIceFrame* New();
  vtkTypeMacro(vtkIceFrame, vtkObject);

  // What an ice prop needs the pass to render for it (vtkIceMapper's GetFrameNeeds): a texture
  // is rendered only when some ice prop of the frame needs it.
  enum Need
  {
    NeedsBackfaceNormals = 1,          // two-sided refraction (TwoSidedRefraction)
    NeedsDepthIntervalBeforeScene = 2, // depth debug views; cracks in the back-face normals
    NeedsDepthIntervalForInterior = 4, // its own interval, right before its cracks and air
    NeedsBackDepthForInterior = 8,     // the back-face target's depth (the screen-space interior)
    NeedsPathLength = 16,              // the back-face target's depth (absorption)
    NeedsScreenInterior = 32           // the screen-space interior step (InteriorScreenSpace)
  };

  // What the frame gives the surface program of an ice prop, from the textures it has ready now:
  // published to the program as #defines (Defines), which the surface's code for each tests,
  // and read by the mapper for the uniforms that go with them. The contract between the pass and
  // the surface's shaders; nothing else of the frame enters a program.
  enum Input
  {
    BackNormalsInput = 1, // ICE_FRAME_BACK_NORMALS: the back-face target (sampler iceBackNormals)
    TwoSidedInput = 2,    // ICE_FRAME_TWO_SIDED: the blended refraction normal (eq 1)
    ExitPointInput = 4,   // ICE_FRAME_EXIT_POINT: refraction again at the exit point
    PathLengthInput = 8,  // ICE_FRAME_PATH_LENGTH: the path in the ice, for absorption
    DepthDebugInput = 32, // ICE_FRAME_DEPTH_DEBUG: the depth interval shown (debug views)
    ScreenInteriorInput = 64 // ICE_FRAME_SCREEN_INTERIOR: the screen-space interior's result
  };
  // The inputs of `prop`'s surface program now, for a prop with `needs` (Need bits) whose
  // two-sided refraction goes through the exit point (`exitPoint`) and which shows a depth debug
  // view (`depthDebug`): none outside the frame or while a sub-pass of the pass draws the prop.
  int InputsOf(vtkProp* prop, int needs, bool exitPoint, bool depthDebug) const;
  // The #define lines of `inputs`.
  static std::string Defines(int inputs);

  // Publishes the frame on the props of `iceState` (their property keys) until End.
  void Begin(const vtkRenderState* iceState, int needs);
  // Releases the frame's texture units and withdraws it from the props.
  void End();
  // Between Begin and End.
  bool Active() const { return this->IceState != nullptr; }

  // The frame drawing `prop` now, or null.
  static vtkIceFrame* Of(vtkProp* prop);

  // The dynamic cube map handed to the shaders of `prop` in this frame, or null (the mapper then
  // binds the renderer's environment).
  vtkTextureObject* CubeMapOf(vtkProp* prop) const;

  // Binds `prop`'s dynamic cube map (if it has one) to `program`'s iceEnvironment: one prop's
  // cube map at a time keeps one texture unit however many ice props there are.
  void BindCubeMap(vtkShaderProgram* program, vtkProp* prop);

  // The key the frame is published under on an ice prop's property keys.
  static vtkInformationObjectBaseKey* FRAME();

  const vtkRenderState* IceState = nullptr; // the ice props, between Begin and End
  int Needs = 0;                            // of all the ice props
  // The textures handed to the shaders: set when rendered in this frame, else null.
  vtkTextureObject* BackfaceNormals = nullptr;
  vtkTextureObject* DepthInterval = nullptr;
  vtkTextureObject* ScreenInterior = nullptr;
  vtkTextureObject* BoundCubeMap = nullptr; // one prop's cube map bound at a time
  vtkIceFrameTextures Textures;             // their texture units
  // The dynamic cube maps of the pass's cube-map pass, if it has one.
  std::function<vtkTextureObject*(vtkProp*)> CubeMaps;
  // Changes whenever the cube-map pass renders a face (for copies made of the cube maps).
  vtkMTimeType CubeMapVersion = 0;

protected:
  vtkIceFrame() = default;
  ~vtkIceFrame() override = default;

private:
  vtkIceFrame(const vtkIceFrame&) = delete;
  void operator=(const vtkIceFrame&) = delete;
};

#endif
