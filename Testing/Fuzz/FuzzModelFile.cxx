// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: ice-render's checks of STL and PLY files (vtkIceModelFileChecks), which run
// before VTK's readers and must answer every file with "" or one sentence. The first byte picks the
// check; the rest is the file.
#include "vtkIceModelFileChecks.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  static const std::string path = "/tmp/vtkice-fuzz-model-" + std::to_string(getpid());
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return 0;
  }
  std::fwrite(data + 1, 1, size - 1, file);
  std::fclose(file);
  const std::string problem =
    data[0] % 2 ? vtkIceModelFileChecks::CheckSTL(path) : vtkIceModelFileChecks::CheckPLY(path);
  // One sentence, printable.
  if (problem.find('\n') != std::string::npos)
  {
    __builtin_trap();
  }
  std::remove(path.c_str());
  return 0;
}
