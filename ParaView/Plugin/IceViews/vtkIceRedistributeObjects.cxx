// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceRedistributeObjects.h"

#include "vtkAppendPolyData.h"
#include "vtkCleanPolyData.h"
#include "vtkCellData.h"
#include "vtkGeometryFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSmartPointer.h"
#include "vtkThreshold.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkIceRedistributeObjects);
vtkCxxSetObjectMacro(vtkIceRedistributeObjects, Controller, vtkMultiProcessController);

namespace
{
constexpr int PieceTag = 48021;
constexpr const char* RankArray = "vtkIceRank";

// The whole surface from every process's piece: coincident points merged, so that an object cut
// by the partition is one connected region again. Cells are kept as they are.
vtkSmartPointer<vtkPolyData> Join(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces)
{
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    auto* polyData = vtkPolyData::SafeDownCast(piece);
    if (polyData && polyData->GetNumberOfPoints() > 0)
    {
      append->AddInputData(polyData);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(append->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->Update();
  return clean->GetOutput();
}

// The connected surfaces of `surface` dealt out to `processes`, largest first, each to the
// process with the fewest cells so far: returns the surface with the cell array RankArray.
vtkSmartPointer<vtkPolyData> Deal(vtkPolyData* surface, int processes, vtkIdType& objects)
{
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputData(surface);
  regions->SetExtractionModeToAllRegions();
  regions->ColorRegionsOn();
  regions->Update();
  vtkIdTypeArray* sizes = regions->GetRegionSizes();
  objects = regions->GetNumberOfExtractedRegions();
  std::vector<int> order(static_cast<size_t>(objects));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [sizes](int a, int b) { return sizes->GetValue(a) > sizes->GetValue(b); });
  std::vector<int> rankOfRegion(static_cast<size_t>(objects), 0);
  std::vector<vtkIdType> load(processes, 0);
  for (int region : order)
  {
    const int target = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    rankOfRegion[region] = target;
    load[target] += sizes->GetValue(region);
  }
  auto dealt = vtkSmartPointer<vtkPolyData>::New();
  dealt->ShallowCopy(regions->GetOutput());
  // The region of a cell is its points' (ColorRegions numbers points).
  vtkDataArray* regionIds = dealt->GetPointData()->GetArray("RegionId");
  vtkNew<vtkIntArray> ranks;
  ranks->SetName(RankArray);
  ranks->SetNumberOfTuples(dealt->GetNumberOfCells());
  vtkNew<vtkIdList> points;
  for (vtkIdType c = 0; c < dealt->GetNumberOfCells(); ++c)
  {
    dealt->GetCellPoints(c, points);
    ranks->SetValue(c, rankOfRegion[static_cast<size_t>(regionIds->GetTuple1(points->GetId(0)))]);
  }
  dealt->GetCellData()->RemoveArray("RegionId");
  dealt->GetPointData()->RemoveArray("RegionId");
  dealt->GetCellData()->AddArray(ranks);
  return dealt;
}

// The cells of `dealt` for `rank`, without the rank array.
vtkSmartPointer<vtkPolyData> Extract(vtkPolyData* dealt, int rank)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  if (dealt->GetNumberOfCells() == 0)
  {
    return piece;
  }
  vtkNew<vtkThreshold> cells;
  cells->SetInputData(dealt);
  cells->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, RankArray);
  cells->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
  cells->SetLowerThreshold(rank);
  cells->SetUpperThreshold(rank);
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputConnection(cells->GetOutputPort());
  surface->Update();
  piece->ShallowCopy(surface->GetOutput());
  piece->GetCellData()->RemoveArray(RankArray);
  return piece;
}
}

//------------------------------------------------------------------------------
vtkIceRedistributeObjects::vtkIceRedistributeObjects()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkIceRedistributeObjects::~vtkIceRedistributeObjects()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
int vtkIceRedistributeObjects::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const double start = vtkTimerLog::GetUniversalTime();
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int processes = this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
  if (processes < 2)
  {
    output->ShallowCopy(input);
    input->GetBounds(this->GlobalBounds);
    this->NumberOfObjects = 0;
    this->Seconds = vtkTimerLog::GetUniversalTime() - start;
    return 1;
  }

  const int rank = this->Controller->GetLocalProcessId();
  vtkTimerLog::MarkStartEvent("Ice: redistribute objects");
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  this->Controller->Gather(input, pieces, 0);
  double header[7] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 0.0 }; // bounds, number of objects
  if (rank == 0)
  {
    vtkSmartPointer<vtkPolyData> surface = Join(pieces);
    pieces.clear();
    vtkIdType objects = 0;
    vtkSmartPointer<vtkPolyData> dealt = surface;
    if (surface->GetNumberOfCells() > 0)
    {
      surface->GetBounds(header);
      dealt = Deal(surface, processes, objects);
    }
    header[6] = static_cast<double>(objects);
    for (int r = 1; r < processes; ++r)
    {
      vtkSmartPointer<vtkPolyData> piece = Extract(dealt, r);
      this->Controller->Send(piece.Get(), r, PieceTag);
    }
    output->ShallowCopy(Extract(dealt, 0));
  }
  else
  {
    vtkNew<vtkPolyData> piece;
    this->Controller->Receive(piece, 0, PieceTag);
    output->ShallowCopy(piece);
  }
  this->Controller->Broadcast(header, 7, 0);
  std::copy(header, header + 6, this->GlobalBounds);
  this->NumberOfObjects = static_cast<vtkIdType>(header[6]);
  vtkTimerLog::MarkEndEvent("Ice: redistribute objects");
  this->Seconds = vtkTimerLog::GetUniversalTime() - start;
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceRedistributeObjects::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfObjects: " << this->NumberOfObjects << "\n";
  os << indent << "Seconds: " << this->Seconds << "\n";
}
