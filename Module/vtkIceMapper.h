/**
 * @class   vtkIceMapper
 * @brief   Renders polygonal data as ice (Seipel & Nivfors).
 *
 * vtkIceMapper is a vtkOpenGLPolyDataMapper whose surfaces look like ice: the eye vector is
 * refracted (eq 2) and reflected (eq 3) about the surface normal, both directions sample an
 * environment cube map, and the two colours are mixed by a per-vertex Fresnel term (eq 4).
 *
 * The environment is the prop's dynamic cube map when a vtkIceCubeMapPass renders one, otherwise
 * the renderer's environment texture (vtkRenderer::SetEnvironmentTexture with a
 * vtkTexture that has CubeMapOn), looked up with the same world directions vtkSkybox uses, so ice
 * with RefractionRatio 1 disappears against a skybox of the same cube map. Without such a texture
 * the mapper warns once and uses a small built-in sky.
 *
 * With vtkIcePass set on the renderer, refraction is two-sided (paper eq 1): the refraction
 * normal blends the front normal with the back-face normal found behind each pixel, weighted by
 * BackNormalWeight. Without the pass, or with TwoSidedRefraction off, refraction is one-sided.
 *
 * Any polydata with polygons works: point normals are computed when the input has none. Inputs
 * without polygons or with non-finite points are reported with an error and not drawn.
 */
#ifndef vtkIceMapper_h
#define vtkIceMapper_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // for members

#include <map> // for members

class vtkPolyData;
class vtkProp;
class vtkTexture;
class vtkTextureObject;

class RENDERINGICE_EXPORT vtkIceMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkIceMapper* New();
  vtkTypeMacro(vtkIceMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Ratio of refraction indices, from / to (eta of eq 2). Default air/ice 1.0003/1.3091.
   * Clamped to [0.05, 20]; a value of 1 lets rays pass undeflected.
   */
  vtkSetClampMacro(RefractionRatio, double, 0.05, 20.0);
  vtkGetMacro(RefractionRatio, double);
  ///@}

  ///@{
  /**
   * Exponent of the Fresnel approximation f = (1 - |e.n|)^P (eq 4). Default 3.
   * Larger values show less reflection away from the silhouette. Clamped to [0, 1e6].
   */
  vtkSetClampMacro(FresnelPower, double, 0.0, 1.0e6);
  vtkGetMacro(FresnelPower, double);
  ///@}

  ///@{
  /**
   * Weight a of the back-face normal in the blended refraction normal (eq 1). Default 0.33.
   * Used by two-sided refraction; clamped to [0, 1].
   */
  vtkSetClampMacro(BackNormalWeight, double, 0.0, 1.0);
  vtkGetMacro(BackNormalWeight, double);
  ///@}

  ///@{
  /**
   * Two-sided refraction (eq 1) when vtkIcePass supplies back-face normals. Default on; off gives
   * the one-sided result for comparison.
   */
  vtkSetMacro(TwoSidedRefraction, bool);
  vtkGetMacro(TwoSidedRefraction, bool);
  vtkBooleanMacro(TwoSidedRefraction, bool);
  ///@}

  ///@{
  /**
   * The back-face normal texture of the current frame (RGB world normal, alpha coverage, at
   * viewport size). vtkIcePass sets it before rendering the scene and clears it afterwards.
   */
  void SetBackfaceNormalTexture(vtkTextureObject* texture);
  vtkTextureObject* GetBackfaceNormalTexture();
  ///@}

  ///@{
  /**
   * Tint multiplied into the ice colour, each component in [0, 1]. Default white.
   */
  vtkSetVector3Macro(IceColor, double);
  vtkGetVector3Macro(IceColor, double);
  ///@}

  /**
   * The vtkIceMapper of `prop` if it is a visible vtkActor drawn by one, else null.
   */
  static vtkIceMapper* GetIceMapperOf(vtkProp* prop);

  /**
   * Draws the ice. Validates the input and adds normals before the usual OpenGL rendering.
   */
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

  /**
   * Bounds of the input. Also checks the input, so that bad input is reported even when the
   * renderer culls the actor (empty data has no bounds).
   */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }

  /**
   * Frees the OpenGL resources of this mapper (and of its built-in sky) for the window.
   */
  void ReleaseGraphicsResources(vtkWindow* win) override;

  /**
   * The ice is opaque: the scene behind it is seen through the environment map.
   */
  bool HasOpaqueGeometry() override { return true; }
  bool HasTranslucentPolygonalGeometry() override { return false; }

protected:
  vtkIceMapper();
  ~vtkIceMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // Whether the shader being built samples back-face normals.
  bool UseTwoSidedShader() const;

  // Checks the input and builds the polydata actually drawn (input plus ice normals).
  bool PrepareInput(vtkPolyData* input);
  // The cube map the ice samples: the prop's dynamic cube map, the renderer's environment texture
  // or the built-in sky. Binds it and returns it.
  vtkTextureObject* BindEnvironment(vtkRenderer* ren, vtkActor* act);
  vtkTexture* SelectEnvironment(vtkRenderer* ren);
  // Whether the helper being compiled draws surfaces (ice) rather than lines or points.
  bool IsSurfaceHelper(const vtkOpenGLHelper* helper) const;

  double RefractionRatio;
  double FresnelPower;
  double BackNormalWeight;
  double IceColor[3];
  bool TwoSidedRefraction = true;

  vtkSmartPointer<vtkTextureObject> BackfaceNormalTexture;
  std::map<const vtkOpenGLHelper*, bool> TwoSidedShaderBuilt;

  vtkSmartPointer<vtkPolyData> PreparedInput;
  vtkMTimeType PreparedInputTime = 0;
  vtkPolyData* PreparedSource = nullptr;
  bool PreparedValid = false;

  vtkSmartPointer<vtkTexture> FallbackEnvironment;
  vtkTexture* ActiveEnvironment = nullptr;             // bound vtkTexture, if one is used
  vtkTextureObject* ActiveEnvironmentObject = nullptr; // what the shader samples
  bool WarnedNoEnvironment = false;

private:
  vtkIceMapper(const vtkIceMapper&) = delete;
  void operator=(const vtkIceMapper&) = delete;
};

#endif
