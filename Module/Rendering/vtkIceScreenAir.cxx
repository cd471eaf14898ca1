// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceScreenAir.h"

#include "vtkIceInteriorTable.h"
#include "vtkIceScreenInteriorFS.h"
#include "vtkIceShaderSections.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"

#include <vector>

//------------------------------------------------------------------------------
vtkIceScreenAir::vtkIceScreenAir() = default;

//------------------------------------------------------------------------------
vtkIceScreenAir::~vtkIceScreenAir() = default;

//------------------------------------------------------------------------------
vtkShaderProgram* vtkIceScreenAir::Ready(
  vtkOpenGLRenderWindow* window, const std::string& declarations)
{
  using vtkIceShaderSections::Get;
  std::string fs = Get(vtkIceScreenInteriorFS, "AirFS");
  vtkShaderProgram::Substitute(fs, "//ICEHOOK::AirDeclarations", declarations);
  if (!this->Quads)
  {
    this->Quads = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  return window->GetShaderCache()->ReadyShaderProgram(
    Get(vtkIceScreenInteriorFS, "AirVS").c_str(), fs.c_str(), "");
}

//------------------------------------------------------------------------------
void vtkIceScreenAir::Draw(
  vtkActor* actor, const vtkIceInteriorTable& interior, vtkShaderProgram* program)
{
  const int planes = interior.GetNumberOfAirPlanes();
  if (planes <= 0 || !program || !this->Quads)
  {
    return;
  }
  std::vector<float> corners;
  std::vector<float> atlas;
  std::vector<unsigned int> triangles;
  corners.reserve(12 * static_cast<size_t>(planes));
  atlas.reserve(8 * static_cast<size_t>(planes));
  triangles.reserve(6 * static_cast<size_t>(planes));
  vtkMatrix4x4* modelToWorld = actor->GetMatrix();
  for (int k = 0; k < planes; ++k)
  {
    double quad[12];
    double coordinates[8];
    interior.GetAirQuad(k, quad, coordinates);
    for (int c = 0; c < 4; ++c)
    {
      const double model[4] = { quad[3 * c], quad[3 * c + 1], quad[3 * c + 2], 1.0 };
      double world[4];
      modelToWorld->MultiplyPoint(model, world);
      for (int i = 0; i < 3; ++i)
      {
        corners.push_back(static_cast<float>(world[i] / world[3]));
      }
      atlas.push_back(static_cast<float>(coordinates[2 * c]));
      atlas.push_back(static_cast<float>(coordinates[2 * c + 1]));
    }
    const unsigned int first = static_cast<unsigned int>(4 * k);
    for (unsigned int corner : { 0u, 1u, 3u, 0u, 3u, 2u })
    {
      triangles.push_back(first + corner);
    }
  }
  // A vertex array serves one program: the lights' or the look's changes make another.
  if (program != this->Program)
  {
    this->Quads->ReleaseGraphicsResources();
    this->Program = program;
  }
  vtkOpenGLRenderUtilities::RenderTriangles(corners.data(),
    static_cast<unsigned int>(corners.size() / 3), triangles.data(),
    static_cast<unsigned int>(triangles.size()), atlas.data(), program, this->Quads);
}

//------------------------------------------------------------------------------
void vtkIceScreenAir::ReleaseGraphicsResources(vtkWindow*)
{
  if (this->Quads)
  {
    this->Quads->ReleaseGraphicsResources();
  }
  this->Program = nullptr;
}
