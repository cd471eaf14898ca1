// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceWorldSpaceMapper.h"

#include "vtkIceEdgesGS.h"
#include "vtkIceShaderSections.h"
#include "vtkIceSmoothNormals.h"
#include "vtkIceSurfaceCheck.h"
#include "vtkIceWorldSpaceFS.h"
#include "vtkIceWorldSpaceVS.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <cmath>
#include <regex>

namespace
{
const char* const IceNormalArray = "vtkIceNormals";
}

//------------------------------------------------------------------------------
const char* vtkIceWorldSpaceMapper::GetPreparedNormalsName()
{
  return IceNormalArray;
}

//------------------------------------------------------------------------------
vtkIceWorldSpaceMapper::vtkIceWorldSpaceMapper()
{
  this->MapDataArrayToVertexAttribute(
    "iceNormalMC", IceNormalArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkIceWorldSpaceMapper::~vtkIceWorldSpaceMapper() = default;

//------------------------------------------------------------------------------
std::string vtkIceWorldSpaceMapper::CheckInput(vtkPolyData* input)
{
  return vtkIceSurfaceCheck::FindInputProblem(input);
}

//------------------------------------------------------------------------------
bool vtkIceWorldSpaceMapper::PrepareInput(vtkPolyData* input)
{
  if (input == this->PreparedSource && input->GetMTime() == this->PreparedInputTime)
  {
    return this->PreparedValid;
  }
  this->PreparedSource = input;
  this->PreparedInputTime = input->GetMTime();
  this->PreparedValid = false;
  this->PreparedInput = nullptr;

  if (input->GetNumberOfPoints() == 0 && this->EmptyInputIsPiece())
  {
    return false;
  }
  const std::string problem = CheckInput(input);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
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
    this->PreparedInput->ShallowCopy(vtkIceSmoothNormals(input));
    iceNormals = this->PreparedInput->GetPointData()->GetNormals();
  }
  iceNormals->SetName(IceNormalArray);
  this->PreparedInput->GetPointData()->AddArray(iceNormals);
  // Point scalars stay: with ScalarVisibility they tint the ice (vtkIceMapper). Cell data goes:
  // with cell scalars VTK 9.1 drew some triangles of the copy as garbage. The copy's attribute
  // lists are its own (ShallowCopy): the input keeps its cell data.
  this->PreparedInput->GetCellData()->Initialize();
  this->PreparedValid = true;
  this->InputPrepared();
  return true;
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
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
double* vtkIceWorldSpaceMapper::GetBounds()
{
  if (this->GetInput())
  {
    if (!this->Static)
    {
      this->Update();
    }
    // Checked before VTK computes the bounds of the cells: with a point id out of range,
    // vtkPolyData::GetCellsBounds writes outside its arrays. Broken input has no bounds.
    if (!this->PrepareInput(this->GetInput()))
    {
      vtkMath::UninitializeBounds(this->Bounds);
      return this->Bounds;
    }
  }
  return this->Superclass::GetBounds();
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkIceWorldSpaceMapper::MapScalars(
  vtkDataSet* input, double alpha, int& cellFlag)
{
  // Every MapScalars overload of VTK's mappers ends here, most with the raw input.
  if (input == this->GetInput() && this->PreparedInput)
  {
    input = this->PreparedInput;
  }
  return this->Superclass::MapScalars(input, alpha, cellFlag);
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  // Draw the prepared copy (input plus ice normals) instead of the raw input.
  this->CurrentInput = this->PreparedInput;
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  for (vtkTextureObject* texture : this->DrawTextures)
  {
    texture->Deactivate();
  }
  this->DrawTextures.clear();
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::ForgetRenderPasses()
{
  for (auto& primitive : this->PrimitiveInfo)
  {
    primitive.second.LastRenderPassInfo->Clear();
  }
}

//------------------------------------------------------------------------------
std::string vtkIceWorldSpaceMapper::PassThroughGeometryShader(const std::string& vs, vtkShader* gs)
{
  // VTK adds a geometry shader for edges (EdgeVisibility) and wide lines; its shader cache then
  // renames "VSOut" to "GSOut" in the fragment shader. Every ice varying (VTK's convention:
  // out TYPE iceNameVSOutput in the vertex shader) is copied through it per vertex, as VTK does
  // for its own; where VTK grows the triangles for their edges, the grown corners take the
  // triangle's values there instead (vtkIceEdgesGS.glsl).
  if (!gs || gs->GetSource().empty())
  {
    return std::string();
  }
  std::string source = gs->GetSource();
  // VTK 9.1-9.3 grow triangles by per-corner offsets; VTK 9.6 draws edges without growing.
  static const std::string grow = "gl_Position.xy = gl_Position.xy + offsets[i]*gl_Position.w;";
  const bool grows = source.find("offsets[i]") != std::string::npos;
  const bool grown =
    source.find(grow) != std::string::npos && source.find("//VTK::Edges::Dec") != std::string::npos;
  std::string missing = grows && !grown ? "'" + grow + "' and //VTK::Edges::Dec (geometry)" : "";
  std::string declarations;
  std::string copies;
  static const std::regex varying("out\\s+(\\w+)\\s+(ice\\w*)VSOutput\\s*;");
  for (std::sregex_iterator it(vs.begin(), vs.end(), varying), end; it != end; ++it)
  {
    const std::string type = (*it)[1];
    const std::string name = (*it)[2];
    const std::string in = name + "VSOutput";
    declarations += "in " + type + " " + in + "[];\nout " + type + " " + name + "GSOutput;\n";
    copies += name + "GSOutput = " +
      (grown ? "iceWeights.x * " + in + "[0] + iceWeights.y * " + in + "[1] + iceWeights.z * " +
            in + "[2];\n"
             : in + "[i];\n");
  }
  if (grown)
  {
    using vtkIceShaderSections::Get;
    vtkIceShaderSections::InsertAfterTag(source, "//VTK::Edges::Dec", Get(vtkIceEdgesGS, "Dec"));
    copies = Get(vtkIceEdgesGS, "Impl") + copies;
    vtkShaderProgram::Substitute(source, grow, grow + "\n" + Get(vtkIceEdgesGS, "Position"));
  }
  for (const auto& place : { std::make_pair("//VTK::Normal::Dec", &declarations),
         std::make_pair("//VTK::Normal::Impl", &copies) })
  {
    if (!vtkIceShaderSections::InsertAfterTag(source, place.first, *place.second))
    {
      missing += (missing.empty() ? "" : ", ") + std::string(place.first) + " (geometry)";
    }
  }
  gs->SetSource(source);
  return missing;
}

//------------------------------------------------------------------------------
bool vtkIceWorldSpaceMapper::IsSurfaceHelper(const vtkOpenGLHelper* helper) const
{
  return helper == &this->Primitives[PrimitiveTris] ||
    helper == &this->Primitives[PrimitiveTriStrips];
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->IsSurfaceHelper(this->LastBoundBO))
  {
    using vtkIceShaderSections::Get;
    vtkIceShaderParts parts;
    parts.VertexDeclarations = Get(vtkIceWorldSpaceVS, "Dec");
    parts.VertexImpl = Get(vtkIceWorldSpaceVS, "Impl");
    parts.FragmentDeclarations =
      Get(vtkIceWorldSpaceFS, "Uniforms") + Get(vtkIceWorldSpaceFS, "Dec");
    this->AddIceShaderParts(parts, ren, act);
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    std::string missing = vtkIceShaderSections::Insert(parts, vs, fs);
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
    const std::string geometry = PassThroughGeometryShader(vs, shaders[vtkShader::Geometry]);
    missing += (missing.empty() || geometry.empty() ? "" : ", ") + geometry;
    if (!missing.empty() && !this->ReportedShaderPlaces)
    {
      // Once: the ice is drawn wrong in every frame after, the message says why.
      this->ReportedShaderPlaces = true;
      vtkErrorMacro(<< "VTK " << VTK_VERSION << "'s shaders lack places the ice's code goes: "
                    << missing << "; this VTK Ice does not support this VTK's shaders");
    }
  }
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  if (!program || !this->IsSurfaceHelper(&cellBO))
  {
    return;
  }

  // Model to world, including the inverse of the VBO's coordinate shift and scale. Matrices are
  // kept transposed, as VTK uploads them.
  vtkNew<vtkMatrix4x4> mcwc;
  vtkOpenGLVertexBufferObject* vertices = this->VBOs->GetVBO("vertexMC");
  if (vertices && vertices->GetCoordShiftAndScaleEnabled())
  {
    mcwc->DeepCopy(this->VBOShiftScale);
  }
  program->SetUniformMatrix("iceVBOToModelMatrix", mcwc);
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* actorMCWC;
    vtkMatrix3x3* actorNormals;
    static_cast<vtkOpenGLActor*>(act)->GetKeyMatrices(actorMCWC, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, actorMCWC, mcwc);
  }
  program->SetUniformMatrix("iceMCWCMatrix", mcwc);
  SetCameraUniforms(program, ren, act);
  this->SetIceShaderParameters(program, ren, act);
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::SetCameraUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act)
{
  // The normal matrix as vtkOpenGLActor::GetKeyMatrices makes it (the inverse of the actor's
  // 3 x 3 part, which GLSL reads transposed), from any vtkActor: the screen-space interior gets
  // the scene's prop (ParaView's vtkPVLODActor), not the OpenGL actor that draws it.
  vtkNew<vtkMatrix3x3> normalMCWC;
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* matrix = act->GetMatrix();
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        normalMCWC->SetElement(i, j, matrix->GetElement(i, j));
      }
    }
    normalMCWC->Invert();
  }
  program->SetUniformMatrix("iceNormalMCWCMatrix", normalMCWC);

  vtkCamera* camera = ren->GetActiveCamera();
  double* eye = camera->GetPosition();
  double* direction = camera->GetDirectionOfProjection();
  const float eyeWC[3] = { static_cast<float>(eye[0]), static_cast<float>(eye[1]),
    static_cast<float>(eye[2]) };
  const float directionWC[3] = { static_cast<float>(direction[0]), static_cast<float>(direction[1]),
    static_cast<float>(direction[2]) };
  program->SetUniform3f("iceCameraWC", eyeWC);
  program->SetUniform3f("iceViewDirectionWC", directionWC);
  program->SetUniformi("iceParallelProjection", camera->GetParallelProjection() ? 1 : 0);
  if (program->IsUniformUsed("iceWCDCMatrix") || program->IsUniformUsed("iceDCWCMatrix"))
  {
    vtkMatrix4x4* wcvc;
    vtkMatrix3x3* normals;
    vtkMatrix4x4* vcdc;
    vtkMatrix4x4* wcdc;
    static_cast<vtkOpenGLCamera*>(camera)->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
    program->SetUniformMatrix("iceWCDCMatrix", wcdc);
    // wcdc is kept transposed, so its inverse is the transposed inverse GLSL reads.
    vtkNew<vtkMatrix4x4> dcwc;
    vtkMatrix4x4::Invert(wcdc, dcwc);
    program->SetUniformMatrix("iceDCWCMatrix", dcwc);
  }

  // Inverses, for the programs that read them. Uploaded as GLSL reads them: VTK uploads a
  // vtkMatrix4x4 as is and GLSL reads columns, so the transpose multiplies column vectors.
  const auto setInverse = [program](const char* name, vtkMatrix4x4* matrix) {
    if (program->IsUniformUsed(name))
    {
      vtkNew<vtkMatrix4x4> inverse;
      vtkMatrix4x4::Invert(matrix, inverse);
      inverse->Transpose();
      program->SetUniformMatrix(name, inverse);
    }
  };
  setInverse("iceWCMCMatrix", act->GetMatrix());
  // VTK's light uniforms are in the view space of GetModelViewTransformMatrix.
  setInverse("iceVCWCMatrix", camera->GetModelViewTransformMatrix());

  // Not GetProjectionTransformMatrix(ren): that one is transposed and must be deleted.
  vtkMatrix4x4* projection =
    camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1.0, 1.0);
  const float depthToWindow[4] = { static_cast<float>(projection->GetElement(2, 2)),
    static_cast<float>(projection->GetElement(2, 3)), camera->GetParallelProjection() ? 1.0f : 0.0f,
    0.0f };
  program->SetUniform4f("iceDepthToWindow", depthToWindow);
}

//------------------------------------------------------------------------------
void vtkIceWorldSpaceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
