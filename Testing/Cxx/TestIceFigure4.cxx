// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Figure 4 of the paper: the ice teapot with two-sided refraction (left) and one-sided refraction
// (right), cracks and air off. Checked against a reviewed baseline, and the two halves must differ
// measurably inside the teapot while being the same (within rounding) outside it.
#include "IceScene.h"
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iostream>

int TestIceFigure4(int argc, char* argv[])
{
  std::string error;
  vtkSmartPointer<vtkPolyData> teapot = IceScene::LoadModel("teapot", error);
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  if (!teapot || !environment)
  {
    std::cerr << error << "\n";
    return EXIT_FAILURE;
  }

  const int halfWidth = 400;
  const int height = 300;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(2 * halfWidth, height);
  window->SetOffScreenRendering(1);
  vtkActor* ice[2];
  vtkNew<vtkRenderer> renderers[2];
  for (int side = 0; side < 2; ++side)
  {
    renderers[side]->SetViewport(0.5 * side, 0.0, 0.5 * (side + 1), 1.0);
    // The paper's Figure 4: the ice in its environment map alone.
    IceScene::Options options;
    options.Landscape = false;
    options.DynamicEnvironment = false;
    ice[side] = IceScene::Populate(renderers[side], teapot, environment, options);
    vtkIceMapper* mapper = vtkIceMapper::SafeDownCast(ice[side]->GetMapper());
    mapper->SetTwoSidedRefraction(side == 0);
    IceTest::UseCleanOptics(mapper); // as in the paper's figure: cracks and air off
    window->AddRenderer(renderers[side]);
  }

  window->Render();
  const IceTest::Image figure = IceTest::Capture(window);
  ice[0]->VisibilityOff();
  ice[1]->VisibilityOff();
  window->Render();
  const IceTest::Image background = IceTest::Capture(window);
  ice[0]->VisibilityOn();
  ice[1]->VisibilityOn();
  window->Render();

  size_t inside = 0;
  size_t outsideDifferent = 0;
  double sum = 0.0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < halfWidth; ++x)
    {
      const unsigned char* twoSided = figure.At(x, y);
      const unsigned char* oneSided = figure.At(x + halfWidth, y);
      const int d = IceTest::PixelDifference(twoSided, oneSided);
      const bool teapot = IceTest::PixelDifference(twoSided, background.At(x, y)) > 0 ||
        IceTest::PixelDifference(oneSided, background.At(x + halfWidth, y)) > 0;
      if (teapot)
      {
        ++inside;
        sum += d;
      }
      else
      {
        // The two viewports' skyboxes may round a texel differently.
        outsideDifferent += d > 2 ? 1 : 0;
      }
    }
  }
  const double mean = inside ? sum / inside : 0.0;
  std::cout << "two-sided vs one-sided inside the teapot (" << inside << " pixels): mean " << mean
            << "/255; pixels differing by more than 2/255 outside it: " << outsideDifferent << "\n";
  const bool differ = inside > 10000 && mean >= 6.0 && outsideDifferent == 0;
  const bool image = IceTest::CheckImage(argc, argv, window);
  return differ && image ? EXIT_SUCCESS : EXIT_FAILURE;
}
