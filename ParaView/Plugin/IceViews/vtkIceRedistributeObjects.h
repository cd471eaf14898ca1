// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceRedistributeObjects
 * @brief   Moves each ice object (connected surface) whole onto one process.
 *
 * Two-sided refraction needs an object's front and back surfaces on the process that renders
 * it, and a dataset split across ranks cuts objects wherever the partition runs. This filter
 * takes each process's piece of a surface (collective: every process of the controller runs
 * it), gathers the pieces on process 0, merges coincident points so that pieces of one object
 * join again, splits the surface into connected regions and deals the regions out to the
 * processes, largest first to the least loaded. Many objects stay parallel; a single object ends
 * up whole on one process (gathered, by design).
 *
 * It also reduces what every process needs to place the look as one process would: the bounds
 * of the whole surface (GlobalBounds) and the number of objects.
 *
 * With one process the output is the input (shallow copy).
 */
#ifndef vtkIceRedistributeObjects_h
#define vtkIceRedistributeObjects_h

#include "IceViewsModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkMultiProcessController;

class ICEVIEWS_EXPORT vtkIceRedistributeObjects : public vtkPolyDataAlgorithm
{
public:
  static vtkIceRedistributeObjects* New();
  vtkTypeMacro(vtkIceRedistributeObjects, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the surface. Default: the global controller.
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * After an update: the bounds of the surface on all processes (uninitialized when it is empty
   * everywhere), its number of objects (0 with one process: not counted), and the seconds the
   * last update took (communication included).
   */
  vtkGetVector6Macro(GlobalBounds, double);
  vtkGetMacro(NumberOfObjects, vtkIdType);
  vtkGetMacro(Seconds, double);
  ///@}

protected:
  vtkIceRedistributeObjects();
  ~vtkIceRedistributeObjects() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkMultiProcessController* Controller = nullptr;
  double GlobalBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  vtkIdType NumberOfObjects = 0;
  double Seconds = 0.0;

private:
  vtkIceRedistributeObjects(const vtkIceRedistributeObjects&) = delete;
  void operator=(const vtkIceRedistributeObjects&) = delete;
};

#endif
