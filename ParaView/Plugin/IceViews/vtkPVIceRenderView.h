// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVIceRenderView
 * @brief   ParaView's "Ice View": a render view whose geometry is rendered through vtkIcePass.
 *
 * The view installs a vtkIcePass as the render pass of its synchronized renderers (after
 * ParaView's camera pass, with ParaView's default geometry pass as its delegate), so "Ice"
 * representations get two-sided refraction, cracks and air. With DynamicEnvironment on, a
 * vtkIceCubeMapPass renders the scene around each ice object into a cube map (CubeMapFaceSize,
 * CubeMapUpdateMode); otherwise the ice refracts and reflects the view's environment: the
 * background's skybox or environment texture (equirectangular images are converted to a cube
 * map), lined up with ParaView's own skybox.
 *
 * On several ranks (pvbatch or pvserver under MPI) each rank renders the cube-map faces with its
 * own part of the scene and vtkPVIceCubeMapCompositor composites them by depth, so ice reflects
 * geometry held by any rank. The faces show the view's background also where a server draws the
 * frame on black (vtkPVIceCubeMapPass).
 */
#ifndef vtkPVIceRenderView_h
#define vtkPVIceRenderView_h

#include "IceViewsModule.h" // for export macro
#include "vtkNew.h"         // for members
#include "vtkPVRenderView.h"

class vtkIcePass;
class vtkPVIceCubeMapCompositor;
class vtkPVIceCubeMapPass;

class ICEVIEWS_EXPORT vtkPVIceRenderView : public vtkPVRenderView
{
public:
  static vtkPVIceRenderView* New();
  vtkTypeMacro(vtkPVIceRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Whether each ice object refracts a cube map of the scene rendered around it (off: the
   * view's environment). Default off.
   */
  void SetDynamicEnvironment(bool dynamic);
  bool GetDynamicEnvironment() const { return this->DynamicEnvironment; }
  ///@}

  ///@{
  /**
   * The dynamic cube map's face size in pixels and update mode
   * (vtkIceCubeMapPass::EveryFrame, OnChange, Manual).
   */
  void SetCubeMapFaceSize(int size);
  void SetCubeMapUpdateMode(int mode);
  ///@}

  vtkIcePass* GetIcePass();

  /**
   * What composites the dynamic cube maps across ranks (used with several ranks only); its
   * counters are for benchmarks.
   */
  vtkPVIceCubeMapCompositor* GetCubeMapCompositor();

protected:
  vtkPVIceRenderView();
  ~vtkPVIceRenderView() override;

  void Render(bool interactive, bool skip_rendering) override;

private:
  vtkPVIceRenderView(const vtkPVIceRenderView&) = delete;
  void operator=(const vtkPVIceRenderView&) = delete;

  vtkNew<vtkIcePass> IcePass;
  vtkNew<vtkPVIceCubeMapPass> CubeMapPass;
  vtkNew<vtkPVIceCubeMapCompositor> Compositor;
  bool DynamicEnvironment = false;
};

#endif
