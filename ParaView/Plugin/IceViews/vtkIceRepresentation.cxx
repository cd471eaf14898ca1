#include "vtkIceRepresentation.h"

#include "vtkCompositeDataGeometryFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkIceMapper.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVView.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkIceRepresentation);

//------------------------------------------------------------------------------
vtkIceRepresentation::vtkIceRepresentation()
{
  // Replace the superclass's composite mappers; SetupDefaults wires the new ones to the actor.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkIceMapper::New();
  this->LODMapper = vtkIceMapper::New();
  // Without a skybox ParaView's views have no environment: the built-in sky is the default.
  this->ForEachIceMapper([](vtkIceMapper* m) { m->WarnWithoutEnvironmentOff(); });
  this->SetupDefaults();
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
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::SetRefractionRatio(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetRefractionRatio(value); });
}

void vtkIceRepresentation::SetFresnelPower(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetFresnelPower(value); });
}

void vtkIceRepresentation::SetBackNormalWeight(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetBackNormalWeight(value); });
}

void vtkIceRepresentation::SetTwoSidedRefraction(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetTwoSidedRefraction(value != 0); });
}

void vtkIceRepresentation::SetIceColor(double red, double green, double blue)
{
  this->ForEachIceMapper([=](vtkIceMapper* m) { m->SetIceColor(red, green, blue); });
}

void vtkIceRepresentation::SetNumberOfCracks(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetNumberOfCracks(value); });
}

void vtkIceRepresentation::SetCrackSeed(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetCrackSeed(value); });
}

void vtkIceRepresentation::SetCrackIntensity(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetCrackIntensity(value); });
}

void vtkIceRepresentation::SetCrackClipping(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetCrackClipping(value); });
}

void vtkIceRepresentation::SetNumberOfAirPlanes(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetNumberOfAirPlanes(value); });
}

void vtkIceRepresentation::SetAirSeed(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetAirSeed(value); });
}

void vtkIceRepresentation::SetMilkiness(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetMilkiness(value); });
}

void vtkIceRepresentation::SetBumpStrength(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetBumpStrength(value); });
}

void vtkIceRepresentation::SetBumpScale(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetBumpScale(value); });
}

void vtkIceRepresentation::SetGlistening(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetGlistening(value != 0); });
}

void vtkIceRepresentation::SetGlisteningIntensity(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetGlisteningIntensity(value); });
}

void vtkIceRepresentation::SetSnowAmount(double value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetSnowAmount(value); });
}

void vtkIceRepresentation::SetInteriorMethod(int value)
{
  this->ForEachIceMapper([value](vtkIceMapper* m) { m->SetInteriorMethod(value); });
}

//------------------------------------------------------------------------------
void vtkIceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IceMapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
