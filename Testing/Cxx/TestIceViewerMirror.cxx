// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render's ice mirrored in its melt pool (IceScene::AddMirrorImage) under the interactive
// viewer: the image lies below the ice's foot, every key's change reaches it as it reaches the
// ice, and a debug view (of the ice alone) hides it until the keys leave the debug views.
#include "IceTestUtilities.h"
#include "IceViewer.h"
#include "IceViewerTestScene.h"

#include "vtkCommand.h"
#include "vtkGenericRenderWindowInteractor.h"
#include "vtkRenderWindow.h"

#include <string>

int TestIceViewerMirror(int, char*[])
{
  using IceTest::Expect;
  IceViewerTestScene scene("cube");
  vtkRenderer* renderer = scene.Renderer;
  vtkPolyData* model = scene.Model;
  const vtkIceLookTable::Target& target = scene.Target;
  vtkActor* image = IceScene::AddMirrorImage(renderer, model);
  vtkIceLookTable::Target mirror = target;
  mirror.Mapper = vtkIceMapper::SafeDownCast(image->GetMapper());

  double bounds[6];
  double mirrored[6];
  model->GetBounds(bounds);
  image->GetBounds(mirrored);
  bool ok = Expect(mirror.Mapper && mirrored[3] <= bounds[2] + 1.0e-9 &&
      mirrored[3] - mirrored[2] > 0.99 * (bounds[3] - bounds[2]),
    "the mirror image is ice as tall as the ice, below its foot (" + std::to_string(mirrored[2]) +
      " to " + std::to_string(mirrored[3]) + ", the ice " + std::to_string(bounds[2]) + " to " +
      std::to_string(bounds[3]) + ")");

  vtkNew<vtkRenderWindow> window;
  window->SetSize(160, 120);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  vtkNew<IceViewer> viewer;
  viewer->Setup(target, renderer);
  viewer->Follow(image);
  interactor->SetInteractorStyle(viewer);
  interactor->SetRenderWindow(window);
  window->Render();
  auto type = [&](char key) {
    interactor->SetKeyCode(key);
    interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
  };

  // Keys of each kind: a count off, a step, a switch, a choice.
  const struct
  {
    char Key;
    const char* Setting;
  } keys[] = { { 'c', "cracks" }, { '=', "milkiness" }, { '1', "two-sided" },
    { '2', "two-sided-method" } };
  for (const auto& key : keys)
  {
    const std::string before = vtkIceLookTable::Value(mirror, key.Setting);
    type(key.Key);
    const std::string now = vtkIceLookTable::Value(target, key.Setting);
    const std::string image = vtkIceLookTable::Value(mirror, key.Setting);
    ok = Expect(now != before && image == now,
           std::string("'") + key.Key + "' changes " + key.Setting + " on the mirror image too (" +
             before + " -> " + image + ", the ice " + now + ")") &&
      ok;
  }
  ok = Expect(image->GetVisibility(), "the mirror image shows with the look") && ok;
  type('v');
  ok = Expect(vtkIceLookTable::Value(target, "debug-view") != "off" && !image->GetVisibility(),
         "a debug view (" + vtkIceLookTable::Value(target, "debug-view") +
           ") hides the mirror image") &&
    ok;
  for (int i = 0; i < 10 && vtkIceLookTable::Value(target, "debug-view") != "off"; ++i)
  {
    type('v');
  }
  ok = Expect(vtkIceLookTable::Value(target, "debug-view") == "off" && image->GetVisibility(),
         "back to the look, the mirror image shows again") &&
    ok;
  return ok ? 0 : 1;
}
