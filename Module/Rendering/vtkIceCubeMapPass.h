// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCubeMapPass
 * @brief   Dynamic environment: renders the scene around each ice prop into a cube map.
 *
 * A sub-pass of vtkIcePass (vtkIcePass::SetCubeMapPass). For each ice prop it renders the scene
 * without the ice six times, with square 90° views along +X, -X, +Y, -Y, +Z, -Z from the centre of
 * the prop's bounds, into a cube-map texture the prop's vtkIceMapper samples instead of the
 * renderer's environment texture. The renderer's background and skybox appear in the cube map;
 * camera-following lights keep the direction they have for the main camera.
 *
 * When the cube maps are rendered is the UpdateMode:
 * - EveryFrame: every frame.
 * - OnChange (default): when something the cube map shows changed (props added, removed, moved,
 *   modified, lights, background, the ice prop's own position), not when only the camera moves.
 * - Manual: once, then only after Update().
 * Cost control: props are culled against each face's frustum (FrustumCulling), and
 * FacesPerFrame < 6 spreads an update over several frames (time slicing).
 *
 * Without this pass the ice reflects the renderer's environment texture (a static environment).
 */
#ifndef vtkIceCubeMapPass_h
#define vtkIceCubeMapPass_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

class vtkIceCubeMapCompositor;
class vtkInformationObjectBaseKey;
class vtkProp;
class vtkTextureObject;

class RENDERINGICE_EXPORT vtkIceCubeMapPass : public vtkOpenGLRenderPass
{
public:
  static vtkIceCubeMapPass* New();
  vtkTypeMacro(vtkIceCubeMapPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum UpdateModes
  {
    EveryFrame = 0,
    OnChange = 1,
    Manual = 2
  };

  ///@{
  /**
   * When cube maps are re-rendered. Default OnChange.
   */
  vtkSetClampMacro(UpdateMode, int, EveryFrame, Manual);
  vtkGetMacro(UpdateMode, int);
  void SetUpdateModeToEveryFrame() { this->SetUpdateMode(EveryFrame); }
  void SetUpdateModeToOnChange() { this->SetUpdateMode(OnChange); }
  void SetUpdateModeToManual() { this->SetUpdateMode(Manual); }
  ///@}

  /**
   * Re-render every cube map in the next frame (the way to refresh them in Manual mode).
   */
  void Update();

  ///@{
  /**
   * Width and height of each cube face in pixels. Default 512.
   */
  vtkSetClampMacro(FaceSize, int, 8, 4096);
  vtkGetMacro(FaceSize, int);
  ///@}

  ///@{
  /**
   * How many faces of a cube map are rendered per frame while it is being updated (1 to 6).
   * Fewer spread the cost over frames. Default 6.
   */
  vtkSetClampMacro(FacesPerFrame, int, 1, 6);
  vtkGetMacro(FacesPerFrame, int);
  ///@}

  ///@{
  /**
   * Render into each face only the props whose bounds intersect that face's frustum. Default on.
   */
  vtkSetMacro(FrustumCulling, bool);
  vtkGetMacro(FrustumCulling, bool);
  vtkBooleanMacro(FrustumCulling, bool);
  ///@}

  ///@{
  /**
   * The pass that renders the scene into each face. Default: a vtkRenderStepsPass.
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * Distributed rendering: composites each face across processes (vtkIceCubeMapCompositor), so
   * the cube maps show the parts of the scene other processes hold. Default null: this
   * process's scene only.
   */
  virtual void SetCompositor(vtkIceCubeMapCompositor* compositor);
  vtkGetObjectMacro(Compositor, vtkIceCubeMapCompositor);
  ///@}

  ///@{
  /**
   * Counters since creation: faces rendered, and props culled from faces by FrustumCulling.
   */
  vtkGetMacro(NumberOfFaceRenders, vtkIdType);
  vtkGetMacro(NumberOfCulledProps, vtkIdType);
  ///@}

  /**
   * Updates the cube maps of the props of `s` (the ice props) as UpdateMode says.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * The cube map of `iceProp`, or null if it has none yet.
   */
  vtkTextureObject* GetCubeMap(vtkProp* iceProp);

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkIceCubeMapPass();
  ~vtkIceCubeMapPass() override;

  int UpdateMode = OnChange;
  int FaceSize = 512;
  int FacesPerFrame = 6;
  bool FrustumCulling = true;
  vtkRenderPass* DelegatePass = nullptr;
  vtkIceCubeMapCompositor* Compositor = nullptr;
  vtkIdType NumberOfFaceRenders = 0;
  vtkIdType NumberOfCulledProps = 0;

  class vtkInternals;
  vtkInternals* Internals;

private:
  vtkIceCubeMapPass(const vtkIceCubeMapPass&) = delete;
  void operator=(const vtkIceCubeMapPass&) = delete;
};

#endif
