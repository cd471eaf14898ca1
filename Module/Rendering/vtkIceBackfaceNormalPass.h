// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceBackfaceNormalPass
 * @brief   Renders the back-face world normals of the ice props into a float texture.
 *
 * For two-sided refraction (paper eq 1) the ice shader needs, at each pixel, the normal of the
 * ice's back face. This pass renders the props of its render state (vtkIcePass gives it only the
 * ice props) with front faces culled and writes their world-space normals, normalised per
 * fragment, into an RGBA32F texture the size of the viewport. Alpha is 1 where ice was drawn and
 * 0 elsewhere. The texture follows the viewport's size and is freed by ReleaseGraphicsResources.
 * Cracks of ice mappers with CracksPerturbRefraction on are drawn into it too, where they lie in
 * front of the back face.
 */
#ifndef vtkIceBackfaceNormalPass_h
#define vtkIceBackfaceNormalPass_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLRenderPass.h"

#include <memory> // for members

class vtkIceScreenTarget;
class vtkTextureObject;

class RENDERINGICE_EXPORT vtkIceBackfaceNormalPass : public vtkOpenGLRenderPass
{
public:
  static vtkIceBackfaceNormalPass* New();
  vtkTypeMacro(vtkIceBackfaceNormalPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Renders the props of `s` into the normal texture.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * The texture of the last Render: RGB world normal, alpha coverage. Null before the first.
   */
  vtkTextureObject* GetNormalTexture();

  /**
   * Renders since creation.
   */
  vtkGetMacro(NumberOfGeometryPasses, vtkIdType);

  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkIceBackfaceNormalPass();
  ~vtkIceBackfaceNormalPass() override;

  std::unique_ptr<vtkIceScreenTarget> Target;
  vtkIdType NumberOfGeometryPasses = 0;

private:
  vtkIceBackfaceNormalPass(const vtkIceBackfaceNormalPass&) = delete;
  void operator=(const vtkIceBackfaceNormalPass&) = delete;
};

#endif
