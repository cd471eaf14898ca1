// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIcePaperInterior.h"

#include "vtkObjectFactory.h"

// The override of VTKIce::RenderingIcePaper when it is loaded, else this class.
vtkObjectFactoryNewMacro(vtkIcePaperInterior);

//------------------------------------------------------------------------------
void vtkIcePaperInterior::DrawCracks(vtkRenderer*, vtkActor*, vtkPolyData*, const CrackLook&, bool)
{
  this->WarnCannotDraw();
}

//------------------------------------------------------------------------------
void vtkIcePaperInterior::DrawAir(
  vtkRenderer*, vtkActor*, vtkPolyData*, const double[6], int, int, double, bool)
{
  this->WarnCannotDraw();
}

//------------------------------------------------------------------------------
void vtkIcePaperInterior::WarnCannotDraw()
{
  if (!this->WarnedCannotDraw)
  {
    vtkErrorMacro(<< "InteriorPaperPasses draws nothing: its cracks and air are drawn by "
                     "VTKIce::RenderingIcePaper, which this program has not loaded (C++: link it "
                     "and name it in vtk_module_autoinit; Python: import vtkice).");
    this->WarnedCannotDraw = true;
  }
}

//------------------------------------------------------------------------------
void vtkIcePaperInterior::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "CrackClipping: " << (this->CrackClipping == Geometry ? "Geometry" : "DepthInterval")
     << "\n";
  os << indent << "CracksPerturbRefraction: " << (this->CracksPerturbRefraction ? "On" : "Off")
     << "\n";
}
