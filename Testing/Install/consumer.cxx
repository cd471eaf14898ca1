#include "vtkIceMapper.h"
#include "vtkIceTeapotSource.h"
#include "vtkNew.h"

#include <iostream>

int main()
{
  vtkNew<vtkIceTeapotSource> teapot;
  teapot->Update();
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(teapot->GetOutputPort());
  std::cout << mapper->GetClassName() << " eta " << mapper->GetRefractionRatio() << ", teapot "
            << teapot->GetOutput()->GetNumberOfPolys() << " triangles\n";
  return teapot->GetOutput()->GetNumberOfPolys() > 0 ? 0 : 1;
}
