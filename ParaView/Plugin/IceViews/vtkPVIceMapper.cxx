#include "vtkPVIceMapper.h"

#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

vtkStandardNewMacro(vtkPVIceMapper);

//------------------------------------------------------------------------------
vtkPVIceMapper::vtkPVIceMapper() = default;

//------------------------------------------------------------------------------
vtkPVIceMapper::~vtkPVIceMapper() = default;

//------------------------------------------------------------------------------
void vtkPVIceMapper::SetBackgroundEnvironment(vtkTexture* texture)
{
  if (this->BackgroundEnvironment != texture)
  {
    this->BackgroundEnvironment = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTexture* vtkPVIceMapper::GetBackgroundEnvironment()
{
  return this->BackgroundEnvironment;
}

//------------------------------------------------------------------------------
void vtkPVIceMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  // vtkIceMapper binds the renderer's environment here; the renderer has it for that moment only.
  if (!this->BackgroundEnvironment || ren->GetEnvironmentTexture())
  {
    this->Superclass::RenderPieceStart(ren, act);
    return;
  }
  ren->SetEnvironmentTexture(this->BackgroundEnvironment);
  this->Superclass::RenderPieceStart(ren, act);
  ren->SetEnvironmentTexture(nullptr);
}

//------------------------------------------------------------------------------
void vtkPVIceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundEnvironment: " << this->BackgroundEnvironment << "\n";
}
