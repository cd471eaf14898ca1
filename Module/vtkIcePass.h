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
 * Sub-passes, in the order they run before the delegate:
 * 1. environment: with a vtkIceCubeMapPass set (SetCubeMapPass), each ice prop gets a cube map of
 *    the scene around it (dynamic environment); without one, the renderer's environment texture
 *    is used (static environment),
 * 2. depth interval of all the ice (vtkIceDepthIntervalPass: front and back depth), only when an
 *    ice mapper shows it in a depth debug view or draws cracks into the back-face normals
 *    (CracksPerturbRefraction),
 * 3. back-face normals (vtkIceBackfaceNormalPass, for paper eq 1).
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
#include "vtkRenderPass.h"

class vtkIceBackfaceNormalPass;
class vtkIceCubeMapPass;
class vtkIceDepthIntervalPass;
class vtkIceOpaqueStep;
class vtkIceOverlayStep;
class vtkIceTranslucentStep;
class vtkIceVolumeStep;

class RENDERINGICE_EXPORT vtkIcePass : public vtkRenderPass
{
public:
  static vtkIcePass* New();
  vtkTypeMacro(vtkIcePass, vtkRenderPass);
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

  /**
   * Draws the ice props of `iceState` over what `s` rendered so far, one by one: the prop's own
   * depth interval (so that the interior of one ice is never clipped by another's), its air, then
   * its cracks. Called by the pass itself after the opaque geometry.
   */
  void RenderOverlays(const vtkRenderState* s, const vtkRenderState* iceState);

protected:
  vtkIcePass();
  ~vtkIcePass() override;


  // Renders the depth interval of the props of `s` and hands it to their mappers.
  void RenderDepthInterval(const vtkRenderState* s);

  vtkIceOverlayStep* OverlayStep = nullptr;

  vtkRenderPass* DelegatePass = nullptr;
  vtkRenderPass* DefaultDelegate = nullptr;
  vtkIceOpaqueStep* OpaqueStep = nullptr;
  vtkIceTranslucentStep* TranslucentStep = nullptr;
  vtkIceVolumeStep* VolumeStep = nullptr;
  vtkIceBackfaceNormalPass* BackfaceNormalPass = nullptr;
  vtkIceCubeMapPass* CubeMapPass = nullptr;
  vtkIceDepthIntervalPass* DepthIntervalPass = nullptr;
  int NumberOfIceProps = 0;

private:
  vtkIcePass(const vtkIcePass&) = delete;
  void operator=(const vtkIcePass&) = delete;
};

#endif
