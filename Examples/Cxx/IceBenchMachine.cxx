// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's machine: the CPU, the GL renderer and version, the back end and VTK, as the tables,
// the CSV and the plot report them.
#include "IceBench.h"
#include "IceHeadless.h"

#include "vtkRenderWindow.h"
#include "vtkVersion.h"
#include "vtkIceVTKCompat.h"

#include <fstream>
#include <string>
#include <thread>

namespace
{
std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const std::string::size_type colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown";
}

std::string GLString(GLenum name)
{
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "unknown";
}
}

IceBench::Machine IceBench::DescribeMachine()
{
  Machine machine;
  machine.Backend = IceHeadless::InstalledDescription();
  machine.CPU = CpuModel();
  machine.Threads = std::thread::hardware_concurrency();
  machine.VTK = vtkVersion::GetVTKVersion();
  return machine;
}

void IceBench::DescribeContext(vtkRenderWindow* window, Machine& machine)
{
  window->MakeCurrent();
  machine.Renderer = GLString(GL_RENDERER);
  machine.MultiSamples = window->GetMultiSamples();
  machine.GLVersion = GLString(GL_VERSION);
}
