// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceLateDepthTest.h"

#include "vtkIceLateDepthFS.h"
#include "vtkIceShaderSections.h"

#include "vtkIceVTKCompat.h"

#include <cstdlib>
#include <cstring>

//------------------------------------------------------------------------------
bool vtkIceLateDepthTest::Wanted()
{
  // For comparisons: the early test everywhere.
  const char* setting = std::getenv("VTKICE_LATE_DEPTH_TEST");
  if (setting && std::strcmp(setting, "0") == 0)
  {
    return false;
  }
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples <= 1)
  {
    return false;
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!renderer || std::strncmp(renderer, "llvmpipe", 8) != 0)
  {
    return false;
  }
  GLint major = 0;
  GLint minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return major > 4 || (major == 4 && minor >= 3);
}

//------------------------------------------------------------------------------
std::string vtkIceLateDepthTest::Extension()
{
  return vtkIceShaderSections::Get(vtkIceLateDepthFS, "Extension");
}

//------------------------------------------------------------------------------
std::string vtkIceLateDepthTest::Declarations()
{
  return vtkIceShaderSections::Get(vtkIceLateDepthFS, "Dec");
}

//------------------------------------------------------------------------------
std::string vtkIceLateDepthTest::Code()
{
  return vtkIceShaderSections::Get(vtkIceLateDepthFS, "Impl");
}
