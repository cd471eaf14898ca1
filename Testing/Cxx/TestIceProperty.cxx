// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The material object, one behaviour per case (--case NAME):
// - mapper-property: the mapper draws the vtkIceProperty set on it; the mapper's modification
//   time follows its property's; SetIceProperty(nullptr) gives the defaults back; DeepCopy copies
//   every parameter.
// - shared: two blocks sharing one property are drawn as two blocks each set the same way on their
//   own property, and one change of the shared property changes both.
// - change-redraws: a property changed alone (not the mapper) is drawn at the next render, a
//   uniform (the tint) and a part of the shader (frost) alike.
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceProperty.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <cmath>
#include <string>

namespace
{
using IceTest::Expect;

bool MapperProperty()
{
  vtkNew<vtkIceMapper> mapper;
  vtkNew<vtkIceProperty> property;
  mapper->SetIceProperty(property);
  bool ok = Expect(mapper->GetIceProperty() == property, "the mapper draws the property set");
  const vtkMTimeType before = mapper->GetMTime();
  property->SetRoughness(0.5);
  ok = Expect(mapper->GetMTime() > before, "a change of the property modifies the mapper") && ok;
  property->SetIndexOfRefraction(1.5);
  property->SetIceColor(0.2, 0.4, 0.6);
  property->SetNumberOfCracks(7);
  property->GlisteningOn();
  vtkNew<vtkIceProperty> copy;
  copy->DeepCopy(property);
  ok = Expect(copy->GetIndexOfRefraction() == 1.5 && copy->GetRoughness() == 0.5 &&
           copy->GetIceColor()[2] == 0.6 && copy->GetNumberOfCracks() == 7 && copy->GetGlistening(),
         "DeepCopy copies the parameters") &&
    ok;
  mapper->SetIceProperty(nullptr);
  vtkNew<vtkIceProperty> defaults;
  ok = Expect(mapper->GetIceProperty() && mapper->GetIceProperty() != property &&
           mapper->GetIceProperty()->GetIndexOfRefraction() == defaults->GetIndexOfRefraction() &&
           mapper->GetIceProperty()->GetNumberOfCracks() == defaults->GetNumberOfCracks() &&
           mapper->GetIceProperty()->GetRoughness() == 0.0,
         "SetIceProperty(nullptr) gives the mapper a property with the defaults") &&
    ok;
  return ok;
}

// Two blocks side by side with clean optics, through vtkIcePass.
struct TwoBlocks
{
  TwoBlocks()
  {
    this->Renderer->SetEnvironmentTexture(
      IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 64));
    for (int i = 0; i < 2; ++i)
    {
      vtkNew<vtkIceBlockSource> block;
      block->SetSeed(3 + i);
      this->Mappers[i] = vtkSmartPointer<vtkIceMapper>::New();
      this->Mappers[i]->SetInputConnection(block->GetOutputPort());
      IceTest::UseCleanOptics(this->Mappers[i]);
      vtkNew<vtkActor> actor;
      actor->SetMapper(this->Mappers[i]);
      actor->SetPosition(1.2 * i - 0.6, 0.0, 0.0);
      this->Renderer->AddActor(actor);
    }
    this->Renderer->SetPass(this->Pass);
    this->Window->SetSize(200, 120);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->GetActiveCamera()->SetPosition(0.0, 0.8, 4.0);
    this->Renderer->ResetCamera();
  }
  IceTest::Image Render()
  {
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }
  vtkSmartPointer<vtkIceMapper> Mappers[2];
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
};

bool Shared()
{
  TwoBlocks own;
  for (auto& mapper : own.Mappers)
  {
    mapper->GetIceProperty()->SetIceColor(0.6, 0.8, 1.0);
    mapper->GetIceProperty()->SetRoughness(0.5);
  }
  const IceTest::Image separate = own.Render();

  TwoBlocks shared;
  vtkNew<vtkIceProperty> look;
  look->DeepCopy(shared.Mappers[0]->GetIceProperty());
  for (auto& mapper : shared.Mappers)
  {
    mapper->SetIceProperty(look);
  }
  const IceTest::Image before = shared.Render();
  look->SetIceColor(0.6, 0.8, 1.0);
  look->SetRoughness(0.5);
  const IceTest::Image after = shared.Render();
  // The blocks lie in the left and right halves of the window.
  size_t changed[2] = { 0, 0 };
  for (int y = 0; y < after.Height; ++y)
  {
    for (int x = 0; x < after.Width; ++x)
    {
      changed[2 * x / after.Width] +=
        IceTest::PixelDifference(before.At(x, y), after.At(x, y)) > 16 ? 1 : 0;
    }
  }
  const size_t differing = IceTest::CountDiffering(separate, after, 0);
  bool ok = Expect(changed[0] > 1000 && changed[1] > 1000,
    "one change of the shared property changes both blocks (" + std::to_string(changed[0]) +
      " pixels of the left half, " + std::to_string(changed[1]) + " of the right)");
  ok = Expect(differing == 0,
         "the blocks sharing a property are drawn as with the same settings each (" +
           std::to_string(differing) + " pixels differ)") &&
    ok;
  return ok;
}

bool ChangeRedraws()
{
  TwoBlocks scene;
  vtkIceProperty* look = scene.Mappers[0]->GetIceProperty();
  const IceTest::Image clear = scene.Render();
  look->SetIceColor(1.0, 0.3, 0.3);
  const IceTest::Image tinted = scene.Render();
  bool ok = Expect(IceTest::CountDiffering(clear, tinted, 16) > 1000,
    "the tint set on the property alone is drawn at the next render");
  look->SetRoughness(1.0);
  const IceTest::Image frosted = scene.Render();
  ok = Expect(IceTest::CountDiffering(tinted, frosted, 16) > 1000,
         "frost set on the property alone (a part of the shader) is drawn at the next render") &&
    ok;
  return ok;
}
}

int TestIceProperty(int argc, char* argv[])
{
  const IceTest::Cases cases = {
    { "mapper-property", MapperProperty },
    { "shared", Shared },
    { "change-redraws", ChangeRedraws },
  };
  return IceTest::RunCases("TestIceProperty", argc, argv, cases);
}
