#include "vtkIceMapper.h"

#include "vtkIceCrackMapper.h"
#include "vtkIceCrackSource.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceDebugDepthFS.h"
#include "vtkIceNoise.h"
#include "vtkIceOptics.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSurfaceCheck.h"
#include "vtkIceSurfaceFS.h"
#include "vtkIceSurfaceVS.h"
#include "vtkIceTwoSidedFS.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
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
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkIceMapper);

namespace
{
enum ShaderParts
{
  TwoSidedPart = 1,
  DepthDebugPart = 2
};
const int GenericCrackModels = 3;

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
    const double size[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
    const double extent = std::max({ size[0], size[1], size[2] });

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
      double u[7];
      for (int k = 0; k < 7; ++k)
      {
        u[k] = vtkIceNoise::Uniform(sequence, static_cast<std::uint32_t>(7 * i + k));
      }
      // A random orientation (axis uniform on the sphere), a position near the centre and a
      // size that spans most of the ice.
      const double z = 2.0 * u[0] - 1.0;
      const double phi = 2.0 * vtkMath::Pi() * u[1];
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      vtkNew<vtkTransform> transform;
      transform->Translate(0.5 * (bounds[0] + bounds[1]) + 0.3 * (u[3] - 0.5) * size[0],
        0.5 * (bounds[2] + bounds[3]) + 0.3 * (u[4] - 0.5) * size[1],
        0.5 * (bounds[4] + bounds[5]) + 0.3 * (u[5] - 0.5) * size[2]);
      transform->RotateWXYZ(360.0 * u[2], r * std::cos(phi), r * std::sin(phi), z);
      const double scale = 0.6 * extent * (0.8 + 0.4 * u[6]);
      transform->Scale(scale, scale, scale);
      vtkNew<vtkTransformPolyDataFilter> place;
      place->SetInputData(models[i % GenericCrackModels]);
      place->SetTransform(transform);
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

//------------------------------------------------------------------------------
vtkIceMapper::vtkIceMapper()
  : RefractionRatio(1.0003 / 1.3091)
  , FresnelPower(3.0)
  , BackNormalWeight(0.33)
  , IceColor{ 1.0, 1.0, 1.0 }
  , Cracks(new vtkCracks)
{
}

//------------------------------------------------------------------------------
vtkIceMapper::~vtkIceMapper()
{
  delete this->Cracks;
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetRefractionRatio(double eta)
{
  if (SetClamped(this, "RefractionRatio", eta, this->GetRefractionRatioMinValue(),
        this->GetRefractionRatioMaxValue(), this->RefractionRatio))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetFresnelPower(double power)
{
  if (SetClamped(this, "FresnelPower", power, this->GetFresnelPowerMinValue(),
        this->GetFresnelPowerMaxValue(), this->FresnelPower))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetBackNormalWeight(double weight)
{
  if (SetClamped(this, "BackNormalWeight", weight, this->GetBackNormalWeightMinValue(),
        this->GetBackNormalWeightMaxValue(), this->BackNormalWeight))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetCrackIntensity(double intensity)
{
  if (SetClamped(this, "CrackIntensity", intensity, this->GetCrackIntensityMinValue(),
        this->GetCrackIntensityMaxValue(), this->CrackIntensity))
  {
    this->Modified();
  }
}

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
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
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
  std::string& vs, std::string& fs, vtkRenderer*, vtkActor*)
{
  using vtkIceShaderSections::AfterTag;
  using vtkIceShaderSections::Get;
  const std::string optics = vtkIceOptics;
  const int variant = this->ShaderVariant();
  this->ShaderVariantBuilt[this->LastBoundBO] = variant;

  vtkShaderProgram::Substitute(
    vs, "//VTK::Normal::Dec", AfterTag("//VTK::Normal::Dec", optics + Get(vtkIceSurfaceVS, "Dec")));
  vtkShaderProgram::Substitute(
    vs, "//VTK::Light::Impl", AfterTag("//VTK::Light::Impl", Get(vtkIceSurfaceVS, "Impl")));

  std::string declarations = optics + Get(vtkIceSurfaceFS, "Dec");
  if (variant & TwoSidedPart)
  {
    declarations += Get(vtkIceTwoSidedFS, "Dec");
  }
  if (variant & DepthDebugPart)
  {
    declarations += Get(vtkIceDebugDepthFS, "Dec");
  }
  vtkShaderProgram::Substitute(fs, "//VTK::Normal::Dec", AfterTag("//VTK::Normal::Dec", declarations));
  vtkShaderProgram::Substitute(
    fs, "//VTK::Light::Impl", AfterTag("//VTK::Light::Impl", Get(vtkIceSurfaceFS, "Impl")));
  if (variant & TwoSidedPart)
  {
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::RefractionNormal", Get(vtkIceTwoSidedFS, "Impl"));
  }
  if (variant & DepthDebugPart)
  {
    vtkShaderProgram::Substitute(fs, "//ICEHOOK::Debug", Get(vtkIceDebugDepthFS, "Impl"));
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor*)
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
  const bool debugDepth = this->DebugView == DebugFrontDepth || this->DebugView == DebugBackDepth;
  if (debugDepth || (!overlay && (!this->CracksPerturbRefraction || debugCracks)))
  {
    return;
  }
  vtkPolyData* geometry = this->GetCrackGeometry();
  if (!geometry || geometry->GetNumberOfPolys() == 0 || !this->DepthIntervalTexture)
  {
    return;
  }
  double bounds[6];
  this->PreparedInput->GetBounds(bounds);
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });

  vtkIceCrackMapper* mapper = this->Cracks->Mapper;
  const bool unclipped = this->DebugView == DebugCracksUnclipped;
  mapper->SetDepthIntervalTexture(this->DepthIntervalTexture);
  mapper->SetClipToInterval(this->UsableCrackClipping() == DepthInterval && !unclipped);
  mapper->SetDebugColor(debugCracks);
  mapper->SetIntensity(this->CrackIntensity);
  mapper->SetBumpFrequency(8.0 / std::max(extent, 1e-12));
  vtkActor* crackActor = this->Cracks->Actor;
  crackActor->SetUserMatrix(actor->GetMatrix());
  // Share the ice actor's keys: render passes that hook the ice hook its cracks too.
  crackActor->SetPropertyKeys(actor->GetPropertyKeys());

  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  state->vtkglDisable(GL_CULL_FACE);
  if (overlay)
  {
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
    if (debugCracks)
    {
      state->vtkglDisable(GL_BLEND);
    }
    else
    {
      // Highlights add light over the ice.
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    }
    if (unclipped)
    {
      state->vtkglDisable(GL_DEPTH_TEST);
    }
    else
    {
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_LEQUAL);
    }
    state->vtkglDepthMask(GL_FALSE);
    mapper->Render(ren, crackActor);
  }
  else
  {
    mapper->Render(ren, crackActor);
  }
  crackActor->SetPropertyKeys(nullptr);
  // The texture belongs to the pass and lives for this frame only: holding it would keep it
  // (and its GL texture) alive after the pass is released or deleted.
  mapper->SetDepthIntervalTexture(nullptr);
  ++this->NumberOfCrackDraws;
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->FallbackEnvironment)
  {
    this->FallbackEnvironment->ReleaseGraphicsResources(win);
  }
  this->Cracks->Mapper->ReleaseGraphicsResources(win);
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
  os << indent << "DebugView: " << this->DebugView << "\n";
}
