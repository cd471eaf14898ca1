/**
 * @class   vtkIceDepthIntervalPass
 * @brief   Renders the ice's front and back depth into a float texture.
 *
 * Crack surfaces are clipped to the inside of the ice in screen space (paper section 3.3): a
 * crack fragment is kept only where its depth lies between the ice's front and back surfaces.
 * This pass renders the props of its render state (vtkIcePass gives it the ice props) twice into
 * an RG32F texture at viewport size: the nearest front-face view depth into R, the farthest
 * back-face view depth into G (view depth: distance in front of the camera along the view
 * direction). Where there is no ice, R > G. While it renders, the camera's near and far planes
 * are fitted to the props' bounding box, as the paper does for depth precision. Each frame only
 * the part of the texture the ice can cover (its projected bounding box, and where it was the
 * frame before) is cleared and drawn, and each stage culls the faces it does not want in OpenGL
 * rather than discarding them in the shader.
 */
#ifndef vtkIceDepthIntervalPass_h
#define vtkIceDepthIntervalPass_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h" // for members

#include <memory> // for members

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class RENDERINGICE_EXPORT vtkIceDepthIntervalPass : public vtkOpenGLRenderPass
{
public:
  static vtkIceDepthIntervalPass* New();
  vtkTypeMacro(vtkIceDepthIntervalPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;

  /**
   * The texture of the last Render (R front, G back view depth). Null before the first.
   */
  vtkTextureObject* GetDepthTexture();

  /**
   * View-depth range of the props' bounding box in the last Render (the fitted near and far).
   */
  vtkGetVector2Macro(DepthRange, double);

  /**
   * Geometry passes rendered since creation (two per Render: front faces, back faces).
   */
  vtkGetMacro(NumberOfGeometryPasses, vtkIdType);

  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkIceDepthIntervalPass();
  ~vtkIceDepthIntervalPass() override;

  void AllocateResources(vtkOpenGLRenderWindow* window, int width, int height);

  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkSmartPointer<vtkTextureObject> DepthTexture;   // RG32F colour: the result
  vtkSmartPointer<vtkTextureObject> ZBufferTexture; // depth attachment for the depth test
  double DepthRange[2] = { 0.0, 1.0 };
  int Stage = 0;
  vtkIdType NumberOfGeometryPasses = 0;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

private:
  vtkIceDepthIntervalPass(const vtkIceDepthIntervalPass&) = delete;
  void operator=(const vtkIceDepthIntervalPass&) = delete;
};

#endif
