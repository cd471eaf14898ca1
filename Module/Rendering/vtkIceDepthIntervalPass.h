// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
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
 * are fitted to the props' bounding box, as the paper does for depth precision.
 */
#ifndef vtkIceDepthIntervalPass_h
#define vtkIceDepthIntervalPass_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <memory> // for members

class vtkIceScreenTarget;
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
   * The depth buffer of the last Render (window depth of the last stage drawn: with FrontOnly,
   * the nearest front faces', 1 where there are none). Null before the first.
   */
  vtkTextureObject* GetDepthBufferTexture();

  /**
   * View-depth range of the props' bounding box in the last Render (nearest and farthest).
   */
  vtkGetVector2Macro(DepthRange, double);

  ///@{
  /**
   * Render the nearest front faces only (R); G then stays empty (-FLT_MAX). Default off. The
   * screen-space interior needs only the front (vtkIceMapper::InteriorScreenSpace).
   */
  vtkSetMacro(FrontOnly, bool);
  vtkGetMacro(FrontOnly, bool);
  vtkBooleanMacro(FrontOnly, bool);
  ///@}

  /**
   * Geometry passes rendered since creation (two per Render: front faces, back faces; one with
   * FrontOnly).
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

  std::unique_ptr<vtkIceScreenTarget> Target; // RG32F: the result
  double DepthRange[2] = { 0.0, 1.0 };
  int Stage = 0;
  bool FrontOnly = false;
  vtkIdType NumberOfGeometryPasses = 0;

private:
  vtkIceDepthIntervalPass(const vtkIceDepthIntervalPass&) = delete;
  void operator=(const vtkIceDepthIntervalPass&) = delete;
};

#endif
