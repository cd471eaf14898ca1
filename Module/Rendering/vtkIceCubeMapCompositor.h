// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCubeMapCompositor
 * @brief   Joins the cube-map faces that several processes render of their parts of a scene.
 *
 * In distributed rendering (ParaView's pvbatch or pvserver under MPI) each process holds a part
 * of the scene, so a dynamic cube map rendered on one process shows only that part. Given to
 * vtkIceCubeMapPass (SetCompositor), a compositor makes the processes agree on what to render
 * (which cube maps update in a frame, the faces' depth range) and composites every rendered face
 * by depth, so the ice on each process reflects and refracts the whole scene.
 *
 * Every process must call the pass together with the same ice props (ParaView's representations
 * exist on every rank; vtkIceMapper::SetPlacementBounds gives their pieces common bounds).
 * Subclasses do the communication: VTK Ice's ParaView plugin has one on
 * vtkMultiProcessController, so this module needs no parallel library.
 */
#ifndef vtkIceCubeMapCompositor_h
#define vtkIceCubeMapCompositor_h

#include "RenderingIceModule.h" // for export macro
#include "vtkObject.h"

class RENDERINGICE_EXPORT vtkIceCubeMapCompositor : public vtkObject
{
public:
  vtkTypeMacro(vtkIceCubeMapCompositor, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Replaces each of the `count` values by its largest over all processes.
   */
  virtual void MaximumOverProcesses(double* values, int count) = 0;

  /**
   * A face of `pixels` pixels rendered on this process: `depth` (window depth, 0 near to 1 far)
   * and `rgba` (4 floats a pixel). On return both hold, at each pixel, the nearest of all
   * processes' (the same on every process).
   */
  virtual void CompositeFace(vtkIdType pixels, float* rgba, float* depth) = 0;

  ///@{
  /**
   * The background the faces are rendered on (colour, top colour and whether it is a gradient,
   * as vtkViewport has them), when UseBackground is on. A compositing pass such as IceT's paints
   * the renderer's background black while the scene is drawn, so the view passes what the user
   * chose. Default off: the renderer's background.
   */
  vtkSetVector3Macro(Background, double);
  vtkGetVector3Macro(Background, double);
  vtkSetVector3Macro(Background2, double);
  vtkGetVector3Macro(Background2, double);
  vtkSetMacro(GradientBackground, bool);
  vtkGetMacro(GradientBackground, bool);
  vtkSetMacro(UseBackground, bool);
  vtkGetMacro(UseBackground, bool);
  vtkBooleanMacro(UseBackground, bool);
  ///@}

protected:
  vtkIceCubeMapCompositor() = default;
  ~vtkIceCubeMapCompositor() override = default;

  double Background[3] = { 0.0, 0.0, 0.0 };
  double Background2[3] = { 0.0, 0.0, 0.0 };
  bool GradientBackground = false;
  bool UseBackground = false;

private:
  vtkIceCubeMapCompositor(const vtkIceCubeMapCompositor&) = delete;
  void operator=(const vtkIceCubeMapCompositor&) = delete;
};

#endif
