// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVIceBackgroundEnvironment
 * @brief   A cube map of a view's background as the camera shows it, for ice to refract.
 *
 * ParaView's views have an environment texture only with a skybox background; ice elsewhere
 * would refract vtkIceMapper's built-in sky, a landscape that is not in the view. This cube map
 * holds what the view's background shows in each direction instead: its single colour, or its
 * gradient (Background at the bottom of the viewport, Background2 at the top) where the camera
 * sees it, so ice with IndexOfRefraction 1 is invisible against the background (perspective
 * camera). Directions outside the view continue the gradient's end colours.
 *
 * Update() reads the renderer's background and camera (call it while the renderer holds the
 * view's background: ParaView's servers paint it black while they draw) and rebuilds the faces
 * when they change: a gradient's faces depend on the camera's orientation and view angle.
 */
#ifndef vtkPVIceBackgroundEnvironment_h
#define vtkPVIceBackgroundEnvironment_h

#include "IceViewsModule.h" // for export macro
#include "vtkNew.h"         // for members
#include "vtkObject.h"

#include <array> // for members

class vtkImageData;
class vtkRenderer;
class vtkTexture;

class ICEVIEWS_EXPORT vtkPVIceBackgroundEnvironment : public vtkObject
{
public:
  static vtkPVIceBackgroundEnvironment* New();
  vtkTypeMacro(vtkPVIceBackgroundEnvironment, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Follows `renderer`'s background and active camera. Returns whether the texture shows the
   * background: false for a background this class does not draw (an image or a skybox).
   */
  bool Update(vtkRenderer* renderer);

  /**
   * The cube map (six RGB float faces, linearly interpolated).
   */
  vtkTexture* GetTexture();

  /**
   * Width and height in texels of a gradient's faces (a single colour needs one). Default 256.
   */
  vtkSetClampMacro(GradientFaceSize, int, 2, 2048);
  vtkGetMacro(GradientFaceSize, int);

protected:
  vtkPVIceBackgroundEnvironment();
  ~vtkPVIceBackgroundEnvironment() override;

private:
  vtkPVIceBackgroundEnvironment(const vtkPVIceBackgroundEnvironment&) = delete;
  void operator=(const vtkPVIceBackgroundEnvironment&) = delete;

  void Build(int size);

  vtkNew<vtkTexture> Texture;
  vtkNew<vtkImageData> Faces[6];
  int GradientFaceSize = 256;
  // What the faces were built from: colours, gradient, camera up, direction and view angle.
  std::array<double, 14> Built;
  bool HasBuilt = false;
};

#endif
