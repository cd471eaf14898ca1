// A viewport-sized render target of the ice sub-passes: a float colour texture (sampled texel
// for pixel, never filtered) and a depth texture in a framebuffer, made on first use and resized
// with the viewport.
#ifndef vtkIceScreenTarget_h
#define vtkIceScreenTarget_h

#include "vtkOpenGLState.h" // for Drawing
#include "vtkSmartPointer.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
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

  // For its lifetime: the target sized to the renderer's viewport and bound, depth test on with
  // depth writes, blending off; then everything it changed is put back.
  class Drawing
  {
  public:
    Drawing(vtkIceScreenTarget& target, vtkRenderer* renderer, int components);
    ~Drawing();
    vtkOpenGLState* State;

  private:
    vtkIceScreenTarget& Target;
    vtkOpenGLState::ScopedglViewport Viewport;
    vtkOpenGLState::ScopedglScissor Scissor;
    vtkOpenGLState::ScopedglClearColor ClearColor;
    vtkOpenGLState::ScopedglColorMask ColorMask;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
    vtkOpenGLState::ScopedglDepthFunc DepthFunc;
    vtkOpenGLState::ScopedglEnableDisable DepthTest;
    vtkOpenGLState::ScopedglEnableDisable Blend;
  };

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
