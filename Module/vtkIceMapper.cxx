#include "vtkIceMapper.h"

#include "vtkIceAirMapper.h"
#include "vtkIceAirTextureSource.h"
#include "vtkIceBumpFS.h"
#include "vtkIceCrackMapper.h"
#include "vtkIceCrackSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceDebugDepthFS.h"
#include "vtkIceGlistening.h"
#include "vtkIceGlisteningTexture.h"
#include "vtkIceNoise.h"
#include "vtkIceOptics.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSurfaceCheck.h"
#include "vtkIceSurfaceFS.h"
#include "vtkIceSurfaceVS.h"
#include "vtkIceNormalMapFS.h"
#include "vtkIceTwoSidedFS.h"
#include "vtkIceValueNoise.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkClipPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSelectEnclosedPoints.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtk_glew.h"

#include <algorithm>
#include <numeric>
#include <vector>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceMapper);

namespace
{
enum ShaderParts
{
  TwoSidedPart = 1,
  DepthDebugPart = 2,
  BumpPart = 4,
  NormalMapPart = 8,
  GlisteningPart = 16
};

enum class Overlay
{
  Add,   // highlights: additive
  Blend, // bubbles: alpha blending
  Opaque // debug colours
};

// Draws `mapper` with `actor` over the rendered scene: the fragment shaders test their fragments
// at the ice's front depth, so the depth test keeps them where the ice is seen; no depth writes.
void DrawOverScene(vtkRenderer* ren, vtkMapper* mapper, vtkActor* actor, Overlay overlay, bool depthTest)
{
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  state->vtkglDisable(GL_CULL_FACE);
  if (overlay == Overlay::Opaque)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    if (overlay == Overlay::Add)
    {
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    }
    else
    {
      state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
  }
  if (depthTest)
  {
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
  }
  else
  {
    state->vtkglDisable(GL_DEPTH_TEST);
  }
  state->vtkglDepthMask(GL_FALSE);
  mapper->Render(ren, actor);
}
const int GenericCrackModels = 3;

// Random placement `index` of `sequence` inside `bounds`: a random orientation (axis uniform on
// the sphere), the centre within the middle `spread` fraction of the bounds, a uniform scale
// between minScale and maxScale times the largest extent. Writes the centre.
vtkSmartPointer<vtkTransform> RandomPlacement(std::uint32_t sequence, int index,
  const double bounds[6], double spread, double minScale, double maxScale, double center[3])
{
  double u[7];
  for (int k = 0; k < 7; ++k)
  {
    u[k] = vtkIceNoise::Uniform(sequence, static_cast<std::uint32_t>(7 * index + k));
  }
  const double z = 2.0 * u[0] - 1.0;
  const double phi = 2.0 * vtkMath::Pi() * u[1];
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double extent = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double size = bounds[2 * c + 1] - bounds[2 * c];
    center[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]) + spread * (u[3 + c] - 0.5) * size;
    extent = std::max(extent, size);
  }
  auto placement = vtkSmartPointer<vtkTransform>::New();
  placement->Translate(center);
  placement->RotateWXYZ(360.0 * u[2], r * std::cos(phi), r * std::sin(phi), z);
  const double scale = extent * (minScale + (maxScale - minScale) * u[6]);
  placement->Scale(scale, scale, scale);
  return placement;
}

// Clamps `value` to [low, high] into `member` as vtkSetClampMacro does, but refuses NaN (which
// the macro would store: every comparison with NaN is false) with a warning naming the
// parameter. Returns whether `member` changed.
bool SetClamped(
  vtkObject* self, const char* name, double value, double low, double high, double& member)
{
  if (std::isnan(value))
  {
    vtkWarningWithObjectMacro(
      self, << "Set" << name << "(NaN) ignored: " << name << " stays " << member << ".");
    return false;
  }
  const double clamped = std::min(std::max(value, low), high);
  if (clamped == member)
  {
    return false;
  }
  member = clamped;
  return true;
}

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

// The crack surfaces of one ice mapper: their geometry (cached) and what draws it.
class vtkIceMapper::vtkCracks
{
public:
  vtkNew<vtkIceCrackMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkPolyData> Geometry;

  vtkCracks()
  {
    vtkProperty* property = this->Actor->GetProperty();
    property->SetAmbient(0.0);
    property->SetDiffuse(0.0);
    property->SetSpecular(1.0);
    property->SetSpecularPower(40.0);
    property->SetSpecularColor(1.0, 1.0, 1.0);
    this->Actor->SetMapper(this->Mapper);
    this->Mapper->ScalarVisibilityOff();
  }

  vtkPolyData* Update(vtkPolyData* ice, int number, int seed, int clipping)
  {
    const bool current = this->Geometry && ice == this->Ice && ice->GetMTime() == this->IceTime &&
      number == this->Number && seed == this->Seed && clipping == this->Clipping;
    if (!current)
    {
      this->Ice = ice;
      this->IceTime = ice->GetMTime();
      this->Number = number;
      this->Seed = seed;
      this->Clipping = clipping;
      this->Geometry = Build(ice, number, seed, clipping);
      this->Mapper->SetInputData(this->Geometry);
    }
    return this->Geometry;
  }

private:
  vtkPolyData* Ice = nullptr;
  vtkMTimeType IceTime = 0;
  int Number = -1;
  int Seed = 0;
  int Clipping = -1;

  static vtkSmartPointer<vtkPolyData> Build(vtkPolyData* ice, int number, int seed, int clipping)
  {
    double bounds[6];
    ice->GetBounds(bounds);

    vtkSmartPointer<vtkPolyData> models[GenericCrackModels];
    for (int m = 0; m < GenericCrackModels; ++m)
    {
      vtkNew<vtkIceCrackSource> source;
      source->SetSeed(GenericCrackModels * seed + m);
      source->Update();
      models[m] = source->GetOutput();
    }

    vtkNew<vtkAppendPolyData> append;
    const std::uint32_t sequence = static_cast<std::uint32_t>(seed) * 7919U + 1U;
    for (int i = 0; i < number; ++i)
    {
      // Near the centre, large enough to span most of the ice.
      double center[3];
      vtkNew<vtkTransformPolyDataFilter> place;
      place->SetInputData(models[i % GenericCrackModels]);
      place->SetTransform(RandomPlacement(sequence, i, bounds, 0.3, 0.48, 0.72, center));
      append->AddInputConnection(place->GetOutputPort());
    }
    if (number == 0)
    {
      return vtkSmartPointer<vtkPolyData>::New();
    }
    append->Update();
    if (clipping != vtkIceMapper::Geometry)
    {
      return append->GetOutput();
    }
    // Signed distance to the ice surface, negative inside. The sign comes from ray casting
    // (vtkSelectEnclosedPoints): vtkImplicitPolyDataDistance's own sign is wrong for some points
    // near edges of concave meshes. The clip interpolates the zero crossing along crack edges.
    vtkPolyData* cracks = append->GetOutput();
    vtkNew<vtkSelectEnclosedPoints> enclosed;
    enclosed->SetInputData(cracks);
    enclosed->SetSurfaceData(ice);
    enclosed->Update();
    vtkNew<vtkImplicitPolyDataDistance> distance;
    distance->SetInput(ice);
    vtkNew<vtkDoubleArray> signedDistance;
    signedDistance->SetName("vtkIceCrackDistance");
    signedDistance->SetNumberOfTuples(cracks->GetNumberOfPoints());
    for (vtkIdType i = 0; i < cracks->GetNumberOfPoints(); ++i)
    {
      const double magnitude = std::abs(distance->EvaluateFunction(cracks->GetPoint(i)));
      signedDistance->SetValue(i, enclosed->IsInside(i) ? -magnitude : magnitude);
    }
    vtkNew<vtkPolyData> measured;
    measured->ShallowCopy(cracks);
    measured->GetPointData()->SetScalars(signedDistance);
    vtkNew<vtkClipPolyData> clip;
    clip->SetInputData(measured);
    clip->InsideOutOn(); // keep negative distances: inside the ice
    clip->SetValue(0.0);
    clip->Update();
    clip->GetOutput()->GetPointData()->RemoveArray("vtkIceCrackDistance");
    return clip->GetOutput();
  }
};

// The air planes of one ice mapper: their geometry (cached), back-to-front order and what draws
// them.
class vtkIceMapper::vtkAir
{
public:
  vtkNew<vtkIceAirMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkPolyData> Geometry;

  vtkAir()
  {
    this->Actor->GetProperty()->LightingOff();
    this->Actor->SetMapper(this->Mapper);
    this->Mapper->ScalarVisibilityOff();
  }

  vtkPolyData* Update(vtkPolyData* ice, int number, int seed)
  {
    const bool current = this->Geometry && ice == this->Ice && ice->GetMTime() == this->IceTime &&
      number == this->Number && seed == this->Seed;
    if (!current)
    {
      this->Ice = ice;
      this->IceTime = ice->GetMTime();
      this->Number = number;
      this->Seed = seed;
      this->Build(ice, number, seed);
      this->Mapper->SetInputData(this->Geometry);
    }
    if (!this->Texture || seed != this->TextureSeed)
    {
      vtkNew<vtkIceAirTextureSource> images;
      images->SetSeed(seed);
      images->Update();
      this->Texture = vtkSmartPointer<vtkTexture>::New();
      this->Texture->SetInputData(images->GetOutput());
      this->Texture->InterpolateOn();
      this->Texture->MipmapOn();
      this->Texture->RepeatOff();
      this->Texture->EdgeClampOn();
      this->Texture->SetColorModeToDirectScalars();
      this->Mapper->SetAirTexture(this->Texture);
      this->TextureSeed = seed;
    }
    return this->Geometry;
  }

  // Reorders the planes back to front as seen from `eye` (model coordinates).
  void Sort(const double eye[3])
  {
    const vtkIdType n = static_cast<vtkIdType>(this->Centers.size() / 3);
    std::vector<vtkIdType> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> distance(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      distance[i] = vtkMath::Distance2BetweenPoints(&this->Centers[3 * i], eye);
    }
    std::stable_sort(order.begin(), order.end(),
      [&distance](vtkIdType a, vtkIdType b) { return distance[a] > distance[b]; });
    if (order == this->Order)
    {
      return;
    }
    this->Order = order;
    vtkNew<vtkCellArray> quads;
    for (vtkIdType i : order)
    {
      const vtkIdType quad[4] = { 4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3 };
      quads->InsertNextCell(4, quad);
    }
    this->Geometry->SetPolys(quads);
  }

private:
  vtkPolyData* Ice = nullptr;
  vtkMTimeType IceTime = 0;
  int Number = -1;
  int Seed = 0;
  int TextureSeed = 0;
  vtkSmartPointer<vtkTexture> Texture;
  std::vector<double> Centers;
  std::vector<vtkIdType> Order;

  void Build(vtkPolyData* ice, int number, int seed)
  {
    double bounds[6];
    ice->GetBounds(bounds);
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> uv;
    uv->SetName("vtkIceAirUV");
    uv->SetNumberOfComponents(2);
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    this->Centers.clear();
    this->Order.clear();
    const std::uint32_t sequence = static_cast<std::uint32_t>(seed) * 6151U + 7U;
    for (int i = 0; i < number; ++i)
    {
      // In the middle 40 % of the bounds, half-sizes of 0.2 to 0.4 of the largest extent.
      double center[3];
      vtkSmartPointer<vtkTransform> place =
        RandomPlacement(sequence, i, bounds, 0.4, 0.2, 0.4, center);
      // Each plane shows one tile of the 2 x 2 atlas, inset against bleeding.
      const double tileU = 0.5 * (i % 2);
      const double tileV = 0.5 * ((i / 2) % 2);
      const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
      for (const auto& corner : corners)
      {
        double p[3] = { corner[0], corner[1], 0.0 };
        place->TransformPoint(p, p);
        points->InsertNextPoint(p);
        uv->InsertNextTuple2(tileU + 0.01 + 0.24 * (corner[0] + 1.0), tileV + 0.01 + 0.24 * (corner[1] + 1.0));
        double n[3] = { 0.0, 0.0, 1.0 };
        place->TransformNormal(n, n);
        vtkMath::Normalize(n);
        normals->InsertNextTuple(n);
      }
      this->Centers.insert(this->Centers.end(), center, center + 3);
    }
    this->Geometry = vtkSmartPointer<vtkPolyData>::New();
    this->Geometry->SetPoints(points);
    this->Geometry->GetPointData()->AddArray(uv);
    this->Geometry->GetPointData()->SetNormals(normals);
    const double far[3] = { 0.0, 0.0, 0.0 };
    this->Sort(far);
  }
};

//------------------------------------------------------------------------------
vtkIceMapper::vtkIceMapper()
  : RefractionRatio(1.0003 / 1.3091)
  , FresnelPower(3.0)
  , BackNormalWeight(0.33)
  , IceColor{ 1.0, 1.0, 1.0 }
  , Cracks(new vtkCracks)
  , Air(new vtkAir)
{
}

//------------------------------------------------------------------------------
vtkIceMapper::~vtkIceMapper()
{
  delete this->Cracks;
  delete this->Air;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetNormalMap(vtkTexture* texture)
{
  if (this->NormalMap != texture)
  {
    this->NormalMap = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceMapper::GetNormalMap()
{
  return this->NormalMap;
}

//------------------------------------------------------------------------------
double vtkIceMapper::InputExtent()
{
  double bounds[6];
  this->PreparedInput->GetBounds(bounds);
  return std::max(
    { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-12 });
}

//------------------------------------------------------------------------------
// The clamped floating-point properties: clamped to the ranges their header declares, NaN
// refused with a warning (SetClamped).
#define vtkIceClampedSetter(name)                                                                 \
  void vtkIceMapper::Set##name(double value)                                                      \
  {                                                                                               \
    if (SetClamped(this, #name, value, this->Get##name##MinValue(), this->Get##name##MaxValue(), \
          this->name))                                                                            \
    {                                                                                             \
      this->Modified();                                                                           \
    }                                                                                             \
  }
vtkIceClampedSetter(RefractionRatio)
vtkIceClampedSetter(FresnelPower)
vtkIceClampedSetter(BackNormalWeight)
vtkIceClampedSetter(CrackIntensity)
vtkIceClampedSetter(Milkiness)
vtkIceClampedSetter(BumpStrength)
vtkIceClampedSetter(BumpScale)
vtkIceClampedSetter(GlisteningScale)
vtkIceClampedSetter(GlisteningIntensity)
vtkIceClampedSetter(GlisteningAlignmentGain)
vtkIceClampedSetter(SnowAmount)
#undef vtkIceClampedSetter

//------------------------------------------------------------------------------
void vtkIceMapper::SetIceColor(double red, double green, double blue)
{
  if (std::isnan(red) || std::isnan(green) || std::isnan(blue))
  {
    vtkWarningMacro(<< "SetIceColor(" << red << ", " << green << ", " << blue
                    << ") ignored: a component is NaN; IceColor stays (" << this->IceColor[0]
                    << ", " << this->IceColor[1] << ", " << this->IceColor[2] << ").");
    return;
  }
  bool changed = false;
  const double color[3] = { red, green, blue };
  for (int i = 0; i < 3; ++i)
  {
    changed = SetClamped(this, "IceColor", color[i], 0.0, 1.0, this->IceColor[i]) || changed;
  }
  if (changed)
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkIceMapper* vtkIceMapper::GetIceMapperOf(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetVisibility() ? vtkIceMapper::SafeDownCast(actor->GetMapper()) : nullptr;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetBackfaceNormalTexture(vtkTextureObject* texture)
{
  // Per-frame textures are uniforms, not pipeline changes: no Modified().
  this->BackfaceNormalTexture = texture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceMapper::GetBackfaceNormalTexture()
{
  return this->BackfaceNormalTexture;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetDepthIntervalTexture(vtkTextureObject* texture)
{
  this->DepthIntervalTexture = texture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceMapper::GetDepthIntervalTexture()
{
  return this->DepthIntervalTexture;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetDepthRange(double nearest, double farthest)
{
  this->DepthRange[0] = nearest;
  this->DepthRange[1] = farthest;
}

//------------------------------------------------------------------------------
int vtkIceMapper::ShaderVariant() const
{
  int variant = 0;
  if (this->TwoSidedRefraction && this->BackfaceNormalTexture)
  {
    variant |= TwoSidedPart;
  }
  if ((this->DebugView == DebugFrontDepth || this->DebugView == DebugBackDepth) &&
    this->DepthIntervalTexture)
  {
    variant |= DepthDebugPart;
  }
  if (this->BumpStrength > 0.0)
  {
    variant |= this->NormalMap ? NormalMapPart : BumpPart;
  }
  if (this->Glistening)
  {
    variant |= GlisteningPart;
  }
  return variant;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The superclass must always run: it also updates the light complexity.
  const bool superclassNeeds = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  auto built = this->ShaderVariantBuilt.find(&cellBO);
  const bool variantChanged =
    built != this->ShaderVariantBuilt.end() && built->second != this->ShaderVariant();
  return superclassNeeds || variantChanged;
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceMapper::SelectEnvironment(vtkRenderer* ren)
{
  vtkTexture* env = ren->GetEnvironmentTexture();
  const bool cubeMap = env && env->GetCubeMap();
  if (cubeMap && HasFaceImages(env))
  {
    return env;
  }
  if (!this->WarnedNoEnvironment)
  {
    vtkWarningMacro(<< (!env          ? "The renderer has no environment texture"
                           : !cubeMap ? "The renderer's environment texture is not a cube map"
                                      : "The renderer's environment cube map has faces without "
                                        "an image (did its reader fail?)")
                    << "; the ice reflects a built-in sky. Set a vtkTexture with CubeMapOn() "
                       "with vtkRenderer::SetEnvironmentTexture.");
    this->WarnedNoEnvironment = true;
  }
  if (!this->FallbackEnvironment)
  {
    vtkNew<vtkIceCubeMapSource> sky;
    sky->SetFaceSize(64);
    this->FallbackEnvironment = vtkSmartPointer<vtkTexture>::New();
    sky->ConfigureTexture(this->FallbackEnvironment);
  }
  return this->FallbackEnvironment;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceMapper::BindEnvironment(vtkRenderer* ren, vtkActor* act)
{
  vtkInformation* keys = act->GetPropertyKeys();
  if (keys && keys->Has(vtkIceCubeMapPass::ENVIRONMENT()))
  {
    vtkTextureObject* cubeMap =
      vtkTextureObject::SafeDownCast(keys->Get(vtkIceCubeMapPass::ENVIRONMENT()));
    cubeMap->Activate();
    return cubeMap;
  }
  this->ActiveEnvironment = this->SelectEnvironment(ren);
  this->ActiveEnvironment->Render(ren);
  return static_cast<vtkOpenGLTexture*>(this->ActiveEnvironment)->GetTextureObject();
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  this->ActiveEnvironmentObject = this->BindEnvironment(ren, act);
  if (this->NormalMap && this->BumpStrength > 0.0)
  {
    this->NormalMap->Render(ren);
  }
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  if (this->NormalMap && this->BumpStrength > 0.0)
  {
    this->NormalMap->PostRender(ren);
  }
  if (this->ActiveEnvironment)
  {
    this->ActiveEnvironment->PostRender(ren);
    this->ActiveEnvironment = nullptr;
  }
  else if (this->ActiveEnvironmentObject)
  {
    this->ActiveEnvironmentObject->Deactivate();
  }
  this->ActiveEnvironmentObject = nullptr;
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReplaceIceShaderValues(
  std::string& vs, std::string& fs, vtkRenderer* ren, vtkActor* act)
{
  using vtkIceShaderSections::InsertAfterTag;
  using vtkIceShaderSections::Get;
  const std::string optics = vtkIceOptics;
  const int variant = this->ShaderVariant();
  this->ShaderVariantBuilt[this->LastBoundBO] = variant;

  InsertAfterTag(vs, "//VTK::Normal::Dec", optics + Get(vtkIceSurfaceVS, "Dec"));
  InsertAfterTag(vs, "//VTK::Light::Impl", Get(vtkIceSurfaceVS, "Impl"));

  std::string declarations = optics + Get(vtkIceSurfaceFS, "Dec");
  if (variant & TwoSidedPart)
  {
    declarations += Get(vtkIceTwoSidedFS, "Dec");
  }
  if (variant & DepthDebugPart)
  {
    declarations += Get(vtkIceDebugDepthFS, "Dec");
  }
  if (variant & BumpPart)
  {
    declarations += Get(vtkIceValueNoise, "Dec") + Get(vtkIceBumpFS, "Dec");
  }
  if (variant & NormalMapPart)
  {
    declarations += Get(vtkIceNormalMapFS, "Dec");
  }
  if (variant & GlisteningPart)
  {
    declarations += vtkIceGlistening::Declarations();
  }
  InsertAfterTag(fs, "//VTK::Normal::Dec", declarations);
  InsertAfterTag(fs, "//VTK::Light::Impl", Get(vtkIceSurfaceFS, "Impl"));
  if (variant & TwoSidedPart)
  {
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::RefractionNormal", Get(vtkIceTwoSidedFS, "Impl"));
  }
  if (variant & DepthDebugPart)
  {
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::Debug", Get(vtkIceDebugDepthFS, "Impl"));
  }
  if (this->DrawingEdges(ren, act))
  {
    // VTK's edge code (before the lighting) weighs edge pixels by emix; the ice colour replaces
    // the lit colour, so the edges go over it here.
    vtkShaderProgram::Substitute(
      fs, "//ICEHOOK::Edges", "gl_FragData[0].rgb = mix(gl_FragData[0].rgb, edgeColor, emix);");
  }
  if (variant & (BumpPart | NormalMapPart))
  {
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::SurfaceNormal",
      Get(variant & BumpPart ? vtkIceBumpFS : vtkIceNormalMapFS, "Impl"));
  }
  if (variant & GlisteningPart)
  {
    // The light calls follow VTK's light loop (set by the superclass's GetNeedToRebuildShaders).
    const auto& lights = this->PrimitiveInfo[this->LastBoundBO];
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::Glistening",
      vtkIceGlistening::Code(
        lights.LastLightCount > 0 ? lights.LastLightComplexity : 0, lights.LastLightCount));
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetIceShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act)
{
  if (!this->ActiveEnvironmentObject)
  {
    return;
  }
  const float tint[3] = { static_cast<float>(this->IceColor[0]),
    static_cast<float>(this->IceColor[1]), static_cast<float>(this->IceColor[2]) };
  program->SetUniform3f("iceTint", tint);
  program->SetUniformf("iceRefractionRatio", static_cast<float>(this->RefractionRatio));
  program->SetUniformf("iceFresnelPower", static_cast<float>(this->FresnelPower));
  program->SetUniformi("iceEnvironment", this->ActiveEnvironmentObject->GetTextureUnit());

  const int variant = this->ShaderVariant();
  if (variant & TwoSidedPart)
  {
    this->BindScreenTexture(program, ren, this->BackfaceNormalTexture, "iceBackNormals");
    program->SetUniformf("iceBackNormalWeight", static_cast<float>(this->BackNormalWeight));
  }
  if (variant & DepthDebugPart)
  {
    this->BindScreenTexture(program, ren, this->DepthIntervalTexture, "iceDepthInterval");
    const float range[2] = { static_cast<float>(this->DepthRange[0]),
      static_cast<float>(this->DepthRange[1]) };
    program->SetUniform2f("iceDepthRange", range);
    program->SetUniformi("iceDebugChannel", this->DebugView == DebugFrontDepth ? 0 : 1);
  }
  if (variant & (BumpPart | NormalMapPart))
  {
    program->SetUniformf("iceBumpStrength", static_cast<float>(this->BumpStrength));
    program->SetUniformf(
      "iceBumpFrequency", static_cast<float>(1.0 / (this->BumpScale * this->InputExtent())));
  }
  if (variant & NormalMapPart)
  {
    program->SetUniformi("iceNormalMap", this->NormalMap->GetTextureUnit());
  }
  if (variant & GlisteningPart)
  {
    if (!this->GlisteningNoise)
    {
      this->GlisteningNoise = vtkSmartPointer<vtkIceGlisteningTexture>::New();
    }
    vtkTextureObject* noise = this->GlisteningNoise->GetTextureObject(
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()));
    noise->Activate();
    // Deactivated after the draw with the screen textures.
    if (std::find(this->BoundScreenTextures.begin(), this->BoundScreenTextures.end(), noise) ==
      this->BoundScreenTextures.end())
    {
      this->BoundScreenTextures.push_back(noise);
    }
    vtkIceGlistening::Parameters parameters;
    parameters.Scale = this->GlisteningScale;
    parameters.Intensity = this->GlisteningIntensity;
    parameters.AlignmentGain = this->GlisteningAlignmentGain;
    parameters.SnowAmount = this->SnowAmount;
    parameters.NoiseTextureUnit = noise->GetTextureUnit();
    vtkIceGlistening::SetUniforms(program, ren, act, parameters);
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkIceMapper::GetCrackGeometry()
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    return nullptr;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (!this->PrepareInput(input))
  {
    return nullptr;
  }
  // Ice without volume has no inside to hold cracks.
  const int cracks = this->InputFlat ? 0 : this->NumberOfCracks;
  return this->Cracks->Update(this->PreparedInput, cracks, this->CrackSeed,
    cracks > 0 ? this->UsableCrackClipping() : DepthInterval);
}

//------------------------------------------------------------------------------
void vtkIceMapper::InputPrepared()
{
  this->Superclass::InputPrepared();
  double thickness;
  double size;
  vtkIceSurfaceCheck::Extents(this->PreparedInput->GetPoints(), thickness, size);
  this->InputFlat = vtkIceSurfaceCheck::IsFlat(thickness, size);
  this->InputOpenEdges = -1;
  this->WarnedOpenInput = false;
  if (this->InputFlat)
  {
    vtkWarningMacro(<< "Input is flat (thickness " << thickness << " for a size of " << size
                    << "): ice without volume has no inside; it is drawn as a surface, without "
                       "cracks.");
  }
}

//------------------------------------------------------------------------------
int vtkIceMapper::UsableCrackClipping()
{
  if (this->CrackClipping != Geometry)
  {
    return this->CrackClipping;
  }
  if (this->InputOpenEdges < 0)
  {
    this->InputOpenEdges = vtkIceSurfaceCheck::CountOpenEdges(this->PreparedInput);
  }
  if (this->InputOpenEdges == 0)
  {
    return Geometry;
  }
  if (!this->WarnedOpenInput)
  {
    vtkWarningMacro(<< "Input is not a closed surface (" << this->InputOpenEdges
                    << " open edges): Geometry crack clipping needs an inside; its cracks are "
                       "clipped to the depth interval instead.");
    this->WarnedOpenInput = true;
  }
  return DepthInterval;
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderCracks(vtkRenderer* ren, vtkActor* actor, bool overlay)
{
  const bool debugCracks =
    this->DebugView == DebugCracksUnclipped || this->DebugView == DebugCracksClipped;
  const bool otherDebug = this->DebugView == DebugFrontDepth ||
    this->DebugView == DebugBackDepth || this->DebugView == DebugAir;
  if (otherDebug || (!overlay && (!this->CracksPerturbRefraction || debugCracks)))
  {
    return;
  }
  vtkPolyData* geometry = this->GetCrackGeometry();
  if (!geometry || geometry->GetNumberOfPolys() == 0 || !this->DepthIntervalTexture)
  {
    return;
  }
  vtkIceCrackMapper* mapper = this->Cracks->Mapper;
  const bool unclipped = this->DebugView == DebugCracksUnclipped;
  mapper->SetDepthIntervalTexture(this->DepthIntervalTexture);
  mapper->SetClipToInterval(this->UsableCrackClipping() == DepthInterval && !unclipped);
  mapper->SetDebugColor(debugCracks);
  mapper->SetIntensity(this->CrackIntensity);
  mapper->SetBumpFrequency(8.0 / this->InputExtent());
  vtkActor* crackActor = this->Cracks->Actor;
  crackActor->SetUserMatrix(actor->GetMatrix());
  // Share the ice actor's keys: render passes that hook the ice hook its cracks too.
  crackActor->SetPropertyKeys(actor->GetPropertyKeys());
  if (overlay)
  {
    DrawOverScene(ren, mapper, crackActor, debugCracks ? Overlay::Opaque : Overlay::Add, !unclipped);
  }
  else
  {
    vtkOpenGLState* state =
      static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
    vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
    state->vtkglDisable(GL_CULL_FACE);
    mapper->Render(ren, crackActor);
  }
  crackActor->SetPropertyKeys(nullptr);
  // The texture belongs to the pass and lives for this frame only: holding it would keep it
  // (and its GL texture) alive after the pass is released or deleted.
  mapper->SetDepthIntervalTexture(nullptr);
  ++this->NumberOfCrackDraws;
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderAir(vtkRenderer* ren, vtkActor* actor)
{
  const bool debugAir = this->DebugView == DebugAir;
  if (this->NumberOfAirPlanes == 0 || !this->DepthIntervalTexture ||
    (this->DebugView != DebugOff && !debugAir))
  {
    return;
  }
  vtkPolyData* input = this->GetInput();
  if (!input || !this->PrepareInput(input))
  {
    return;
  }
  this->Air->Update(this->PreparedInput, this->NumberOfAirPlanes, this->AirSeed);

  // Back to front for this camera: the eye in the ice's model coordinates.
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  ren->GetActiveCamera()->GetPosition(eye);
  vtkNew<vtkMatrix4x4> worldToModel;
  vtkMatrix4x4::Invert(actor->GetMatrix(), worldToModel);
  worldToModel->MultiplyPoint(eye, eye);
  this->Air->Sort(eye);

  vtkIceAirMapper* mapper = this->Air->Mapper;
  mapper->SetDepthIntervalTexture(this->DepthIntervalTexture);
  mapper->SetMilkiness(this->Milkiness);
  mapper->SetDebugColor(debugAir);
  vtkActor* airActor = this->Air->Actor;
  airActor->SetUserMatrix(actor->GetMatrix());
  DrawOverScene(ren, mapper, airActor, debugAir ? Overlay::Opaque : Overlay::Blend, true);
  // The texture belongs to the pass and lives for this frame only (see RenderCracks).
  mapper->SetDepthIntervalTexture(nullptr);
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->FallbackEnvironment)
  {
    this->FallbackEnvironment->ReleaseGraphicsResources(win);
  }
  this->Cracks->Mapper->ReleaseGraphicsResources(win);
  this->Air->Mapper->ReleaseGraphicsResources(win);
  if (this->GlisteningNoise)
  {
    this->GlisteningNoise->ReleaseGraphicsResources(win);
  }
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkIceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RefractionRatio: " << this->RefractionRatio << "\n";
  os << indent << "FresnelPower: " << this->FresnelPower << "\n";
  os << indent << "BackNormalWeight: " << this->BackNormalWeight << "\n";
  os << indent << "TwoSidedRefraction: " << (this->TwoSidedRefraction ? "On" : "Off") << "\n";
  os << indent << "IceColor: (" << this->IceColor[0] << ", " << this->IceColor[1] << ", "
     << this->IceColor[2] << ")\n";
  os << indent << "NumberOfCracks: " << this->NumberOfCracks << "\n";
  os << indent << "CrackSeed: " << this->CrackSeed << "\n";
  os << indent << "CrackIntensity: " << this->CrackIntensity << "\n";
  os << indent << "CrackClipping: "
     << (this->CrackClipping == Geometry ? "Geometry" : "DepthInterval") << "\n";
  os << indent << "CracksPerturbRefraction: " << (this->CracksPerturbRefraction ? "On" : "Off")
     << "\n";
  os << indent << "NumberOfAirPlanes: " << this->NumberOfAirPlanes << "\n";
  os << indent << "AirSeed: " << this->AirSeed << "\n";
  os << indent << "Milkiness: " << this->Milkiness << "\n";
  os << indent << "BumpStrength: " << this->BumpStrength << "\n";
  os << indent << "BumpScale: " << this->BumpScale << "\n";
  os << indent << "NormalMap: " << this->NormalMap.Get() << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "Glistening: " << (this->Glistening ? "On" : "Off") << "\n";
  os << indent << "SnowAmount: " << this->SnowAmount << "\n";
  os << indent << "GlisteningScale: " << this->GlisteningScale << "\n";
  os << indent << "GlisteningIntensity: " << this->GlisteningIntensity << "\n";
  os << indent << "GlisteningAlignmentGain: " << this->GlisteningAlignmentGain << "\n";
}
