/**
 * @class   vtkIceMapper
 * @brief   Renders polygonal data as ice (Seipel & Nivfors).
 *
 * vtkIceMapper is a vtkOpenGLPolyDataMapper whose surfaces look like ice: the eye vector is
 * refracted (eq 2) and reflected (eq 3) about the surface normal, both directions sample an
 * environment cube map, and the two colours are mixed by a per-vertex Fresnel term (eq 4).
 *
 * The environment is the prop's dynamic cube map when a vtkIceCubeMapPass renders one, otherwise
 * the renderer's environment texture (vtkRenderer::SetEnvironmentTexture with a vtkTexture that
 * has CubeMapOn), looked up with the same world directions vtkSkybox uses, so ice with
 * RefractionRatio 1 disappears against a skybox of the same cube map. Without such a texture the
 * mapper warns once and uses a small built-in sky.
 *
 * With vtkIcePass set on the renderer, refraction is two-sided (paper eq 1): the refraction
 * normal blends the front normal with the back-face normal found behind each pixel, weighted by
 * BackNormalWeight. Without the pass, or with TwoSidedRefraction off, refraction is one-sided.
 * vtkIcePass also draws the ice's cracks (NumberOfCracks generic crack surfaces placed at random
 * inside, showing only their specular highlights), clipped to the ice either per fragment by its
 * depth interval or once on the CPU (CrackClipping), and its air: NumberOfAirPlanes planes of
 * bubble images that make the ice milky (Milkiness). InteriorMethod chooses how: in the ice's
 * own fragment shader along the view ray (default), or the paper's passes. BumpStrength and
 * BumpScale make the surface bumpy. Air, cracks and bumps are on by default (the paper's full
 * look); set them to 0 for clean optics.
 *
 * Any polydata with polygons works: point normals are computed when the input has none. Inputs
 * without polygons or with non-finite points are reported with an error and not drawn. Flat
 * input (all points in one plane: no volume, no inside) is drawn as a surface without cracks,
 * with one warning. Open surfaces are drawn as they are; Geometry crack clipping needs a closed
 * one and falls back to the depth interval, with one warning.
 */
#ifndef vtkIceMapper_h
#define vtkIceMapper_h

#include "RenderingIceModule.h" // for export macro
#include "vtkIceWorldSpaceMapper.h"

#include <map>    // for members
#include <memory> // for members

class vtkActor;
class vtkIceInterior;
class vtkIceSinglePassInterior;
class vtkIcePrefilteredEnvironment;
class vtkIceStaticEnvironment;
class vtkIceBackfaceCulling;
class vtkIceGlisteningTexture;
class vtkProp;
class vtkTexture;
class vtkTextureObject;

class RENDERINGICE_EXPORT vtkIceMapper : public vtkIceWorldSpaceMapper
{
public:
  static vtkIceMapper* New();
  vtkTypeMacro(vtkIceMapper, vtkIceWorldSpaceMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The ice's index of refraction, as glTF's KHR_materials_ior means it (relative to the air
   * around it). Default 1.31, ice's. The ratio the optics use (eta of eq 2, RefractionRatio) is
   * its inverse: setting one sets the other. Clamped to [0.05, 20]; 1 lets rays pass undeflected.
   * NaN is refused with a warning.
   */
  virtual void SetIndexOfRefraction(double ior);
  virtual double GetIndexOfRefractionMinValue() { return 0.05; }
  virtual double GetIndexOfRefractionMaxValue() { return 20.0; }
  vtkGetMacro(IndexOfRefraction, double);
  ///@}

  ///@{
  /**
   * Ratio of refraction indices, from / to (eta of eq 2): 1 / IndexOfRefraction, which it sets.
   * Default 1 / 1.31. Clamped to [0.05, 20]; a value of 1 lets rays pass undeflected. NaN is
   * refused with a warning (this and the other floating-point parameters clamp as
   * vtkSetClampMacro does, which would store NaN).
   */
  virtual void SetRefractionRatio(double eta);
  virtual double GetRefractionRatioMinValue() { return 0.05; }
  virtual double GetRefractionRatioMaxValue() { return 20.0; }
  vtkGetMacro(RefractionRatio, double);
  ///@}

  ///@{
  /**
   * Absorption by the distance the light travels in the ice (Beer-Lambert), with glTF
   * KHR_materials_volume's meaning: white light that has travelled AttenuationDistance in the
   * ice has the colour AttenuationColor. Defaults: white and infinity (no absorption). The
   * distance is the refracted ray's path from the front face to the back face behind it, so it
   * needs vtkIcePass on the renderer (without it the ice does not absorb, and the mapper says
   * so once): with
   * TwoSidedExitPoint the path to the exit point, otherwise the eye ray's. Colour components are
   * clamped to [0, 1], the distance to [1e-6, infinity]; NaN is refused with a warning.
   */
  virtual void SetAttenuationColor(double red, double green, double blue);
  virtual void SetAttenuationColor(const double color[3])
  {
    this->SetAttenuationColor(color[0], color[1], color[2]);
  }
  vtkGetVector3Macro(AttenuationColor, double);
  virtual void SetAttenuationDistance(double distance);
  virtual double GetAttenuationDistanceMinValue() { return 1.0e-6; }
  virtual double GetAttenuationDistanceMaxValue();
  vtkGetMacro(AttenuationDistance, double);
  ///@}

  ///@{
  /**
   * Exponent of the Fresnel approximation f = (1 - |e.n|)^P (eq 4). Default 3.
   * Larger values show less reflection away from the silhouette. Clamped to [0, 1e6]; NaN is
   * refused with a warning.
   */
  virtual void SetFresnelPower(double power);
  virtual double GetFresnelPowerMinValue() { return 0.0; }
  virtual double GetFresnelPowerMaxValue() { return 1.0e6; }
  vtkGetMacro(FresnelPower, double);
  ///@}

  ///@{
  /**
   * Weight a of the back-face normal in the blended refraction normal (eq 1). Default 0.33.
   * Used by two-sided refraction; clamped to [0, 1]; NaN is refused with a warning.
   */
  virtual void SetBackNormalWeight(double weight);
  virtual double GetBackNormalWeightMinValue() { return 0.0; }
  virtual double GetBackNormalWeightMaxValue() { return 1.0; }
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

  enum TwoSidedMethods
  {
    TwoSidedBlendedNormals = 0, // the paper's eq 1: one refraction about a blended normal
    TwoSidedExitPoint = 1       // refraction at the front and again at the exit point
  };

  ///@{
  /**
   * How two-sided refraction goes through the ice. TwoSidedBlendedNormals (default): the paper's
   * eq 1, one refraction about the front normal blended with the back normal behind the pixel
   * (BackNormalWeight). TwoSidedExitPoint: the eye ray refracts at the front surface, travels
   * through the ice to an exit point estimated in image space from the back faces' depth, and
   * refracts again there, ice to air (where it cannot, it is reflected back into the ice and
   * leaves in that direction); BackNormalWeight is not used. Closer to real double refraction
   * (Documentation/optics.md has the measured errors) for a few more texture reads per pixel.
   */
  vtkSetClampMacro(TwoSidedMethod, int, TwoSidedBlendedNormals, TwoSidedExitPoint);
  vtkGetMacro(TwoSidedMethod, int);
  void SetTwoSidedMethodToBlendedNormals() { this->SetTwoSidedMethod(TwoSidedBlendedNormals); }
  void SetTwoSidedMethodToExitPoint() { this->SetTwoSidedMethod(TwoSidedExitPoint); }
  ///@}

  ///@{
  /**
   * Whether the mapper warns (once) when the renderer has no usable environment texture and the
   * ice reflects the built-in sky. Default on. ParaView's Ice representation turns it off: its
   * views have no environment unless the background is a skybox, and the sky is the default there.
   */
  vtkSetMacro(WarnWithoutEnvironment, bool);
  vtkGetMacro(WarnWithoutEnvironment, bool);
  vtkBooleanMacro(WarnWithoutEnvironment, bool);
  ///@}

  ///@{
  /**
   * Whether the ice skips its back faces in a draw where none of them can be seen (default on):
   * a closed surface whose faces point outward (checked once per input, from its second frame:
   * an input changed every frame is not checked), opaque, drawn as a surface without edges,
   * vertices, clipping planes, face culling of its own property or a mirroring transform, wholly
   * beyond the camera's near plane. Such back faces are hidden by the front faces, but a CPU
   * renderer shades many of them before the depth test hides them; skipping them saves up to a
   * quarter of a frame (Documentation/performance.md). Off: both sides are drawn, as VTK does.
   */
  vtkSetMacro(CullHiddenBackfaces, bool);
  vtkGetMacro(CullHiddenBackfaces, bool);
  vtkBooleanMacro(CullHiddenBackfaces, bool);
  ///@}

  /**
   * Whether the mapper's last draw in the main scene skipped the back faces (CullHiddenBackfaces).
   */
  vtkGetMacro(LastDrawCulledBackfaces, bool);

  ///@{
  /**
   * Bounds of the whole ice object when the input is one piece of it (distributed rendering:
   * ParaView's Ice representation sets the bounds of the data on all ranks). Cracks, air planes
   * and the bump scale are placed in these bounds instead of the input's, so every piece looks
   * as its part of the whole does; they are also the mapper's bounds (the dynamic cube map's
   * centre, culling) and empty input is a piece with nothing to draw, not an error.
   * Uninitialized (the default, vtkMath::UninitializeBounds): the input's own bounds.
   */
  vtkSetVector6Macro(PlacementBounds, double);
  vtkGetVector6Macro(PlacementBounds, double);
  ///@}

  /**
   * The mapper's bounds: PlacementBounds when set (the input is still checked), else the input's.
   */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }

  ///@{
  /**
   * Tint multiplied into the ice colour, each component clamped to [0, 1]. Default white. A
   * colour with a NaN component is refused with a warning. When the mapper colours by scalars
   * (ScalarVisibility with point scalars or a selected point array, mapped through the lookup
   * table as by any VTK mapper), the mapped colour of each point is the tint instead; refraction
   * and reflection stay. Cell arrays do not tint the ice. Unlike other VTK mappers,
   * ScalarVisibility is off by default: a surface that carries scalars (an iso-surface from
   * vtkContourFilter) keeps the ice colour until ScalarVisibilityOn() asks for the tint.
   */
  virtual void SetIceColor(double red, double green, double blue);
  virtual void SetIceColor(const double color[3])
  {
    this->SetIceColor(color[0], color[1], color[2]);
  }
  vtkGetVector3Macro(IceColor, double);
  ///@}

  ///@{
  /**
   * Number of crack surfaces inside the ice (drawn by vtkIcePass). Default 2; clamped to
   * [0, 1000]. They cost one draw whatever their number.
   */
  vtkSetClampMacro(NumberOfCracks, int, 0, 1000);
  vtkGetMacro(NumberOfCracks, int);
  ///@}

  ///@{
  /**
   * Seed of the cracks' models, rotations and positions: the same seed gives the same cracks.
   */
  vtkSetMacro(CrackSeed, int);
  vtkGetMacro(CrackSeed, int);
  ///@}

  ///@{
  /**
   * Brightness of the cracks' highlights. Default 1. Clamped to [0, 100]; NaN is refused with a
   * warning.
   */
  virtual void SetCrackIntensity(double intensity);
  virtual double GetCrackIntensityMinValue() { return 0.0; }
  virtual double GetCrackIntensityMaxValue() { return 100.0; }
  vtkGetMacro(CrackIntensity, double);
  ///@}

  ///@{
  /**
   * Cracks as sheets: how much of the reflectance of a thin gap of air in the ice (Fresnel's,
   * all of it at glancing angles: total internal reflection) a crack mirrors of the environment,
   * its outline whitening with it. 0: the highlights alone, the paper's look. Default 0.4.
   * Clamped to [0, 1]. Drawn by the single-pass interior (InteriorSinglePass) with vtkIcePass.
   */
  virtual void SetCrackReflection(double reflection);
  virtual double GetCrackReflectionMinValue() { return 0.0; }
  virtual double GetCrackReflectionMaxValue() { return 1.0; }
  vtkGetMacro(CrackReflection, double);
  ///@}

  enum CrackClippingModes
  {
    DepthInterval = 0, // per fragment, against the ice's [front, back] depth (the paper)
    Geometry = 1       // once on the CPU against the ice surface: exact for concave ice
  };

  ///@{
  /**
   * How cracks are kept inside the ice. Default DepthInterval. Geometry needs a closed surface:
   * for an open one (a warning says so) the cracks are clipped to the depth interval.
   */
  vtkSetClampMacro(CrackClipping, int, DepthInterval, Geometry);
  vtkGetMacro(CrackClipping, int);
  void SetCrackClippingToDepthInterval() { this->SetCrackClipping(DepthInterval); }
  void SetCrackClippingToGeometry() { this->SetCrackClipping(Geometry); }
  ///@}

  ///@{
  /**
   * Let the cracks' normals perturb the refraction (the paper's experiment): cracks are drawn
   * into the back-face normal texture too. Default off.
   */
  vtkSetMacro(CracksPerturbRefraction, bool);
  vtkGetMacro(CracksPerturbRefraction, bool);
  vtkBooleanMacro(CracksPerturbRefraction, bool);
  ///@}

  ///@{
  /**
   * Number of air-bubble planes inside the ice (drawn by vtkIcePass, alpha blended, back to
   * front, clipped to the ice). Default 19, as in the paper's measurements; clamped to
   * [0, 1000]. 0 turns the air off.
   */
  vtkSetClampMacro(NumberOfAirPlanes, int, 0, 1000);
  vtkGetMacro(NumberOfAirPlanes, int);
  ///@}

  ///@{
  /**
   * Seed of the air planes' positions, orientations and images. Default 1.
   */
  vtkSetMacro(AirSeed, int);
  vtkGetMacro(AirSeed, int);
  ///@}

  ///@{
  /**
   * How white and cloudy the air makes the ice: 0 sparse clear bubbles, 1 milky. Default 0.5.
   */
  virtual void SetMilkiness(double milkiness);
  virtual double GetMilkinessMinValue() { return 0.0; }
  virtual double GetMilkinessMaxValue() { return 1.0; }
  vtkGetMacro(Milkiness, double);
  ///@}

  ///@{
  /**
   * A milky core: air gathered where the ice froze last, around the centre of its bounds, as a
   * cloud that whitens what is seen through it (by Milkiness: a ray through its centre at
   * Milkiness 1 loses 98 % of what is behind) and draws the air planes' bubbles towards it. The
   * core's radius is this fraction of the ice's half size along each axis; the cloud thins
   * smoothly beyond it. 0 (the default): no core, the air planes spread evenly. Clamped to
   * [0, 10]. Drawn by the single-pass interior (InteriorSinglePass) with vtkIcePass.
   */
  virtual void SetMilkyCoreRadius(double radius);
  virtual double GetMilkyCoreRadiusMinValue() { return 0.0; }
  virtual double GetMilkyCoreRadiusMaxValue() { return 10.0; }
  vtkGetMacro(MilkyCoreRadius, double);
  ///@}

  ///@{
  /**
   * Frost: how rough the surface is, in [0, 1] (glTF's roughness: GGX with alpha = roughness^2).
   * Reflection and refraction both show the environment averaged over the rough surface's lobe
   * (the environment prefiltered once per change of it, static or dynamic), as cold ice covered
   * in small crystals does. 0 (the default): a mirror-smooth surface, the paper's look.
   */
  virtual void SetRoughness(double roughness);
  virtual double GetRoughnessMinValue() { return 0.0; }
  virtual double GetRoughnessMaxValue() { return 1.0; }
  vtkGetMacro(Roughness, double);
  ///@}

  ///@{
  /**
   * A bumpy surface: how far the normal tilts (0 = smooth, the paper's clean optics) and the size
   * of a bump as a fraction of the ice's largest extent. The bumps are fixed to the model, so they
   * do not swim when the camera moves, and they drive reflection, refraction and Fresnel.
   * Defaults 0.08 and 0.15.
   */
  virtual void SetBumpStrength(double bumpStrength);
  virtual double GetBumpStrengthMinValue() { return 0.0; }
  virtual double GetBumpStrengthMaxValue() { return 10.0; }
  vtkGetMacro(BumpStrength, double);
  virtual void SetBumpScale(double bumpScale);
  virtual double GetBumpScaleMinValue() { return 1.0e-4; }
  virtual double GetBumpScaleMaxValue() { return 100.0; }
  vtkGetMacro(BumpScale, double);
  ///@}

  ///@{
  /**
   * A tangent-space normal map (RGB, repeat on) used instead of the procedural bumps, projected
   * on the three model planes; BumpStrength scales it and BumpScale is the size of one repeat.
   */
  void SetNormalMap(vtkTexture* texture);
  vtkTexture* GetNormalMap();
  ///@}

  ///@{
  /**
   * Glistening ice and snow (Liquidiced): direct light from the scene's lights (Phong with a
   * broad, soft specular on a subtle wavy bump), rim light, and two layers of crack glints (one
   * roughly parallel to the surface, one of any orientation) from a random normal texture, crisp
   * at any distance. Added to the ice; with SnowAmount 1 the surface is snow instead. Default off.
   */
  vtkSetMacro(Glistening, bool);
  vtkGetMacro(Glistening, bool);
  vtkBooleanMacro(Glistening, bool);
  ///@}

  ///@{
  /**
   * With Glistening: size of a crack cell in the input's units. Default 0.03; clamped to
   * [1e-6, 1e6].
   */
  virtual void SetGlisteningScale(double glisteningScale);
  virtual double GetGlisteningScaleMinValue() { return 1.0e-6; }
  virtual double GetGlisteningScaleMaxValue() { return 1.0e6; }
  vtkGetMacro(GlisteningScale, double);
  ///@}

  ///@{
  /**
   * With Glistening: brightness of the glints. Default 1; clamped to [0, 100].
   */
  virtual void SetGlisteningIntensity(double glisteningIntensity);
  virtual double GetGlisteningIntensityMinValue() { return 0.0; }
  virtual double GetGlisteningIntensityMaxValue() { return 100.0; }
  vtkGetMacro(GlisteningIntensity, double);
  ///@}

  ///@{
  /**
   * With Glistening: gain of the glints where the view looks along a light's direction (the light
   * behind the viewer), where the surface specular and the parallel crack layer are missing.
   * Default 2 (doubled, as in Liquidiced); 1 turns the intensification off. Clamped to [1, 10].
   */
  virtual void SetGlisteningAlignmentGain(double glisteningAlignmentGain);
  virtual double GetGlisteningAlignmentGainMinValue() { return 1.0; }
  virtual double GetGlisteningAlignmentGainMaxValue() { return 10.0; }
  vtkGetMacro(GlisteningAlignmentGain, double);
  ///@}

  ///@{
  /**
   * With Glistening: 0 gives ice, 1 snow (white, diffuse), values between blend the two looks.
   * Default 0; clamped to [0, 1]. Snow without Glistening shows nothing: the mapper says so once.
   */
  virtual void SetSnowAmount(double snowAmount);
  virtual double GetSnowAmountMinValue() { return 0.0; }
  virtual double GetSnowAmountMaxValue() { return 1.0; }
  vtkGetMacro(SnowAmount, double);
  ///@}

  enum InteriorMethods
  {
    InteriorPaperPasses = 0, // the paper: a depth-interval pass, crack and air draws per ice
    InteriorSinglePass = 1   // in the ice's own fragment shader, intersected along the view ray
  };

  ///@{
  /**
   * How the cracks and air inside the ice are rendered (both need vtkIcePass).
   * InteriorSinglePass (default): the ice's fragment shader intersects the view ray, from the
   * front surface to the nearest back face (whose depth the back-face pass stores), with every
   * crack sheet and air plane and composites them there: no depth-interval pass, no crack or air
   * draw call. InteriorPaperPasses: the paper's method: the ice's depth interval is rendered,
   * then the air planes (blended, back to front) and the crack sheets (their highlights added)
   * are drawn over it. On a GPU the single pass is the faster one at the default look (an
   * NVIDIA H200, VTK's default window: 2-43 % less frame time); on llvmpipe the paper's passes
   * are (30-48 % less): Documentation/performance.md. DebugCracksUnclipped always uses the paper's
   * passes.
   */
  vtkSetClampMacro(InteriorMethod, int, InteriorPaperPasses, InteriorSinglePass);
  vtkGetMacro(InteriorMethod, int);
  void SetInteriorMethodToSinglePass() { this->SetInteriorMethod(InteriorSinglePass); }
  void SetInteriorMethodToPaperPasses() { this->SetInteriorMethod(InteriorPaperPasses); }
  ///@}

  enum DebugViews
  {
    DebugOff = 0,
    DebugFrontDepth = 1,      // the ice's front depth (near black, far white)
    DebugBackDepth = 2,       // the ice's back depth
    DebugCracksUnclipped = 3, // cracks in red, not clipped, over everything
    DebugCracksClipped = 4,   // cracks in red, clipped
    DebugAir = 5              // air bubbles in green
  };

  ///@{
  /**
   * The paper's Figure 5 views. Default DebugOff.
   */
  vtkSetClampMacro(DebugView, int, DebugOff, DebugAir);
  vtkGetMacro(DebugView, int);
  ///@}

  /**
   * The crack surfaces in the input's coordinates: NumberOfCracks instances of three generic
   * crack models, randomly rotated, near the centre, scaled to the input's bounds; clipped to the
   * ice surface in Geometry mode. Rebuilt only when the input or a crack parameter changes.
   */
  vtkPolyData* GetCrackGeometry();

  /**
   * Number of crack draw calls since creation (one per frame step that draws this ice's cracks).
   */
  vtkGetMacro(NumberOfCrackDraws, vtkIdType);

  void ReleaseGraphicsResources(vtkWindow* win) override;

  /**
   * The ice is opaque: the scene behind it is seen through the environment map.
   */
  bool HasOpaqueGeometry() override { return true; }
  bool HasTranslucentPolygonalGeometry() override { return false; }

protected:
  vtkIceMapper();
  ~vtkIceMapper() override;

  // What vtkIcePass asks of the mapper in a frame (vtkIceMapperAccess, inside the module): what
  // this ice needs rendered for it (vtkIceFrame::Need bits), its cracks and its air drawn.
  friend class vtkIceMapperAccess;
  int GetFrameNeeds();
  void RenderCracks(vtkRenderer* ren, vtkActor* actor, bool overlay);
  void RenderAir(vtkRenderer* ren, vtkActor* actor);

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act) override;
  void SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // Which optional shader parts of the mapper's own the next build includes (bumps, glistening;
  // vtkIcePass adds the parts that sample its textures).
  int ShaderVariant() const;
  // Whether VTK's colour code of the bound primitive holds colours mapped from scalars.
  bool DrawsScalarColors();

  // Looks at a new input: flat input (no volume, hence no inside) gets no cracks.
  void InputPrepared() override;

  // The crack clipping the input allows: Geometry needs a closed surface (the inside is found by
  // ray casting); an open one is clipped to the depth interval instead, with one warning.
  int UsableCrackClipping();

  // Whether the interior (cracks or air) is drawn in this frame, and by which method.
  bool Absorbs() const; // absorption set: a path length is needed
  bool HasInterior() const;
  bool HasMilkyCore() const; // MilkyCoreRadius and Milkiness above 0
  bool UsesSinglePassInterior() const;

  double IndexOfRefraction;
  double RefractionRatio;
  double FresnelPower;
  double BackNormalWeight;
  double IceColor[3];
  double AttenuationColor[3];
  double AttenuationDistance;
  bool TwoSidedRefraction = true;
  int TwoSidedMethod = TwoSidedBlendedNormals;
  int InteriorMethod = InteriorSinglePass;
  int NumberOfCracks = 2;
  int CrackSeed = 1;
  double CrackIntensity = 1.0;
  double CrackReflection = 0.4;
  int CrackClipping = DepthInterval;
  bool CracksPerturbRefraction = false;
  int DebugView = DebugOff;
  bool WarnWithoutEnvironment = true;
  int NumberOfAirPlanes = 19;
  int AirSeed = 1;
  double Milkiness = 0.5;
  double MilkyCoreRadius = 0.0;
  double Roughness = 0.0;
  double BumpStrength = 0.08;
  double BumpScale = 0.15;
  vtkSmartPointer<vtkTexture> NormalMap;
  vtkIdType NumberOfCrackDraws = 0;
  bool Glistening = false;
  double SnowAmount = 0.0;
  double GlisteningScale = 0.03;
  double GlisteningIntensity = 1.0;
  double GlisteningAlignmentGain = 2.0;
  vtkSmartPointer<vtkIceGlisteningTexture> GlisteningNoise;

  std::map<const vtkOpenGLHelper*, int> ShaderVariantBuilt;
  std::unique_ptr<vtkIceSinglePassInterior> SinglePass;
  bool SinglePassPrepared = false; // during a draw

  // The renderer's environment or the built-in sky, when no pass hands a dynamic cube map.
  std::unique_ptr<vtkIceStaticEnvironment> Environment;
  vtkTextureObject* ActiveEnvironmentObject = nullptr; // what the shader samples, if bound here
  // What it samples where the surface is rough (Roughness), bound during a draw.
  std::unique_ptr<vtkIcePrefilteredEnvironment> Prefiltered;
  vtkTextureObject* ActiveRoughEnvironment = nullptr;

  // The bounds the look is placed in (PlacementBounds, else the prepared input's), and their
  // largest extent.
  void GetLookBounds(double bounds[6]);
  double InputExtent();
  bool EmptyInputIsPiece() override;
  double PlacementBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };

  std::unique_ptr<vtkIceInterior> Interior; // cracks and air

  // What InputPrepared and UsableCrackClipping found about the current input.
  bool InputFlat = false;
  bool WarnedOpenInput = false;
  // A setting that cannot show is said once per mapper (WarnSettingsWithoutEffect).
  void WarnSettingsWithoutEffect(bool withPass);
  bool WarnedSnowWithoutGlistening = false;
  bool WarnedAbsorptionWithoutPass = false;
  bool WarnedCoreWithPaperPasses = false;
  // How the input encloses a volume (vtkIceSurfaceCheck::CheckClosure), found when Geometry
  // clipping or culling first needs it: its open edges, whether it is closed and faces outward.
  void CheckInputClosure();
  vtkIdType InputOpenEdges = -1; // -1: not checked yet
  bool InputDrawnBefore = false; // in the main scene, since the input changed
  bool InputClosedOutward = false;

  bool CullHiddenBackfaces = true;
  bool LastDrawCulledBackfaces = false;
  std::unique_ptr<vtkIceBackfaceCulling> Culling; // during a draw

  // Whether the cracks or air were drawn in a vtkIcePass frame since the mapper last drew
  // without one (see vtkIceWorldSpaceMapper::ForgetRenderPasses).
  bool HelpersSawPass = false;

private:
  vtkIceMapper(const vtkIceMapper&) = delete;
  void operator=(const vtkIceMapper&) = delete;
};

#endif
