// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Running VTK readers on files the user hands to ice-render: one clean line for any failure, and
// a reader's crash on a broken file contained in a child process.
#ifndef IceReading_h
#define IceReading_h

#include "vtkSmartPointer.h"

#include <string>

class vtkAlgorithm;
class vtkPolyData;

namespace IceReading
{
// Updates `algorithm` with VTK's messages captured and whatever libraries print on stderr held
// back (libpng, vtkPLY print there directly). On failure returns false with the first VTK
// message, made printable, in `error`, and drops the held-back text; on success passes it on.
bool UpdateQuietly(vtkAlgorithm* algorithm, std::string& error);

// Runs `reader` (whose output 0 is polydata) in a child process and returns a copy of its
// output, which passed vtkIceMapper::CheckInput. Call it before the program starts threads.
// VTK 9.1's readers trust their files: a cut legacy .vtk file crashes vtkPolyDataReader, a cut PLY
// vtkPLYReader. A crash, an abort or running out of memory in the child becomes nullptr and a
// one-line `error`, as does a message of the reader's. Point arrays with fewer values than points
// (an OBJ file with fewer texture coordinates than vertices), which the ice does not use and VTK
// would read past, are dropped; `warning` (when given) then says which.
vtkSmartPointer<vtkPolyData> ReadPolyDataIsolated(
  vtkAlgorithm* reader, std::string& error, std::string* warning = nullptr);
}

#endif
