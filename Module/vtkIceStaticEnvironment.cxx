#include "vtkIceStaticEnvironment.h"

#include "vtkIceCubeMapSource.h"

#include "vtkAlgorithm.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

namespace
{
// Whether every face of a cube-map texture has an image. A reader that failed (missing or
// corrupt files) gives empty faces: bound anyway, the texture reports an error every frame and
// the ice samples an incomplete texture (GL_INVALID_VALUE for its sampler).
bool HasFaceImages(vtkTexture* texture)
{
  for (int port = 0; port < texture->GetNumberOfInputPorts(); ++port)
  {
    int outputPort = 0;
    vtkAlgorithm* producer = texture->GetNumberOfInputConnections(port) > 0
      ? texture->GetInputAlgorithm(port, 0, outputPort)
      : nullptr;
    if (!producer)
    {
      return false;
    }
    producer->Update(outputPort);
    vtkImageData* face = vtkImageData::SafeDownCast(producer->GetOutputDataObject(outputPort));
    if (!face || face->GetNumberOfPoints() == 0 || !face->GetPointData()->GetScalars())
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceStaticEnvironment::Select(vtkRenderer* renderer, vtkObject* owner)
{
  vtkTexture* env = renderer->GetEnvironmentTexture();
  const bool cubeMap = env && env->GetCubeMap();
  if (cubeMap && HasFaceImages(env))
  {
    return env;
  }
  if (!this->Warned)
  {
    vtkWarningWithObjectMacro(
      owner, << (!env          ? "The renderer has no environment texture"
                    : !cubeMap ? "The renderer's environment texture is not a cube map"
                               : "The renderer's environment cube map has faces without "
                                 "an image (did its reader fail?)")
             << "; the ice reflects a built-in sky. Set a vtkTexture with CubeMapOn() "
                "with vtkRenderer::SetEnvironmentTexture.");
    this->Warned = true;
  }
  if (!this->Fallback)
  {
    vtkNew<vtkIceCubeMapSource> sky;
    sky->SetFaceSize(64);
    this->Fallback = vtkSmartPointer<vtkTexture>::New();
    sky->ConfigureTexture(this->Fallback);
  }
  return this->Fallback;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceStaticEnvironment::Bind(vtkRenderer* renderer, vtkObject* owner)
{
  this->Bound = this->Select(renderer, owner);
  this->Bound->Render(renderer);
  return static_cast<vtkOpenGLTexture*>(this->Bound)->GetTextureObject();
}

//------------------------------------------------------------------------------
void vtkIceStaticEnvironment::Unbind(vtkRenderer* renderer)
{
  if (this->Bound)
  {
    this->Bound->PostRender(renderer);
    this->Bound = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkIceStaticEnvironment::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Fallback)
  {
    this->Fallback->ReleaseGraphicsResources(window);
  }
}
