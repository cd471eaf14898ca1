// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// When VTK's shaders lack a place the ice's code goes (here the fragment shader's
// //VTK::Light::Impl, taken out of the template by a mapper made for the test), the mapper says
// so once, naming the place and the VTK, instead of drawing wrong ice in silence.
#include "IceTestUtilities.h"

#include "vtkActor.h"
#include "vtkIceMapper.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSphereSource.h"
#include "vtkVersionMacros.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
// A VTK whose fragment template has no //VTK::Light::Impl.
class MapperOfAnotherVTK : public vtkIceMapper
{
public:
  static MapperOfAnotherVTK* New();
  vtkTypeMacro(MapperOfAnotherVTK, vtkIceMapper);

protected:
  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::GetShaderTemplate(shaders, ren, act);
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl", "");
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
};
vtkStandardNewMacro(MapperOfAnotherVTK);
}

int TestIceShaderPlacesMissing(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<MapperOfAnotherVTK> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ice);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<IceTest::MessageRecorder> messages;
  messages->Watch(mapper);
  window->Render();
  window->Render();

  size_t naming = 0;
  for (const std::string& error : messages->Errors)
  {
    std::cout << "     error: " << error << "\n";
    naming += error.find("//VTK::Light::Impl (fragment)") != std::string::npos &&
        error.find("VTK " VTK_VERSION) != std::string::npos
      ? 1
      : 0;
  }
  const bool ok = naming == 1 && messages->Errors.size() == 1;
  std::cout << (ok ? "ok   " : "FAIL ") << "one error names the missing place and the VTK ("
            << messages->Errors.size() << " errors over two frames)\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
