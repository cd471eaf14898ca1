// The environment an ice mapper samples when no pass hands it a dynamic cube map: the renderer's
// environment texture, or a built-in sky (with one warning) when that is missing or unusable.
#ifndef vtkIceStaticEnvironment_h
#define vtkIceStaticEnvironment_h

#include "vtkSmartPointer.h"

class vtkObject;
class vtkRenderer;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

class vtkIceStaticEnvironment
{
public:
  // Binds the environment for a draw of `owner` (who warns) in `renderer`; returns what the
  // shader samples.
  vtkTextureObject* Bind(vtkRenderer* renderer, vtkObject* owner);
  // After the draw.
  void Unbind(vtkRenderer* renderer);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTexture* Select(vtkRenderer* renderer, vtkObject* owner);

  vtkSmartPointer<vtkTexture> Fallback;
  vtkTexture* Bound = nullptr;
  bool Warned = false;
};

#endif
