// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The two interior methods side by side: the full look (2 cracks, 19 air planes, bumps; the same
// seeds; the cracks' sheets off, which the paper's passes do not draw) on the block and the
// teapot, rendered with the paper's passes and in the screen-space interior.
// Inside the ice the pictures agree closely (mean and 99th percentile of the per-pixel difference
// bounded) and the interior adds about as much light in both (its mean brightening over the ice
// without cracks and air, within 30 %); away from the ice they are identical. With VTKICE_FIGURE
// set to a .png path the test writes the 2 x 2 figure of Documentation/usage.md there (paper
// passes left, screen space right).
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const int Width = 320;
const int Height = 240;

IceTest::Image Render(vtkPolyDataAlgorithm* source, int method, bool ice, bool interior = true)
{
  vtkNew<vtkRenderer> renderer;
  IceTest::AddSky(renderer, 256);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetInteriorMethod(method);
  // What both methods draw: the paper's passes draw no crack sheets.
  mapper->GetIceProperty()->SetCrackReflection(0.0);
  if (!interior)
  {
    mapper->GetIceProperty()->SetNumberOfCracks(0);
    mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetVisibility(ice);
  renderer->AddActor(actor);
  vtkNew<vtkIcePass> pass;
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Width, Height);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.2, 1.6, 3.4);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  renderer->ResetCameraClippingRange();
  window->Render();
  return IceTest::Capture(window);
}

bool Compare(const char* name, vtkPolyDataAlgorithm* source, std::vector<IceTest::Image>& figure)
{
  const IceTest::Image background = Render(source, vtkIceMapper::InteriorScreenSpace, false);
  const IceTest::Image clean = Render(source, vtkIceMapper::InteriorScreenSpace, true, false);
  const IceTest::Image paper = Render(source, vtkIceMapper::InteriorPaperPasses, true);
  const IceTest::Image screen = Render(source, vtkIceMapper::InteriorScreenSpace, true);
  figure.push_back(paper);
  figure.push_back(screen);
  // The ice: where it changes the picture, widened by 2 pixels (multisampled edges).
  std::vector<bool> near(static_cast<size_t>(Width) * Height, false);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      if (IceTest::PixelDifference(background.At(x, y), paper.At(x, y)) > 0)
      {
        for (int dy = -2; dy <= 2; ++dy)
        {
          for (int dx = -2; dx <= 2; ++dx)
          {
            const int nx = std::min(std::max(x + dx, 0), Width - 1);
            const int ny = std::min(std::max(y + dy, 0), Height - 1);
            near[static_cast<size_t>(ny) * Width + nx] = true;
          }
        }
      }
    }
  }
  std::vector<double> inside;
  size_t outside = 0;
  double paperAdds = 0.0;
  double screenAdds = 0.0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const int difference = IceTest::PixelDifference(paper.At(x, y), screen.At(x, y));
      if (IceTest::PixelDifference(background.At(x, y), paper.At(x, y)) > 0)
      {
        inside.push_back(difference);
        for (int c = 0; c < 3; ++c)
        {
          paperAdds += paper.At(x, y)[c] - clean.At(x, y)[c];
          screenAdds += screen.At(x, y)[c] - clean.At(x, y)[c];
        }
      }
      else if (!near[static_cast<size_t>(y) * Width + x])
      {
        outside += difference > 0 ? 1 : 0;
      }
    }
  }
  const IceTest::Stats stats = IceTest::Summarize(inside);
  const double count = 3.0 * std::max<size_t>(stats.Count, 1);
  const double ratio = screenAdds / std::max(paperAdds, 1.0);
  const bool ok = stats.Count > 5000 && stats.Mean < 10.0 && stats.P99 < 100.0 && outside == 0 &&
    ratio > 0.7 && ratio < 1.3;
  std::cout << (ok ? "ok   " : "FAIL ") << name << ": screen space against paper passes over "
            << stats.Count << " ice pixels: mean " << stats.Mean << "/255, p99 " << stats.P99
            << "/255, max " << stats.Max << "/255; the interior brightens the ice by "
            << paperAdds / count << "/255 (paper passes) and " << screenAdds / count
            << "/255 (screen space); " << outside << " pixels differ away from the ice\n";
  return ok;
}

// Paper passes left, screen space right; the block above the teapot.
void WriteFigure(const char* path, const std::vector<IceTest::Image>& images)
{
  vtkNew<vtkImageData> figure;
  figure->SetDimensions(2 * Width, 2 * Height, 1);
  figure->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(figure->GetScalarPointer());
  for (size_t i = 0; i < images.size(); ++i)
  {
    const int column = static_cast<int>(i % 2);
    const int row = 1 - static_cast<int>(i / 2);
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        const unsigned char* p = images[i].At(x, y);
        unsigned char* q = pixels + 3 * ((row * Height + y) * 2 * Width + column * Width + x);
        q[0] = p[0];
        q[1] = p[1];
        q[2] = p[2];
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path);
  writer->SetInputData(figure);
  writer->Write();
  std::cout << "wrote " << path << "\n";
}
}

int TestIceInteriorMethods(int, char*[])
{
  std::vector<IceTest::Image> figure;
  vtkNew<vtkIceBlockSource> block;
  vtkNew<vtkIceTeapotSource> teapot;
  bool ok = Compare("block", block, figure);
  ok = Compare("teapot", teapot, figure) && ok;
  if (const char* path = std::getenv("VTKICE_FIGURE"))
  {
    WriteFigure(path, figure);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
