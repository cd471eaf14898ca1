// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
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
 * inside, showing only their specular highlights) and its air: NumberOfAirPlanes planes of
 * bubble images that make the ice milky (Milkiness). InteriorMethod chooses how: once per pixel
 * along the view ray (default), or the paper's passes (their own settings, such as crack
 * clipping, on GetPaperInterior(); their drawing in VTKIce::RenderingIcePaper). BumpStrength and
 * BumpScale make the surface bumpy. Air, cracks and bumps are on by default (the paper's full
 * look); set them to 0 for clean optics.
 *
 * The look's parameters (optics, cracks, air, bumps, glistening) are on the mapper's
 * vtkIceProperty, as a vtkActor's are on its vtkProperty: mapper->GetIceProperty()->
 * SetNumberOfCracks(4); SetIceProperty shares one between mappers. How the ice is drawn
 * (two-sided refraction, the interior method, debug views) is set on the mapper.
 *
 * Any polydata with polygons works: point normals are computed when the input has none. Inputs
 * without polygons or with non-finite points are reported with an error and not drawn. Flat
 * input (all points in one plane: no volume, no inside) is drawn as a surface without cracks,
 * with one warning. Open surfaces are drawn as they are; Geometry crack clipping needs a closed
 * one and falls back to the depth interval, with one warning.
 *
 * @sa vtkIceProperty vtkIcePass vtkIcePaperInterior
 */
#ifndef vtkIceMapper_h
#define vtkIceMapper_h

#include "RenderingIceModule.h"  // for export macro
#include "vtkIcePaperInterior.h" // for GetPaperInterior
#include "vtkIceProperty.h"      // for GetIceProperty
#include "vtkIceWorldSpaceMapper.h"

#include <map>    // for members
#include <memory> // for members

class vtkActor;
class vtkIceInteriorSources;
class vtkIceInteriorTable;
class vtkIcePrefilteredEnvironment;
class vtkIceStaticEnvironment;
class vtkIceBackfaceCulling;
class vtkIceGlisteningTexture;
class vtkIceTraceTextures;
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
   * The look of the ice: its material parameters (vtkIceProperty). A mapper has its own until
   * one is set; mappers may share one, as actors share a vtkProperty. Setting nullptr gives the
   * mapper a new property with the defaults.
   */
  void SetIceProperty(vtkIceProperty* property);
  vtkIceProperty* GetIceProperty() { return this->IceProperty; }
  ///@}

  /**
   * The mapper's modification time, its ice property's included.
   */
  vtkMTimeType GetMTime() override;

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
   * How many times the light refracted into the ice is followed from face to face inside it, with
   * TwoSidedExitPoint. 1 (default): to the exit point estimated in image space, as above. Above
   * 1: the ray is traced through the ice's own triangles (a bounding volume hierarchy built on the
   * CPU when the input changes, read by the shader from texture buffers); at each hit Fresnel's
   * equations at the IndexOfRefraction split it into light refracted out and light reflected on
   * (all of it beyond the critical angle, 49.8 degrees for ice: the mirrored quadrants of a real
   * ice cube), absorbed along every segment; at the last hit what is left leaves. Non-convex ice
   * works: a ray leaving it is not followed back in. With the screen-space interior, each segment
   * after a reflection inside also crosses the milky core and meets its nearest crack, which
   * mirrors the environment there as it does seen directly, and the first such segment crosses
   * the bubbles.
   */
  vtkSetClampMacro(MaxBounces, int, 1, 16);
  vtkGetMacro(MaxBounces, int);
  ///@}

  ///@{
  /**
   * Whether the trace (MaxBounces above 1) averages more paths where one a pixel would alias.
   * Behind rounded edges the paths of neighbouring pixels part after a few reflections inside (one
   * leaves to the sky, the next to the ground), and one path a pixel draws dotted bright and dark
   * curves where a path tracer shows their average. Default on: where the traced light of a pixel
   * and its neighbours differs by more than 60 % of its own, four more paths from inside the pixel
   * are averaged in (on llvmpipe about a quarter more time for ice-render's default look;
   * Documentation/performance.md). Off: one path a pixel, as the CPU reference traces it.
   */
  vtkSetMacro(TraceAntiAliasing, bool);
  vtkGetMacro(TraceAntiAliasing, bool);
  vtkBooleanMacro(TraceAntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Whether the ice stands in its melt water, on a surface below it along the model's y axis (the
   * trace only: MaxBounces above 1). Light inside that meets the ice's base, its faces up to 6 %
   * of its height (drying between 6 % and 10 %: the water wets a rounded bottom edge), leaves into water
   * instead of air: ice and water refract nearly alike (1.31 and 1.33), so nothing reflects totally
   * there and the base shows what lies under the ice (the environment below it, the ground of a
   * dynamic cube map) instead of mirroring the ice's inside, as ice on a wet surface does. Default
   * off; ice-render turns it on where it stands the ice on the ground.
   */
  vtkSetMacro(WetBase, bool);
  vtkGetMacro(WetBase, bool);
  vtkBooleanMacro(WetBase, bool);
  ///@}

  ///@{
  /**
   * Whether the mapper draws a mirror image of ice in a horizontal mirror (the model's points
   * reflected in a plane of constant world y, as a pool of water under the ice shows it): it then
   * looks its environment up at y-mirrored world directions, so the image shows the sky where
   * the ice shows the sky, as a reflection does, not the ground below the mirror. Default off.
   */
  vtkSetMacro(MirroredEnvironment, bool);
  vtkGetMacro(MirroredEnvironment, bool);
  vtkBooleanMacro(MirroredEnvironment, bool);
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

  enum InteriorMethods
  {
    InteriorPaperPasses = 0, // the paper: a depth-interval pass, crack and air draws per ice
    InteriorScreenSpace = 1  // once per pixel, along the view ray, in a step of vtkIcePass
  };

  ///@{
  /**
   * How the cracks and air inside the ice are rendered (both need vtkIcePass).
   * InteriorScreenSpace (default): once per covered pixel by a screen-space step of vtkIcePass
   * before the scene (inside the ice's projected bounding box, from the ice's own front faces
   * and the back faces' depth, each pixel's ray intersected with the crack sheets and air planes
   * its 16 x 16 pixel tile can meet) and applied by the ice's surface: its cost follows the ice's
   * pixels, not its triangles or their overdraw. InteriorPaperPasses: the paper's method: the
   * ice's depth interval is rendered, then the air planes (blended, back to front) and the crack
   * sheets (their highlights added) are drawn over it; no crack sheets' mirror and no milky core.
   * Documentation/performance.md compares the two. DebugCracksUnclipped always uses the paper's
   * passes. The paper's passes are drawn by VTKIce::RenderingIcePaper (see vtkIcePaperInterior).
   * (Before VTK Ice 2026-12-04 a third value, 1, drew the interior in the ice's own fragment
   * shader; it is now the screen-space step's value, which draws the same look.)
   */
  vtkSetClampMacro(InteriorMethod, int, InteriorPaperPasses, InteriorScreenSpace);
  vtkGetMacro(InteriorMethod, int);
  void SetInteriorMethodToPaperPasses() { this->SetInteriorMethod(InteriorPaperPasses); }
  void SetInteriorMethodToScreenSpace() { this->SetInteriorMethod(InteriorScreenSpace); }
  ///@}

  ///@{
  /**
   * The paper's passes of this mapper, with the settings only they use (CrackClipping,
   * CracksPerturbRefraction). The mapper makes one with vtkIcePaperInterior::New() on first use
   * (the OpenGL implementation where VTKIce::RenderingIcePaper is loaded); mappers may share one.
   * Setting nullptr gives the mapper a new one with the defaults.
   */
  vtkIcePaperInterior* GetPaperInterior();
  void SetPaperInterior(vtkIcePaperInterior* interior);
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
   * ice surface with the paper interior's Geometry crack clipping. Rebuilt only when the input or
   * a crack parameter changes.
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

#ifndef __VTK_WRAP__
  ///@{
  /**
   * For vtkIcePass and its sub-passes, inside a frame; not for applications. What this ice needs
   * the pass to render for it (vtkIceFrame::Need bits), and what the frame drawing `prop` gives
   * its surface program now (vtkIceFrame::Input bits).
   */
  int GetFrameNeeds();
  int GetFrameInputs(vtkProp* prop);
  ///@}

  ///@{
  /**
   * For vtkIcePass and its sub-passes: the paper's passes' cracks of `actor` (`overlay`: over the
   * rendered scene, added; otherwise with the current state, into the back-face normals for
   * CracksPerturbRefraction) and air planes (over the scene, back to front), each drawn only when
   * the mapper's settings ask for it; and the screen-space interior's table, textures,
   * environment and look readied for its `program` until EndScreenInterior (returns the records
   * readied, or null, with nothing to end, when there is no input to draw); in between, the same
   * uniforms on its other programs.
   */
  void DrawPaperCracks(vtkRenderer* ren, vtkActor* actor, bool overlay);
  void DrawPaperAir(vtkRenderer* ren, vtkActor* actor);
  const vtkIceInteriorTable* BeginScreenInterior(
    vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program);
  void SetScreenInteriorUniforms(vtkRenderer* ren, vtkActor* actor, vtkShaderProgram* program);
  void EndScreenInterior(vtkRenderer* ren);
  ///@}
#endif

protected:
  vtkIceMapper();
  ~vtkIceMapper() override;

  int ActiveFrameInputs = 0; // during a draw

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act) override;
  void SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // The parts that use what vtkIcePass's frame gives (vtkIceFrame::Input), each compiled where
  // the frame defines it.
  void AddFrameInputParts(vtkIceShaderParts& parts);

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
  bool HasInterior() const;
  bool UsesScreenInterior() const;
  // The screen step's interior: its table and textures ready for a draw of `act` (until
  // FinishInterior; vtkIceMapperInterior.cxx).
  void PrepareInterior(vtkRenderer* ren, vtkActor* act);
  void FinishInterior(vtkRenderer* ren);
  // The environment the ice samples in a draw of `act` (a dynamic cube map is bound by the
  // frame): bound until UnbindEnvironment, its uniforms set on `program`. Called for the surface
  // (RenderPieceStart) and for the screen-space interior's step: a subclass that picks another
  // environment overrides this, so both sample the same one.
  virtual void BindEnvironment(vtkRenderer* ren, vtkActor* act);
  void SetEnvironmentUniforms(vtkShaderProgram* program);
  void UnbindEnvironment(vtkRenderer* ren);

  vtkSmartPointer<vtkIceProperty> IceProperty; // never null
  bool TwoSidedRefraction = true;
  int TwoSidedMethod = TwoSidedBlendedNormals;
  int MaxBounces = 1;
  bool TraceAntiAliasing = true;
  bool WetBase = false;
  bool MirroredEnvironment = false;
  // The triangle tree MaxBounces traces (made on first use), and whether a failed build was said.
  std::unique_ptr<vtkIceTraceTextures> Trace;
  bool WarnedTraceUnusable = false;
  bool TracesInterior() const;
  void SetTraceUniforms(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act);
  // Whether the trace meets the cracks, and the bubbles, on its segments after a reflection
  // inside (the screen-space interior shows them along the first), and what it reads of them
  // (the crack table and grid, the bubbles' noise: `active`, three at most).
  // Whether the trace carries the screen-space interior's look (cracks, bubbles, air) along its
  // path: the look of the screen-space interior, not a debug view, not flat ice.
  bool TracesInteriorLook() const;
  bool TracesCracks() const;
  bool TracesBubbles() const;
  bool TracesAir() const;
  void PrepareTraceInterior(
    vtkRenderer* ren, vtkShaderProgram* program, vtkTextureObject* active[4]);
  int InteriorMethod = InteriorScreenSpace;
  int DebugView = DebugOff;
  bool WarnWithoutEnvironment = true;
  vtkIdType NumberOfCrackDraws = 0;
  vtkSmartPointer<vtkIceGlisteningTexture> GlisteningNoise;

  std::map<const vtkOpenGLHelper*, int> ShaderVariantBuilt;
  bool LateDepthTest = false; // vtkIceLateDepthTest::Wanted at the draw
  std::unique_ptr<vtkIceInteriorTable> InteriorTable; // the screen-space interior's records
  bool InteriorPrepared = false;                      // during a draw

  // The renderer's environment or the built-in sky, when no pass hands a dynamic cube map.
  std::unique_ptr<vtkIceStaticEnvironment> Environment;
  vtkTextureObject* ActiveEnvironmentObject = nullptr; // what the shader samples, if bound here
  bool EnvironmentEncoded = false; // vtkIceStaticEnvironment::ShowsEncodedLight, at the bind
  // What it samples where the surface is rough (Roughness), bound during a draw.
  std::unique_ptr<vtkIcePrefilteredEnvironment> Prefiltered;
  vtkTextureObject* ActiveRoughEnvironment = nullptr;

  // The bounds the look is placed in (PlacementBounds, else the prepared input's), and their
  // largest extent.
  void GetLookBounds(double bounds[6]);
  double InputExtent();
  bool EmptyInputIsPiece() override;
  double PlacementBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };

  std::unique_ptr<vtkIceInteriorSources> Interior;    // cracks and air images
  vtkSmartPointer<vtkIcePaperInterior> PaperInterior; // made on first use
  // The paper's CracksPerturbRefraction, without making the paper interior.
  bool CracksPerturbRefraction() const;

  // What InputPrepared and UsableCrackClipping found about the current input.
  bool InputFlat = false;
  bool WarnedOpenInput = false;
  // A setting that cannot show is said once per mapper (WarnSettingsWithoutEffect).
  void WarnSettingsWithoutEffect(bool withPass);
  bool WarnedSnowWithoutGlistening = false;
  bool WarnedAbsorptionWithoutPass = false;
  bool WarnedCoreWithPaperPasses = false;
  bool WarnedBubblesWithPaperPasses = false;
  bool WarnedBouncesWithoutExitPoint = false;
  // How the input encloses a volume (vtkIceSurfaceCheck::CheckClosure), found when Geometry
  // clipping or culling first needs it: its open edges, whether it is closed and faces outward.
  void CheckInputClosure();
  vtkIdType InputOpenEdges = -1; // -1: not checked yet
  bool InputDrawnBefore = false; // in the main scene, since the input changed
  bool InputClosedOutward = false;
  int InputOrientation = 0; // vtkIceTriangleBVH::Intersect's orientation of the input's triangles

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
