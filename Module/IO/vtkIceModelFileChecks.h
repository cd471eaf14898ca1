// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Checks of model files that VTK 9.1's readers take on trust: a truncated binary PLY makes
// vtkPLYReader read past its points (a crash) and a truncated ASCII one floods stderr; a binary
// STL whose header promises more (or fewer) triangles than the file holds is read in part, or
// allocated for a billion triangles. These checks read the file's structure, not its values, and
// run before the reader does. Used by ice-render, ice-bench and (through vtkIceModelFile) Python.
#ifndef vtkIceModelFileChecks_h
#define vtkIceModelFileChecks_h

#include "IOIceModule.h" // For export macro

#include <cstddef>
#include <string>

namespace vtkIceModelFileChecks
{
// Whether `path` is a binary or ASCII STL file whose size and end agree with its header.
// Returns "" or the problem in one sentence.
IOICE_EXPORT std::string CheckSTL(const std::string& path);

// Whether `path` is a PLY file (ASCII or binary, either byte order) whose header parses and whose
// body holds every element the header declares, with face indices naming existing vertices.
// Returns "" or the problem in one sentence.
IOICE_EXPORT std::string CheckPLY(const std::string& path);

// Why the model file at `path` cannot be handed to a reader, or "": it must be a regular file (a
// device such as /dev/zero or a pipe would never end), readable, and for the formats whose VTK
// readers trust their headers (STL, PLY: by its extension), consistent with them.
IOICE_EXPORT std::string CheckFile(const std::string& path);

// `text` safe for a terminal: control characters and bytes that are not valid UTF-8 become '?';
// at most about `limit` bytes (then "...").
IOICE_EXPORT std::string Printable(const std::string& text, std::size_t limit = 240);
}

#endif // vtkIceModelFileChecks_h
