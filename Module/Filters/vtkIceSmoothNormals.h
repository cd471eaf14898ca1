// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Smooth point normals for the module's surfaces: no splitting at sharp edges (the ice shader
// wants one normal per point), orientation made consistent, no cell normals.
#ifndef vtkIceSmoothNormals_h
#define vtkIceSmoothNormals_h

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <string>

inline vtkSmartPointer<vtkPolyData> vtkIceSmoothNormals(vtkPolyData* input)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  // One thread: VTK 9.3's threaded vtkPolyDataNormals sums a point's cell normals in whatever
  // order its threads finish, so the same surface got normals 1 ulp apart from run to run and the
  // ice changed between two renders of one scene (Debian 13; 9.1 and 9.6 measured exact).
  vtkSMPTools::LocalScope(
    vtkSMPTools::Config{ std::string("Sequential") }, [&normals]() { normals->Update(); });
  return normals->GetOutput();
}

#endif
