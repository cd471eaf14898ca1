// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Linked into the programs of a VTKICE_SANITIZE build that LeakSanitizer checks (the C++ test
// driver and ice-render). Mesa unloads its driver (swrast_dri.so, llvmpipe) when the last X or
// EGL display closes, before LeakSanitizer reports at exit: what the driver allocated and never
// freed is then reported from "<unknown module>", and no suppression can name the library.
// Loading the drivers once more with RTLD_NODELETE keeps them mapped until the process ends, so
// that every leak report names its library.
#include <dlfcn.h>

#include <initializer_list>

namespace
{
struct KeepDriversLoaded
{
  KeepDriversLoaded()
  {
    for (const char* path : { VTKICE_KEEP_LOADED })
    {
      // A driver that is not installed is simply not kept.
      dlopen(path, RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
    }
  }
};
const KeepDriversLoaded keepDriversLoaded;
}
