// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIcePass
 * @brief   The render pass that gives a renderer's ice its two-sided refraction.
 *
 * Set it on a renderer (`renderer->SetPass(icePass)`). Each frame it finds the visible props whose
 * mapper is a vtkIceMapper, runs the ice sub-passes for them, hands their textures to the ice
 * mappers, and then renders the whole scene with its delegate pass (by default a
 * vtkRenderStepsPass whose steps follow the renderer's own settings every frame: hidden line
 * removal, SSAO, order-independent translucency or dual depth peeling with the renderer's number
 * of peels, occlusion ratio and volumes, FXAA). A frame without ice is exactly the delegate's
 * frame, and with the default delegate pixel for pixel the frame the renderer draws without any
 * pass. Hardware selection is rendered through the renderer's vtkHardwareSelector, as without a
 * pass, and the camera's stereo projection follows the window.
 *
 * Sub-passes, in the order they run before the delegate, each only when an ice mapper needs what
 * it renders (what each ice mapper needs in a frame):
 * 1. environment: with a vtkIceCubeMapPass set (SetCubeMapPass), each ice prop gets a cube map of
 *    the scene around it (dynamic environment); without one, the renderer's environment texture
 *    is used (static environment),
 * 2. depth interval of all the ice (vtkIceDepthIntervalPass: front and back depth), for the depth
 *    debug views and cracks drawn into the back-face normals (CracksPerturbRefraction),
 * 3. back-face normals (vtkIceBackfaceNormalPass, for paper eq 1),
 * 4. the screen-space interior of the ice with InteriorScreenSpace: prop by prop, its own depth
 *    interval, then its cracks, air and milky core once per pixel into a texture its surface
 *    applies.
 * The pass owns the frame's textures. For the frame it is one of the render passes of each ice
 * prop (vtkOpenGLRenderPass): when an ice shader is built it adds the code that samples the
 * textures it has ready (PostReplaceShaderValues), and when one is bound it hands them over
 * (SetShaderParameters); the mappers keep no per-frame state and never call the pass.
 * Right after the opaque geometry (before translucent geometry, when the delegate is the default
 * one; after the delegate otherwise) it draws, ice prop by ice prop, the prop's own depth interval
 * and its air planes (blended back to front) and cracks (highlights added), clipped to that
 * interval: one draw each per ice prop however many planes and cracks it has, and no ice's
 * interior shows on another ice.
 *
 * @sa vtkIceMapper vtkIceBackfaceNormalPass
 */
#ifndef vtkIcePass_h
#define vtkIcePass_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

class vtkIceBackfaceNormalPass;
class vtkIceCubeMapPass;
class vtkIceDepthIntervalPass;
class vtkIceFrame;
class vtkIceScreenInterior;
class vtkIceOpaqueStep;
class vtkIceOverlayStep;
class vtkIceTranslucentStep;
class vtkIceStepTimers;
class vtkIceVolumeStep;

class RENDERINGICE_EXPORT vtkIcePass : public vtkOpenGLRenderPass
{
public:
  static vtkIcePass* New();
  vtkTypeMacro(vtkIcePass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The pass that renders the scene itself. Default: a vtkRenderStepsPass.
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * The optional dynamic-environment sub-pass. Default null: ice reflects the renderer's
   * environment texture.
   */
  virtual void SetCubeMapPass(vtkIceCubeMapPass* pass);
  vtkGetObjectMacro(CubeMapPass, vtkIceCubeMapPass);
  ///@}

  /**
   * The back-face normal and depth-interval sub-passes (always present).
   */
  vtkGetObjectMacro(BackfaceNormalPass, vtkIceBackfaceNormalPass);
  vtkGetObjectMacro(DepthIntervalPass, vtkIceDepthIntervalPass);

  /**
   * Number of ice props found in the last Render.
   */
  vtkGetMacro(NumberOfIceProps, int);

  ///@{
  /**
   * Measures the GPU time of each step of the frame (OpenGL timestamp queries). Off by default.
   * The times are read without waiting for the GPU: a frame's times are collected at the start
   * of a later frame, once the GPU has finished them (after a glFinish, at the next frame).
   */
  vtkSetMacro(MeasureStepTimes, bool);
  vtkGetMacro(MeasureStepTimes, bool);
  vtkBooleanMacro(MeasureStepTimes, bool);
  ///@}

  /**
   * The steps GetStepTime reports: the cube maps of the dynamic environment (all their faces),
   * the depth interval of all the ice before the scene, the back faces' normals and depth, the
   * scene (the delegate: every prop, the ice surfaces, and the screen-space interior's step when
   * the default delegate draws it), and the interior of the paper's passes
   * (each ice's own depth interval, air and cracks).
   */
  enum Steps
  {
    CubeMapStep = 0,
    DepthIntervalStep,
    BackfaceNormalStep,
    SceneStep,
    InteriorStep,
    NumberOfSteps
  };

  /**
   * The latest measured GPU time of `step` (Steps) in milliseconds, or -1 when the step did not
   * run in the frame measured last, or MeasureStepTimes is off.
   */
  double GetStepTime(int step);

  ///@{
  /**
   * vtkOpenGLRenderPass: the code sampling the frame's textures goes into the ice shaders, and
   * the textures to the programs sampling them.
   */
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  ///@}

protected:
  vtkIcePass();
  ~vtkIcePass() override;

  // Renders the ice of `iceState`'s frame before the delegate's scene.
  void RenderIce(const vtkRenderState* iceState, int needs);

  // Renders the depth interval of the props of `s`; the shaders get it from then on.
  void RenderDepthInterval(const vtkRenderState* s);

  // Draws the ice props of `iceState` over what `s` rendered so far, one by one: the prop's own
  // depth interval (so that the interior of one ice is never clipped by another's), its air,
  // then its cracks. After the opaque geometry (a step of the default delegate).
  void RenderOverlays(const vtkRenderState* s, const vtkRenderState* iceState);

  // The screen-space interior of the props of `iceState` that use it (InteriorScreenSpace), prop
  // by prop after the back faces: its own depth interval, then its interior once per pixel.
  void RenderScreenInterior(const vtkRenderState* iceState);
  // Ends the frame: its textures are no longer handed over.
  void EndFrame();

  // Bracket a step's GPU time when MeasureStepTimes is on.
  void StartStep(int step);
  void StopStep(int step);

  // What the frame being rendered knows (vtkIceFrame.h), begun and ended with each frame of ice.
  vtkIceFrame* Frame = nullptr;

  vtkIceOverlayStep* OverlayStep = nullptr;

  vtkRenderPass* DelegatePass = nullptr;
  vtkRenderPass* DefaultDelegate = nullptr;
  vtkIceOpaqueStep* OpaqueStep = nullptr;
  vtkIceTranslucentStep* TranslucentStep = nullptr;
  vtkIceVolumeStep* VolumeStep = nullptr;
  vtkIceBackfaceNormalPass* BackfaceNormalPass = nullptr;
  vtkIceCubeMapPass* CubeMapPass = nullptr;
  vtkIceDepthIntervalPass* DepthIntervalPass = nullptr;
  vtkIceDepthIntervalPass* PropFrontPass = nullptr; // one prop's front faces (screen interior)
  int NumberOfIceProps = 0;
  bool MeasureStepTimes = false;
  vtkIceStepTimers* StepTimers = nullptr; // while MeasureStepTimes is on
  vtkIceScreenInterior* ScreenInterior = nullptr;

private:
  vtkIcePass(const vtkIcePass&) = delete;
  void operator=(const vtkIcePass&) = delete;
};

#endif
