// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceEnvironmentReader.h"
#include "vtkIceLookTable.h"
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
  // The reader's header needs no OpenImageIO headers (the library links OpenImageIO privately).
  vtkNew<vtkIceEnvironmentReader> reader;
  std::cout << mapper->GetClassName() << " eta " << mapper->GetIceProperty()->GetRefractionRatio()
            << ", teapot " << teapot->GetOutput()->GetNumberOfPolys() << " triangles, "
            << reader->GetClassName() << " layout " << reader->GetLayoutAsString()
            << ", the look's setting eta " << (vtkIceLookTable::Find("eta") ? "found" : "missing")
            << ", paper passes " << mapper->GetPaperInterior()->GetClassName() << "\n";
  return teapot->GetOutput()->GetNumberOfPolys() > 0 && vtkIceLookTable::Find("eta") &&
      mapper->GetPaperInterior()->CanDraw()
    ? 0
    : 1;
}
