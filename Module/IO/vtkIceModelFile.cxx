// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceModelFile.h"

#include "vtkIceModelFileChecks.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkIceModelFile);

//------------------------------------------------------------------------------
void vtkIceModelFile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
std::string vtkIceModelFile::CheckFile(const char* path)
{
  return path ? vtkIceModelFileChecks::CheckFile(path) : std::string("no model file named");
}

//------------------------------------------------------------------------------
std::string vtkIceModelFile::Printable(const char* text, int limit)
{
  return text
    ? vtkIceModelFileChecks::Printable(text, limit > 0 ? static_cast<std::size_t>(limit) : 0)
    : std::string();
}
