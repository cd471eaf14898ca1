#include "vtkIceMapper.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceOptics.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSurfaceFS.h"
#include "vtkIceSurfaceVS.h"
#include "vtkIceTwoSidedFS.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkOpenGLTexture.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cmath>

vtkStandardNewMacro(vtkIceMapper);

namespace
{
const char* const IceNormalArray = "vtkIceNormals";

bool HasOnlyFinitePoints(vtkPoints* points)
{
  vtkDataArray* data = points->GetData();
  const vtkIdType n = data->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(data->GetComponent(i / 3, static_cast<int>(i % 3))))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkIceMapper::vtkIceMapper()
  : RefractionRatio(1.0003 / 1.3091)
  , FresnelPower(3.0)
  , BackNormalWeight(0.33)
  , IceColor{ 1.0, 1.0, 1.0 }
{
  this->MapDataArrayToVertexAttribute(
    "iceNormalMC", IceNormalArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkIceMapper::~vtkIceMapper() = default;

//------------------------------------------------------------------------------
bool vtkIceMapper::PrepareInput(vtkPolyData* input)
{
  if (input == this->PreparedSource && input->GetMTime() == this->PreparedInputTime)
  {
    return this->PreparedValid;
  }
  this->PreparedSource = input;
  this->PreparedInputTime = input->GetMTime();
  this->PreparedValid = false;
  this->PreparedInput = nullptr;

  const vtkIdType surfaces = input->GetNumberOfPolys() + input->GetNumberOfStrips();
  if (input->GetNumberOfPoints() == 0 || surfaces == 0)
  {
    vtkErrorMacro(<< "Input has no polygons to render as ice (" << input->GetNumberOfPoints()
                  << " points, " << input->GetNumberOfLines() << " lines, "
                  << input->GetNumberOfVerts() << " vertices); it is not drawn.");
    return false;
  }
  if (!HasOnlyFinitePoints(input->GetPoints()))
  {
    vtkErrorMacro(<< "Input has NaN or infinite point coordinates; it is not drawn as ice.");
    return false;
  }

  vtkDataArray* normals = input->GetPointData()->GetNormals();
  vtkSmartPointer<vtkDataArray> iceNormals;
  this->PreparedInput = vtkSmartPointer<vtkPolyData>::New();
  if (normals && normals->GetNumberOfComponents() == 3)
  {
    this->PreparedInput->ShallowCopy(input);
    iceNormals.TakeReference(normals->NewInstance());
    iceNormals->ShallowCopy(normals);
  }
  else
  {
    vtkNew<vtkPolyDataNormals> computeNormals;
    computeNormals->SetInputData(input);
    computeNormals->SplittingOff();
    computeNormals->ConsistencyOn();
    computeNormals->ComputeCellNormalsOff();
    computeNormals->Update();
    this->PreparedInput->ShallowCopy(computeNormals->GetOutput());
    iceNormals = this->PreparedInput->GetPointData()->GetNormals();
  }
  iceNormals->SetName(IceNormalArray);
  this->PreparedInput->GetPointData()->AddArray(iceNormals);
  this->PreparedValid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    vtkErrorMacro(<< "No input.");
    return;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (!this->PrepareInput(input))
  {
    return;
  }
  this->Superclass::RenderPiece(ren, act);
}

//------------------------------------------------------------------------------
double* vtkIceMapper::GetBounds()
{
  double* bounds = this->Superclass::GetBounds();
  if (vtkPolyData* input = this->GetInput())
  {
    this->PrepareInput(input);
  }
  return bounds;
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceMapper::SelectEnvironment(vtkRenderer* ren)
{
  vtkTexture* env = ren->GetEnvironmentTexture();
  if (env && env->GetCubeMap())
  {
    return env;
  }
  if (!this->WarnedNoEnvironment)
  {
    vtkWarningMacro(<< (env ? "The renderer's environment texture is not a cube map"
                            : "The renderer has no environment texture")
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
vtkIceMapper* vtkIceMapper::GetIceMapperOf(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetVisibility() ? vtkIceMapper::SafeDownCast(actor->GetMapper()) : nullptr;
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
  // Draw the prepared copy (input plus ice normals) instead of the raw input.
  this->CurrentInput = this->PreparedInput;
  this->ActiveEnvironmentObject = this->BindEnvironment(ren, act);
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkIceMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  if (this->BackfaceNormalTexture)
  {
    this->BackfaceNormalTexture->Deactivate();
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
void vtkIceMapper::SetBackfaceNormalTexture(vtkTextureObject* texture)
{
  // Not Modified(): the texture changes every frame and is a uniform, not a pipeline change.
  this->BackfaceNormalTexture = texture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceMapper::GetBackfaceNormalTexture()
{
  return this->BackfaceNormalTexture;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::UseTwoSidedShader() const
{
  return this->TwoSidedRefraction && this->BackfaceNormalTexture != nullptr;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The superclass must always run: it also updates the light complexity.
  const bool superclassNeeds = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  auto built = this->TwoSidedShaderBuilt.find(&cellBO);
  const bool variantChanged =
    built != this->TwoSidedShaderBuilt.end() && built->second != this->UseTwoSidedShader();
  return superclassNeeds || variantChanged;
}

//------------------------------------------------------------------------------
bool vtkIceMapper::IsSurfaceHelper(const vtkOpenGLHelper* helper) const
{
  return helper == &this->Primitives[PrimitiveTris] ||
    helper == &this->Primitives[PrimitiveTriStrips];
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->IsSurfaceHelper(this->LastBoundBO))
  {
    const std::string optics = vtkIceOptics;
    const std::string vs = vtkIceSurfaceVS;
    const std::string fs = vtkIceSurfaceFS;
    const bool twoSided = this->UseTwoSidedShader();
    this->TwoSidedShaderBuilt[this->LastBoundBO] = twoSided;
    std::string vsSource = shaders[vtkShader::Vertex]->GetSource();
    std::string fsSource = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(vsSource, "//VTK::Normal::Dec",
      vtkIceShaderSections::AfterTag(
        "//VTK::Normal::Dec", optics + vtkIceShaderSections::Get(vs, "Dec")));
    vtkShaderProgram::Substitute(vsSource, "//VTK::Light::Impl",
      vtkIceShaderSections::AfterTag("//VTK::Light::Impl", vtkIceShaderSections::Get(vs, "Impl")));
    vtkShaderProgram::Substitute(fsSource, "//VTK::Normal::Dec",
      vtkIceShaderSections::AfterTag(
        "//VTK::Normal::Dec", optics + vtkIceShaderSections::Get(fs, "Dec")));
    vtkShaderProgram::Substitute(fsSource, "//VTK::Light::Impl",
      vtkIceShaderSections::AfterTag("//VTK::Light::Impl", vtkIceShaderSections::Get(fs, "Impl")));
    if (twoSided)
    {
      const std::string twoSidedCode = vtkIceTwoSidedFS;
      vtkShaderProgram::Substitute(fsSource, "//VTK::Normal::Dec",
        vtkIceShaderSections::AfterTag(
          "//VTK::Normal::Dec", vtkIceShaderSections::Get(twoSidedCode, "Dec")));
      vtkShaderProgram::Substitute(fsSource, "//ICEHOOK::RefractionNormal",
        vtkIceShaderSections::Get(twoSidedCode, "Impl"));
    }
    shaders[vtkShader::Vertex]->SetSource(vsSource);
    shaders[vtkShader::Fragment]->SetSource(fsSource);
  }
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkIceMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  if (!program || !this->IsSurfaceHelper(&cellBO) || !this->ActiveEnvironmentObject)
  {
    return;
  }

  // Model to world, including the inverse of the VBO's coordinate shift and scale. Matrices are
  // kept transposed, as VTK uploads them.
  vtkNew<vtkMatrix4x4> mcwc;
  vtkNew<vtkMatrix3x3> normalMCWC;
  vtkOpenGLVertexBufferObject* vertices = this->VBOs->GetVBO("vertexMC");
  if (vertices && vertices->GetCoordShiftAndScaleEnabled())
  {
    mcwc->DeepCopy(this->VBOShiftScale);
  }
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* actorMCWC;
    vtkMatrix3x3* actorNormals;
    static_cast<vtkOpenGLActor*>(act)->GetKeyMatrices(actorMCWC, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, actorMCWC, mcwc);
    normalMCWC->DeepCopy(actorNormals);
  }
  program->SetUniformMatrix("iceMCWCMatrix", mcwc);
  program->SetUniformMatrix("iceNormalMCWCMatrix", normalMCWC);

  double* eye = ren->GetActiveCamera()->GetPosition();
  const float cameraWC[3] = { static_cast<float>(eye[0]), static_cast<float>(eye[1]),
    static_cast<float>(eye[2]) };
  const float tint[3] = { static_cast<float>(this->IceColor[0]),
    static_cast<float>(this->IceColor[1]), static_cast<float>(this->IceColor[2]) };
  program->SetUniform3f("iceCameraWC", cameraWC);
  program->SetUniform3f("iceTint", tint);
  program->SetUniformf("iceRefractionRatio", static_cast<float>(this->RefractionRatio));
  program->SetUniformf("iceFresnelPower", static_cast<float>(this->FresnelPower));
  program->SetUniformi("iceEnvironment", this->ActiveEnvironmentObject->GetTextureUnit());

  if (this->UseTwoSidedShader() && program->IsUniformUsed("iceBackNormals"))
  {
    // The back-normal texture covers the renderer's viewport, which starts at the current GL
    // viewport's origin in whatever framebuffer this draw goes to.
    int viewport[4];
    static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())
      ->GetState()
      ->vtkglGetIntegerv(GL_VIEWPORT, viewport);
    this->BackfaceNormalTexture->Activate();
    program->SetUniformi("iceBackNormals", this->BackfaceNormalTexture->GetTextureUnit());
    program->SetUniform2i("iceViewportOrigin", viewport);
    program->SetUniformf("iceBackNormalWeight", static_cast<float>(this->BackNormalWeight));
  }
}

//------------------------------------------------------------------------------
void vtkIceMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->FallbackEnvironment)
  {
    this->FallbackEnvironment->ReleaseGraphicsResources(win);
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
}
