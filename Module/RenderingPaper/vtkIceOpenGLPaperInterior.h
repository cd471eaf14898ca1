// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceOpenGLPaperInterior
 * @brief   The paper's crack and air passes drawn with OpenGL: the override of
 *          vtkIcePaperInterior.
 *
 * Draws the crack sheets (vtkIceCrackMapper: bump-mapped highlights, paper section 3.3) and the
 * air planes (vtkIceAirMapper: bubble images, blended back to front, ordered by
 * vtkIceBackToFront) of one ice mapper over the rendered scene, clipped by the depth interval
 * vtkIcePass hands them; the cracks also into the back-face normals (CracksPerturbRefraction).
 */
#ifndef vtkIceOpenGLPaperInterior_h
#define vtkIceOpenGLPaperInterior_h

#include "RenderingIcePaperModule.h" // For export macro
#include "vtkIcePaperInterior.h"
#include "vtkNew.h" // for the helpers

class vtkIceAirGeometry;
class vtkIceAirMapper;
class vtkIceAirTextureSource;
class vtkIceBackToFront;
class vtkIceCrackMapper;
class vtkTexture;

class RENDERINGICEPAPER_EXPORT vtkIceOpenGLPaperInterior : public vtkIcePaperInterior
{
public:
  static vtkIceOpenGLPaperInterior* New();
  vtkTypeMacro(vtkIceOpenGLPaperInterior, vtkIcePaperInterior);

  bool CanDraw() override { return true; }

#ifndef __VTK_WRAP__
  void DrawCracks(vtkRenderer* renderer, vtkActor* ice, vtkPolyData* cracks, const CrackLook& look,
    bool overlay) override;
  void DrawAir(vtkRenderer* renderer, vtkActor* ice, vtkPolyData* iceInput, const double bounds[6],
    int number, int seed, double milkiness, bool debug) override;
  void ForgetRenderPasses() override;
#endif
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkIceOpenGLPaperInterior();
  ~vtkIceOpenGLPaperInterior() override;

private:
  vtkNew<vtkIceCrackMapper> CrackMapper;
  vtkNew<vtkActor> CrackActor;
  vtkNew<vtkIceAirGeometry> Air;
  vtkNew<vtkIceBackToFront> AirOrder;
  vtkNew<vtkIceAirTextureSource> AirImages;
  vtkNew<vtkTexture> AirTexture;
  vtkNew<vtkIceAirMapper> AirMapper;
  vtkNew<vtkActor> AirActor;

  vtkIceOpenGLPaperInterior(const vtkIceOpenGLPaperInterior&) = delete;
  void operator=(const vtkIceOpenGLPaperInterior&) = delete;
};

#endif
