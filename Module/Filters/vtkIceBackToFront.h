// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceBackToFront
 * @brief   Orders the polygons of its input back to front for an eye point (for the
 *          renderer; not installed).
 *
 * For alpha blending without depth writes (the ice's air planes): the polygons come out
 * farthest first, by the distance of their centroid from Eye (in the input's coordinates); ties
 * keep the input's order. The points and point data are the input's own arrays (shallow copy), so
 * a new eye changes only the order of the cells: the mapper uploads no vertex again.
 */
#ifndef vtkIceBackToFront_h
#define vtkIceBackToFront_h

#include "FiltersIceModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // for Order

class FILTERSICE_EXPORT vtkIceBackToFront : public vtkPolyDataAlgorithm
{
public:
  static vtkIceBackToFront* New();
  vtkTypeMacro(vtkIceBackToFront, vtkPolyDataAlgorithm);

  vtkSetVector3Macro(Eye, double);
  vtkGetVector3Macro(Eye, double);

  // The indices of `centers` (x, y, z each) farthest from `eye` first; ties keep their order.
  // The filter orders its polygons by their centroids so; the screen-space interior its planes.
  static std::vector<vtkIdType> Order(const std::vector<double>& centers, const double eye[3]);

protected:
  vtkIceBackToFront() = default;
  ~vtkIceBackToFront() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Eye[3] = { 0.0, 0.0, 0.0 };

private:
  vtkIceBackToFront(const vtkIceBackToFront&) = delete;
  void operator=(const vtkIceBackToFront&) = delete;
};

#endif
