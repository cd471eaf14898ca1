// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render's interactive legend at the window's size: at 1024x768 it lists every key at a
// readable size in a corner; at 400x300 it shrinks to one line ("h  keys") that leaves the model
// alone, and 'h' brings the whole list at the smallest readable size; resizing back gives the
// whole list again. Its key names are the characters typed ('[' and ']', not '(' and ')').
#include "vtkIceLookTable.h"
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "IceViewer.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkGenericRenderWindowInteractor.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using IceTest::Expect;

// Pixels of the model (where the ice changes the scene) that the viewer's text covers.
size_t HiddenModelPixels(vtkRenderWindow* window, vtkRenderer* renderer, vtkActor* ice)
{
  const IceTest::Image shown = IceTest::Capture(window);
  // The viewer's text actors out of the scene for the pictures without them.
  std::vector<vtkSmartPointer<vtkProp>> text;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
  {
    if (prop->IsA("vtkTextActor"))
    {
      text.emplace_back(prop);
    }
  }
  for (vtkProp* prop : text)
  {
    renderer->RemoveViewProp(prop);
  }
  const IceTest::Image withIce = IceTest::Capture(window);
  ice->VisibilityOff();
  const IceTest::Image scene = IceTest::Capture(window);
  ice->VisibilityOn();
  for (vtkProp* prop : text)
  {
    renderer->AddViewProp(prop);
  }
  size_t hidden = 0;
  for (int y = 0; y < shown.Height; ++y)
  {
    for (int x = 0; x < shown.Width; ++x)
    {
      const bool model = IceTest::PixelDifference(scene.At(x, y), withIce.At(x, y)) > 8;
      hidden += model && IceTest::PixelDifference(withIce.At(x, y), shown.At(x, y)) > 8 ? 1 : 0;
    }
  }
  return hidden;
}
}

int TestIceViewerLegend(int, char*[])
{
  std::string error;
  vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel("teapot", error);
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  vtkNew<vtkRenderer> renderer;
  IceScene::Options options;
  options.DynamicEnvironment = false;
  vtkActor* ice = IceScene::Populate(renderer, model, environment, options);
  vtkIceMapper* mapper = vtkIceMapper::SafeDownCast(ice->GetMapper());
  const vtkIceLookTable::Target target{ mapper, vtkIcePass::SafeDownCast(renderer->GetPass()),
    nullptr, renderer->GetActiveCamera() };

  vtkNew<vtkRenderWindow> window;
  window->SetSize(1024, 768);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  vtkNew<IceViewer> viewer;
  viewer->Setup(target, renderer);
  interactor->SetInteractorStyle(viewer);
  interactor->SetRenderWindow(window);
  window->Render();

  bool ok = true;
  const std::string legend = viewer->GetLegend();
  ok = Expect(legend.find("[  ior down / up ]") != std::string::npos,
         "the legend names the keys as typed: '[' and ']'") &&
    ok;

  auto check = [&](const char* what, int width, int height, IceViewer::LegendKind kind,
                 int minimumFont, double maximumShare, size_t maximumHidden) {
    window->SetSize(width, height);
    window->Render();
    const double share = viewer->GetLegendShare();
    const int font = viewer->GetLegendFontSize();
    const size_t hidden = HiddenModelPixels(window, renderer, ice);
    ok =
      Expect(viewer->GetLegendShown() == kind && font >= minimumFont && share <= maximumShare &&
          hidden <= maximumHidden,
        std::string(what) + ": " + std::to_string(width) + "x" + std::to_string(height) +
          ", font " + std::to_string(font) + " px, legend covers " + std::to_string(100.0 * share) +
          " % of the window, hides " + std::to_string(hidden) + " model pixels") &&
      ok;
  };
  check("the whole list at the default size", 1024, 768, IceViewer::LegendFull, 14, 0.12, 0);
  check("one line in a small window", 400, 300, IceViewer::LegendHint, 8, 0.03, 0);
  interactor->SetKeyCode('h');
  interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
  window->Render();
  ok = Expect(viewer->GetLegendShown() == IceViewer::LegendFull &&
           viewer->GetLegendFontSize() >= 8 && viewer->GetLegendFontSize() < 14,
         "'h' in the small window shows the whole list at " +
           std::to_string(viewer->GetLegendFontSize()) + " px") &&
    ok;
  interactor->SetKeyCode('h');
  interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
  check("the whole list again at the default size", 1024, 768, IceViewer::LegendFull, 14, 0.12, 0);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
