// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: ice-render's preset files (vtkIceLookTable::ReadPreset: "NAME = VALUE" lines,
// checked against the library's ranges before anything is applied). Every file gives either a
// list of assignments that apply cleanly or one problem, never a fault.
#include "vtkIceLookTable.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const std::string path = "/tmp/vtkice-fuzz-preset-" + std::to_string(getpid());
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return 0;
  }
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  vtkIceLookTable::Assignments assignments;
  if (vtkIceLookTable::ReadPreset(path, assignments).empty() &&
    !vtkIceLookTable::Check(assignments).empty())
  {
    __builtin_trap(); // accepted, then refused
  }
  std::remove(path.c_str());
  return 0;
}
