// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: vtkIceEnvironmentReader's checks of an environment image's header (size,
// layout, limits) before any pixel is read. The first byte picks the file type (PNG, JPEG,
// Radiance HDR, OpenEXR), the rest is the file; the reader must answer with its information or
// one error, never a fault. Pixels are not read: that is OpenImageIO's part, bounded by the
// header checks.
#include "vtkIceEnvironmentReader.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace
{
// Keeps the reader's errors off the console (a fuzzer runs it a million times).
class Quiet : public vtkCommand
{
public:
  static Quiet* New() { return new Quiet; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  static const char* const extensions[] = { ".png", ".jpg", ".hdr", ".exr" };
  const std::string path =
    "/tmp/vtkice-fuzz-env-" + std::to_string(getpid()) + extensions[data[0] % 4];
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return 0;
  }
  std::fwrite(data + 1, 1, size - 1, file);
  std::fclose(file);
  vtkObject::GlobalWarningDisplayOff();
  vtkNew<vtkIceEnvironmentReader> reader;
  vtkNew<Quiet> quiet;
  reader->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->AddObserver(vtkCommand::WarningEvent, quiet);
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  std::remove(path.c_str());
  return 0;
}
