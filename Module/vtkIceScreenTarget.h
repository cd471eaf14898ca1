// A viewport-sized render target of the ice sub-passes: a float colour texture (sampled texel
// for pixel, never filtered) and a depth texture in a framebuffer, made on first use and resized
// with the viewport.
#ifndef vtkIceScreenTarget_h
#define vtkIceScreenTarget_h

#include "vtkSmartPointer.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkTextureObject;
class vtkWindow;

class vtkIceScreenTarget
{
public:
  vtkIceScreenTarget();
  ~vtkIceScreenTarget();

  // Makes or resizes the textures: `components` float channels (2 or 4) and depth.
  void Prepare(vtkOpenGLRenderWindow* window, int width, int height, int components);

  // Draws into the target from here to Unbind, with a (0, 0, width, height) viewport and scissor.
  // The caller keeps (scoped savers) the viewport and scissor it wants back.
  void Bind(vtkOpenGLState* state);
  void Unbind(vtkOpenGLState* state);

  vtkTextureObject* GetColorTexture() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkSmartPointer<vtkTextureObject> ColorTexture;
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  int Width = 0;
  int Height = 0;

  vtkIceScreenTarget(const vtkIceScreenTarget&) = delete;
  void operator=(const vtkIceScreenTarget&) = delete;
};

#endif
