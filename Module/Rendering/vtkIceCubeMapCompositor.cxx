// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCubeMapCompositor.h"

//------------------------------------------------------------------------------
void vtkIceCubeMapCompositor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Background: " << this->Background[0] << ", " << this->Background[1] << ", "
     << this->Background[2] << "\n";
  os << indent << "Background2: " << this->Background2[0] << ", " << this->Background2[1] << ", "
     << this->Background2[2] << "\n";
  os << indent << "GradientBackground: " << (this->GradientBackground ? "On" : "Off") << "\n";
  os << indent << "UseBackground: " << (this->UseBackground ? "On" : "Off") << "\n";
}
