// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVIceCubeMapCompositor
 * @brief   vtkIceCubeMapCompositor over ParaView's processes (vtkMultiProcessController).
 *
 * Used by vtkPVIceRenderView when it runs on several processes (pvbatch or pvserver under
 * MPI): every rank renders each cube-map face with its own part of the scene, the faces are
 * gathered on every rank and the nearest fragment of each pixel kept. The ranks of one
 * compositing are those of the global controller.
 */
#ifndef vtkPVIceCubeMapCompositor_h
#define vtkPVIceCubeMapCompositor_h

#include "IceViewsModule.h" // for export macro
#include "vtkIceCubeMapCompositor.h"

#include <vector> // for members

class vtkMultiProcessController;

class ICEVIEWS_EXPORT vtkPVIceCubeMapCompositor : public vtkIceCubeMapCompositor
{
public:
  static vtkPVIceCubeMapCompositor* New();
  vtkTypeMacro(vtkPVIceCubeMapCompositor, vtkIceCubeMapCompositor);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that composite. Default: the global controller.
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  void MaximumOverProcesses(double* values, int count) override;
  void CompositeFace(vtkIdType pixels, float* rgba, float* depth) override;

  ///@{
  /**
   * Faces composited and the seconds spent on it (communication included) since creation.
   */
  vtkGetMacro(NumberOfFaces, vtkIdType);
  vtkGetMacro(CompositeSeconds, double);
  ///@}

protected:
  vtkPVIceCubeMapCompositor();
  ~vtkPVIceCubeMapCompositor() override;

  vtkMultiProcessController* Controller = nullptr;
  vtkIdType NumberOfFaces = 0;
  double CompositeSeconds = 0.0;
  // This process's face and every process's, kept between faces.
  std::vector<float> Local;
  std::vector<float> All;

private:
  vtkPVIceCubeMapCompositor(const vtkPVIceCubeMapCompositor&) = delete;
  void operator=(const vtkPVIceCubeMapCompositor&) = delete;
};

#endif
