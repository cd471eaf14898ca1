// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceTraceTextures.h"

#include "vtkActor.h"
#include "vtkIceTriangleBVH.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"


//------------------------------------------------------------------------------
vtkIceTraceTextures::vtkIceTraceTextures()
  : Tree(vtkSmartPointer<vtkIceTriangleBVH>::New())
{
}

//------------------------------------------------------------------------------
vtkIceTraceTextures::~vtkIceTraceTextures() = default;

//------------------------------------------------------------------------------
bool vtkIceTraceTextures::Update(vtkPolyData* surface, const char* normals)
{
  if (surface != this->Surface || !surface || surface->GetMTime() != this->SurfaceTime)
  {
    this->Surface = surface;
    this->SurfaceTime = surface ? surface->GetMTime() : 0;
    this->Usable =
      surface && this->Tree->Build(surface, surface->GetPointData()->GetArray(normals));
  }
  return this->Usable;
}

//------------------------------------------------------------------------------
void vtkIceTraceTextures::Activate(vtkOpenGLRenderWindow* window, vtkShaderProgram* program,
  vtkActor* actor, int maxBounces, vtkTextureObject* active[2])
{
  if (!this->Nodes || this->Nodes->GetContext() != window)
  {
    this->ReleaseGraphicsResources(window);
    this->NodeBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->TriangleBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Nodes = vtkSmartPointer<vtkTextureObject>::New();
    this->Triangles = vtkSmartPointer<vtkTextureObject>::New();
    this->Nodes->SetContext(window);
    this->Triangles->SetContext(window);
  }
  if (this->UploadedTime != this->Tree->GetMTime())
  {
    const std::vector<float>& nodes = this->Tree->GetNodes();
    const std::vector<float>& triangles = this->Tree->GetTriangles();
    this->NodeBuffer->Upload(nodes, vtkOpenGLBufferObject::TextureBuffer);
    this->Nodes->CreateTextureBuffer(
      static_cast<unsigned int>(nodes.size() / 4), 4, VTK_FLOAT, this->NodeBuffer);
    this->TriangleBuffer->Upload(triangles, vtkOpenGLBufferObject::TextureBuffer);
    this->Triangles->CreateTextureBuffer(
      static_cast<unsigned int>(triangles.size() / 4), 4, VTK_FLOAT, this->TriangleBuffer);
    this->UploadedTime = this->Tree->GetMTime();
  }
  this->Nodes->Activate();
  this->Triangles->Activate();
  active[0] = this->Nodes;
  active[1] = this->Triangles;
  program->SetUniformi("iceTraceNodes", this->Nodes->GetTextureUnit());
  program->SetUniformi("iceTraceTriangles", this->Triangles->GetTextureUnit());
  program->SetUniformi("iceTraceMaxBounces", maxBounces);
  // A hit nearer than a millionth of the ice's size is the surface the ray starts on.
  program->SetUniformf("iceTraceEpsilon", static_cast<float>(1.0e-5 * this->Tree->GetDiagonal()));
  // World to model: the inverse of the actor's matrix, transposed as VTK uploads matrices.
  vtkMatrix4x4* wcmc = this->WorldToModel;
  wcmc->Identity();
  if (!actor->GetIsIdentity())
  {
    vtkMatrix4x4::Invert(actor->GetMatrix(), wcmc);
  }
  wcmc->Transpose();
  program->SetUniformMatrix("iceTraceWCMC", wcmc);
}

//------------------------------------------------------------------------------
void vtkIceTraceTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Nodes)
  {
    this->Nodes->ReleaseGraphicsResources(window);
    this->Triangles->ReleaseGraphicsResources(window);
    this->NodeBuffer->ReleaseGraphicsResources();
    this->TriangleBuffer->ReleaseGraphicsResources();
  }
  this->UploadedTime = 0;
}
