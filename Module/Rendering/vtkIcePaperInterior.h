// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIcePaperInterior
 * @brief   The paper's crack and air passes of one vtkIceMapper (InteriorPaperPasses): their
 *          settings here, their drawing in VTKIce::RenderingIcePaper.
 *
 * As vtkRenderWindow keeps its settings in RenderingCore and draws in RenderingOpenGL2, this class
 * holds what only the paper's passes use, and New() returns the OpenGL implementation
 * (vtkIceOpenGLPaperInterior) through VTK's object factory wherever VTKIce::RenderingIcePaper is
 * loaded: linked and named in vtk_module_autoinit (C++), imported (Python: `import vtkice` does),
 * or in the ParaView plugin. Without it the mapper draws no paper cracks or air and says once
 * what to link.
 *
 * An ice mapper makes its own on first use (vtkIceMapper::GetPaperInterior).
 */
#ifndef vtkIcePaperInterior_h
#define vtkIcePaperInterior_h

#include "RenderingIceModule.h" // For export macro
#include "vtkObject.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkWindow;

class RENDERINGICE_EXPORT vtkIcePaperInterior : public vtkObject
{
public:
  static vtkIcePaperInterior* New();
  vtkTypeMacro(vtkIcePaperInterior, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CrackClippingModes
  {
    DepthInterval = 0, // per fragment, against the ice's [front, back] depth (the paper)
    Geometry = 1       // once on the CPU against the ice surface: exact for concave ice
  };

  ///@{
  /**
   * How cracks are kept inside the ice. Default DepthInterval. Geometry needs a closed surface:
   * for an open one (a warning says so) the cracks are clipped to the depth interval.
   */
  vtkSetClampMacro(CrackClipping, int, DepthInterval, Geometry);
  vtkGetMacro(CrackClipping, int);
  void SetCrackClippingToDepthInterval() { this->SetCrackClipping(DepthInterval); }
  void SetCrackClippingToGeometry() { this->SetCrackClipping(Geometry); }
  ///@}

  ///@{
  /**
   * Let the cracks' normals perturb the refraction (the paper's experiment): cracks are drawn
   * into the back-face normal texture too. Default off.
   */
  vtkSetMacro(CracksPerturbRefraction, bool);
  vtkGetMacro(CracksPerturbRefraction, bool);
  vtkBooleanMacro(CracksPerturbRefraction, bool);
  ///@}

  /**
   * True for an implementation that draws (the OpenGL one); false for this class alone.
   */
  virtual bool CanDraw() { return false; }

#ifndef __VTK_WRAP__
  // How one draw of the cracks looks.
  struct CrackLook
  {
    bool ClipToInterval;
    bool Debug;     // solid red, opaque
    bool Unclipped; // over everything: no depth test
    double Intensity;
    double BumpFrequency;
  };

  // For vtkIceMapper, inside vtkIcePass's frame. Draws the crack sheets `cracks` (the ice's model
  // coordinates) with `ice`'s matrix and render passes: over the rendered scene (`overlay`), or
  // with the current state (into the back-face normals).
  virtual void DrawCracks(
    vtkRenderer* renderer, vtkActor* ice, vtkPolyData* cracks, const CrackLook& look, bool overlay);

  // Draws the air planes of `ice` (whose surface is `iceInput`), placed in `bounds`, over the
  // rendered scene, back to front for the active camera.
  virtual void DrawAir(vtkRenderer* renderer, vtkActor* ice, vtkPolyData* iceInput,
    const double bounds[6], int number, int seed, double milkiness, bool debug);

  // See vtkIceWorldSpaceMapper::ForgetRenderPasses.
  virtual void ForgetRenderPasses() {}
#endif

  virtual void ReleaseGraphicsResources(vtkWindow*) {}

protected:
  vtkIcePaperInterior() = default;
  ~vtkIcePaperInterior() override = default;

  int CrackClipping = DepthInterval;
  bool CracksPerturbRefraction = false;

private:
  void WarnCannotDraw();
  bool WarnedCannotDraw = false;

  vtkIcePaperInterior(const vtkIcePaperInterior&) = delete;
  void operator=(const vtkIcePaperInterior&) = delete;
};

#endif
