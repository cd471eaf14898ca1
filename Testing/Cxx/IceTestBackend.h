// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Included in the generated test driver (IceCxxTests.cxx): before each test, the back end named
// by VTKICE_BACKEND (x, egl, osmesa or auto) is installed, so every vtkRenderWindow the tests
// create renders through it. Without VTKICE_BACKEND the tests use VTK's own (X) windows.
#ifndef IceTestBackend_h
#define IceTestBackend_h

#include "IceHeadless.h"

#include <cstdlib>
#include <iostream>
#include <string>

inline bool IceTestSelectBackend()
{
  const char* name = std::getenv("VTKICE_BACKEND");
  if (!name || !*name)
  {
    return true;
  }
  const std::string error = IceHeadless::Install(name);
  if (!error.empty())
  {
    std::cerr << "IceCxxTests: " << error << "\n";
    return false;
  }
  std::cout << "IceCxxTests: VTKICE_BACKEND=" << name << ", " << IceHeadless::InstalledDescription()
            << "\n";
  return true;
}

#endif
