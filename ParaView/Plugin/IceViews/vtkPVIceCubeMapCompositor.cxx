// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVIceCubeMapCompositor.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"

#include <vector>

vtkStandardNewMacro(vtkPVIceCubeMapCompositor);
vtkCxxSetObjectMacro(vtkPVIceCubeMapCompositor, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkPVIceCubeMapCompositor::vtkPVIceCubeMapCompositor()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkPVIceCubeMapCompositor::~vtkPVIceCubeMapCompositor()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapCompositor::MaximumOverProcesses(double* values, int count)
{
  if (!this->Controller || this->Controller->GetNumberOfProcesses() < 2 || count == 0)
  {
    return;
  }
  std::vector<double> local(values, values + count);
  this->Controller->AllReduce(local.data(), values, count, vtkCommunicator::MAX_OP);
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapCompositor::CompositeFace(vtkIdType pixels, float* rgba, float* depth)
{
  const int processes = this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
  if (processes < 2)
  {
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  vtkTimerLog::MarkStartEvent("Ice: composite cube-map face");
  // Depth and colour of a pixel side by side, so one gather brings every process's face.
  std::vector<float>& local = this->Local;
  local.resize(5 * pixels);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    local[5 * p] = depth[p];
    std::copy(rgba + 4 * p, rgba + 4 * p + 4, &local[5 * p + 1]);
  }
  std::vector<float>& all = this->All;
  all.resize(local.size() * processes);
  this->Controller->AllGather(local.data(), all.data(), static_cast<vtkIdType>(local.size()));
  // The nearest fragment; on equal depth (the background everywhere) the lowest rank's, so
  // every process keeps the same.
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const float* nearest = &all[5 * p];
    for (int r = 1; r < processes; ++r)
    {
      const float* other = &all[(r * pixels + p) * 5];
      if (other[0] < nearest[0])
      {
        nearest = other;
      }
    }
    depth[p] = nearest[0];
    std::copy(nearest + 1, nearest + 5, rgba + 4 * p);
  }
  vtkTimerLog::MarkEndEvent("Ice: composite cube-map face");
  ++this->NumberOfFaces;
  this->CompositeSeconds += vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkPVIceCubeMapCompositor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfFaces: " << this->NumberOfFaces << "\n";
  os << indent << "CompositeSeconds: " << this->CompositeSeconds << "\n";
}
