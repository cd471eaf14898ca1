// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVIceCubeMapPass
 * @brief   vtkIceCubeMapPass whose faces show the view's background, not the one being drawn.
 *
 * ParaView paints the renderer's background black while a server renders: pvserver under remote
 * rendering (the client puts the server's image on its own background) and IceT on several
 * ranks. Cube-map faces rendered then would show black around the scene, and the ice a black
 * rim. vtkPVIceRenderView hands the background the user chose (SetFaceBackground, each frame
 * before ParaView's synchronizers change it); the faces are drawn on it, and the renderer's
 * background is put back for the rest of the frame.
 */
#ifndef vtkPVIceCubeMapPass_h
#define vtkPVIceCubeMapPass_h

#include "IceViewsModule.h" // for export macro
#include "vtkIceCubeMapPass.h"

class vtkRenderer;

class ICEVIEWS_EXPORT vtkPVIceCubeMapPass : public vtkIceCubeMapPass
{
public:
  static vtkPVIceCubeMapPass* New();
  vtkTypeMacro(vtkPVIceCubeMapPass, vtkIceCubeMapPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Takes `renderer`'s current background (colours, gradient, image) as the faces' background.
   */
  void SetFaceBackground(vtkRenderer* renderer);

  void Render(const vtkRenderState* s) override;

protected:
  vtkPVIceCubeMapPass();
  ~vtkPVIceCubeMapPass() override;

private:
  vtkPVIceCubeMapPass(const vtkPVIceCubeMapPass&) = delete;
  void operator=(const vtkPVIceCubeMapPass&) = delete;

  struct Background
  {
    double Color[3] = { 0.0, 0.0, 0.0 };
    double Color2[3] = { 0.0, 0.0, 0.0 };
    double Alpha = 1.0;
    bool Gradient = false;
    bool Textured = false;
    void Get(vtkRenderer* renderer);
    void Set(vtkRenderer* renderer) const;
  };
  Background FaceBackground;
  bool HasFaceBackground = false;
};

#endif
