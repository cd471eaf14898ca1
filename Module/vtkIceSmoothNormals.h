// Smooth point normals for the module's surfaces: no splitting at sharp edges (the ice shader
// wants one normal per point), orientation made consistent, no cell normals.
#ifndef vtkIceSmoothNormals_h
#define vtkIceSmoothNormals_h

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"

inline vtkSmartPointer<vtkPolyData> vtkIceSmoothNormals(vtkPolyData* input)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

#endif
