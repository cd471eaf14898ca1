// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The places in VTK's shaders where the ice's code goes, on the VTK this build uses (each lane
// builds against its own): the ice sphere is drawn with the pass, then with its edges shown
// (VTK adds a geometry shader), and every program VTK compiles for the mapper must carry the
// ice's code (vertex outputs, fragment inputs, the pass's samplers declared once) and, where the
// geometry shader grows triangles for edges (VTK 9.1-9.3), the ice's corner weights; the mapper
// must report no missing place. A VTK that renames a tag or a line the code relies on fails here.
#include "IceTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using IceTest::Expect;

struct Program
{
  std::string Vertex;
  std::string Geometry;
  std::string Fragment;
};

size_t Count(const std::string& text, const std::string& what)
{
  size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++n;
  }
  return n;
}

// Whether `program` is the ice surface's: its vertex shader writes the ice's world position.
bool IsIceSurface(const Program& program)
{
  return program.Vertex.find("icePositionWCVSOutput =") != std::string::npos;
}
}

int TestIceShaderPlaces(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ice);
  renderer->SetEnvironmentTexture(IceTest::MakeCubeMap(0, 32));
  vtkNew<vtkIcePass> pass;
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(96, 96);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);

  // Every program VTK builds or updates for the mapper, as compiled.
  std::vector<Program> programs;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&programs);
  record->SetCallback([](vtkObject*, unsigned long, void* list, void* data) {
    auto* program = static_cast<vtkShaderProgram*>(data);
    auto source = [](vtkShader* shader) { return shader ? shader->GetSource() : std::string(); };
    static_cast<std::vector<Program>*>(list)->push_back({ source(program->GetVertexShader()),
      source(program->GetGeometryShader()), source(program->GetFragmentShader()) });
  });
  mapper->AddObserver(vtkCommand::UpdateShaderEvent, record);
  vtkNew<IceTest::MessageRecorder> messages;
  messages->Watch(mapper);

  bool ok = true;
  for (bool edges : { false, true })
  {
    programs.clear();
    ice->GetProperty()->SetEdgeVisibility(edges);
    window->Render();
    const Program* surface = nullptr;
    for (const Program& program : programs)
    {
      if (IsIceSurface(program) && (program.Geometry.empty() != edges))
      {
        surface = &program;
      }
    }
    const std::string what = edges ? "with edges: " : "surface: ";
    ok = Expect(surface != nullptr,
           what + "a program of the ice surface (" + std::to_string(programs.size()) +
             " programs updated)") &&
      ok;
    if (!surface)
    {
      continue;
    }
    // The fragment shader reads the varyings under VTK's name for its stage before it.
    const std::string in = edges ? "icePositionWCGSOutput" : "icePositionWCVSOutput";
    ok = Expect(surface->Fragment.find("in vec3 " + in) != std::string::npos,
           what + "the fragment shader receives the ice's world position (" + in + ")") &&
      ok;
    ok = Expect(Count(surface->Fragment, "uniform sampler2D iceBackNormals") == 1,
           what + "the pass's back-normal sampler is declared once") &&
      ok;
    if (edges)
    {
      ok = Expect(surface->Geometry.find("icePositionWCGSOutput = ") != std::string::npos,
             what + "the geometry shader passes the ice's varyings on") &&
        ok;
      const bool grows = surface->Geometry.find("offsets[i]") != std::string::npos;
      ok = Expect(!grows || surface->Geometry.find("iceGrownCornerWeights(") != std::string::npos,
             what +
               (grows ? "VTK grows triangles for edges: the ice's corner weights are in"
                      : "VTK draws edges without growing triangles")) &&
        ok;
    }
  }
  std::string errors;
  for (const std::string& error : messages->Errors)
  {
    errors += " " + error;
  }
  ok = Expect(messages->Errors.empty(), "the mapper found every place:" + errors) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
