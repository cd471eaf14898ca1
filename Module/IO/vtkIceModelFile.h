// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceModelFile
 * @brief   Checks a model file before a VTK reader reads it, as ice-render does.
 *
 * VTK's readers trust their files: a binary STL whose header promises more triangles than the
 * file holds, or a cut PLY file, makes them read past their data or allocate for a billion
 * triangles. CheckFile reads the file's structure (not its values) and says what is wrong in one
 * sentence: a missing or unreadable file, something that is not a regular file (a pipe, a device),
 * an STL or PLY file (by extension) that disagrees with its header. After the reader, check its
 * output with vtkIceMapper::CheckInput. The checks are those of ice-render's --model
 * (vtkIceModelFileChecks.h).
 */

#ifndef vtkIceModelFile_h
#define vtkIceModelFile_h

#include "IOIceModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class IOICE_EXPORT vtkIceModelFile : public vtkObject
{
public:
  static vtkIceModelFile* New();
  vtkTypeMacro(vtkIceModelFile, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * An empty string when the file at `path` can be handed to its reader, else the problem.
   */
  static std::string CheckFile(const char* path);

  /**
   * `text` safe to show (control characters and invalid UTF-8 become '?'), at most about
   * `limit` bytes.
   */
  static std::string Printable(const char* text, int limit = 240);

protected:
  vtkIceModelFile() = default;
  ~vtkIceModelFile() override = default;

private:
  vtkIceModelFile(const vtkIceModelFile&) = delete;
  void operator=(const vtkIceModelFile&) = delete;
};

#endif // vtkIceModelFile_h
