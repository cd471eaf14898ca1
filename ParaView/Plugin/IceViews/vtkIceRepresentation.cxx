// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceRepresentation.h"

#include "vtkCompositeDataGeometryFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkIceMapper.h"
#include "vtkIceProperty.h"
#include "vtkIceRedistributeObjects.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPVIceBackgroundEnvironment.h"
#include "vtkPVIceMapper.h"
#include "vtkPVLODActor.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"

#include <limits>

vtkStandardNewMacro(vtkIceRepresentation);

//------------------------------------------------------------------------------
vtkIceRepresentation::vtkIceRepresentation()
{
  // Replace the superclass's composite mappers; SetupDefaults wires the new ones to the actor.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkPVIceMapper::New();
  this->LODMapper = vtkPVIceMapper::New();
  // Without a skybox ParaView's views have no environment: the ice shows the view's background
  // (the built-in sky where even that is missing, an image background), without a warning.
  this->ForEachIceMapper([](vtkIceMapper* m) { m->WarnWithoutEnvironmentOff(); });
  // One look for both: the LOD mapper draws the same ice while interacting.
  static_cast<vtkIceMapper*>(this->LODMapper)->SetIceProperty(this->GetIceProperty());
  this->SetupDefaults();
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  this->Distributed = controller && controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
vtkIceRedistributeObjects* vtkIceRepresentation::GetRedistribution()
{
  return this->Distributed ? this->Redistribute.Get() : nullptr;
}

//------------------------------------------------------------------------------
int vtkIceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  // A multiblock from ParaView 5.11, a partitioned dataset collection from 5.13 and 6.1 (for
  // polydata input too).
  auto* pieces = vtkCompositeDataSet::SafeDownCast(this->MultiBlockMaker->GetOutputDataObject(0));
  if (this->Distributed && pieces)
  {
    // Every rank runs this together (ParaView updates representations on all ranks), as the
    // redistribution needs. Its result replaces the surface ParaView hands to the view (as the
    // only block or partition; a second vtkPVView::SetPiece would be ignored).
    vtkSmartPointer<vtkCompositeDataSet> local = vtk::TakeSmartPointer(pieces->NewInstance());
    local->ShallowCopy(pieces);
    this->MergePiece->SetInputDataObject(local);
    this->Redistribute->SetInputConnection(this->MergePiece->GetOutputPort());
    this->Redistribute->Modified();
    this->Redistribute->Update();
    if (vtkPartitionedDataSetCollection::SafeDownCast(pieces))
    {
      vtkNew<vtkPartitionedDataSetCollection> objects;
      objects->SetPartition(0, 0, this->Redistribute->GetOutput());
      pieces->ShallowCopy(objects);
    }
    else
    {
      vtkNew<vtkMultiBlockDataSet> objects;
      objects->SetBlock(0, this->Redistribute->GetOutput());
      pieces->ShallowCopy(objects);
    }
    double bounds[6];
    this->Redistribute->GetGlobalBounds(bounds);
    // On the mappers directly: modifying the representation here would update it again.
    static_cast<vtkIceMapper*>(this->Mapper)->SetPlacementBounds(bounds);
    static_cast<vtkIceMapper*>(this->LODMapper)->SetPlacementBounds(bounds);
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkIceRepresentation::~vtkIceRepresentation() = default;

//------------------------------------------------------------------------------
vtkIceMapper* vtkIceRepresentation::GetIceMapper()
{
  return static_cast<vtkIceMapper*>(this->Mapper);
}

//------------------------------------------------------------------------------
template <typename Setter>
void vtkIceRepresentation::ForEachIceMapper(Setter setter)
{
  setter(static_cast<vtkIceMapper*>(this->Mapper));
  setter(static_cast<vtkIceMapper*>(this->LODMapper));
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkIceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    // The superclass has just handed the delivered (composite) pieces to the mappers: merge each
    // into the one polydata an ice mapper draws. The filters run only when their input changed.
    const auto merge = [](vtkMapper* mapper, vtkCompositeDataGeometryFilter* filter) {
      auto* composite = vtkCompositeDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0));
      if (composite)
      {
        filter->SetInputDataObject(composite);
        filter->Update();
        mapper->SetInputDataObject(filter->GetOutput());
      }
    };
    merge(this->Mapper, this->Merge);
    merge(this->LODMapper, this->MergeLOD);
    // The renderer holds the view's background now: a server paints it black later, while it
    // draws.
    auto* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
    vtkTexture* background = view && this->BackgroundEnvironment->Update(view->GetRenderer())
      ? this->BackgroundEnvironment->GetTexture()
      : nullptr;
    static_cast<vtkPVIceMapper*>(this->Mapper)->SetBackgroundEnvironment(background);
    static_cast<vtkPVIceMapper*>(this->LODMapper)->SetBackgroundEnvironment(background);
    // Empty data is common in ParaView (an iso-value out of range, an empty block or piece); the
    // ice mapper reports it as an error, ParaView's surface draws nothing: so does this.
    // A rank without ice of a distributed surface still takes part in the frame (the dynamic
    // cube map is composited by all ranks): its mapper draws nothing (PlacementBounds).
    auto* surface = vtkDataSet::SafeDownCast(this->Mapper->GetInputDataObject(0, 0));
    const bool empty = this->Distributed
      ? !vtkMath::AreBoundsInitialized(this->Redistribute->GetGlobalBounds())
      : !surface || surface->GetNumberOfPoints() == 0;
    this->Actor->SetVisibility(this->GetVisibility() && !empty);
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkIceProperty* vtkIceRepresentation::GetIceProperty()
{
  return this->GetIceMapper()->GetIceProperty();
}

//------------------------------------------------------------------------------
// A look parameter goes to the mappers' shared ice property, a drawing setting to both mappers;
// `value` converted as the setter takes it.
#define vtkIceLookMacro(name, type, value)                                                         \
  void vtkIceRepresentation::Set##name(type v)                                                     \
  {                                                                                                \
    this->GetIceProperty()->Set##name(value);                                                      \
  }
#define vtkIceDrawingMacro(name, type, value)                                                      \
  void vtkIceRepresentation::Set##name(type v)                                                     \
  {                                                                                                \
    this->ForEachIceMapper([v](vtkIceMapper* m) { m->Set##name(value); });                         \
  }

vtkIceLookMacro(IndexOfRefraction, double, v);
vtkIceLookMacro(FresnelPower, double, v);
vtkIceLookMacro(FresnelModel, int, v);
vtkIceLookMacro(BackNormalWeight, double, v);
vtkIceDrawingMacro(TwoSidedRefraction, int, v != 0);
vtkIceDrawingMacro(WetBase, int, v != 0);
// The representation has no TwoSidedMethod: tracing (above 1) goes with the exit point it needs.
void vtkIceRepresentation::SetMaxBounces(int v)
{
  this->ForEachIceMapper([v](vtkIceMapper* m) {
    m->SetMaxBounces(v);
    m->SetTwoSidedMethod(
      v > 1 ? vtkIceMapper::TwoSidedExitPoint : vtkIceMapper::TwoSidedBlendedNormals);
  });
}
vtkIceLookMacro(NumberOfCracks, int, v);
vtkIceLookMacro(CrackSeed, int, v);
vtkIceLookMacro(CrackIntensity, double, v);
void vtkIceRepresentation::SetCrackClipping(int v)
{
  this->ForEachIceMapper([v](vtkIceMapper* m) { m->GetPaperInterior()->SetCrackClipping(v); });
}
vtkIceLookMacro(NumberOfAirPlanes, int, v);
vtkIceLookMacro(AirSeed, int, v);
vtkIceLookMacro(Milkiness, double, v);
vtkIceLookMacro(MilkyCoreRadius, double, v);
vtkIceLookMacro(BubbleDensity, double, v);
// "Roughness" is ParaView's physically based lighting's (vtkGeometryRepresentation::SetRoughness).
void vtkIceRepresentation::SetIceRoughness(double v)
{
  this->GetIceProperty()->SetRoughness(v);
}
vtkIceLookMacro(CrackReflection, double, v);
vtkIceLookMacro(BumpStrength, double, v);
vtkIceLookMacro(BumpScale, double, v);
vtkIceLookMacro(Glistening, int, v != 0);
vtkIceLookMacro(GlisteningIntensity, double, v);
vtkIceLookMacro(SnowAmount, double, v);
vtkIceDrawingMacro(InteriorMethod, int, v);
#undef vtkIceLookMacro
#undef vtkIceDrawingMacro

void vtkIceRepresentation::SetIceColor(double red, double green, double blue)
{
  this->GetIceProperty()->SetIceColor(red, green, blue);
}

void vtkIceRepresentation::SetAttenuationColor(double red, double green, double blue)
{
  this->GetIceProperty()->SetAttenuationColor(red, green, blue);
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::SetAbsorption(int value)
{
  this->Absorption = value != 0;
  this->PushAttenuationDistance();
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::SetAttenuationDistance(double value)
{
  this->AttenuationDistance = value;
  this->PushAttenuationDistance();
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::PushAttenuationDistance()
{
  const double distance =
    this->Absorption ? this->AttenuationDistance : std::numeric_limits<double>::infinity();
  this->GetIceProperty()->SetAttenuationDistance(distance);
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IceMapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
