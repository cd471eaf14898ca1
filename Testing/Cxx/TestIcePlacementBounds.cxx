// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceMapper::PlacementBounds, which distributed rendering gives every piece of an ice object:
// - a piece (the left of two blocks) placed in the bounds of the whole (both blocks) draws its
//   cracks, air and bumps over its own pixels as the whole does; without PlacementBounds it does
//   not (they are placed in the piece's own bounds), so the check can fail;
// - GetBounds returns PlacementBounds;
// - empty input with PlacementBounds draws nothing and reports nothing; without, it is an error.
#include "IceTestUtilities.h"
#include "vtkIceBlockSource.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
using IceTest::Expect;

vtkSmartPointer<vtkPolyData> Block(int seed, double x)
{
  vtkNew<vtkIceBlockSource> block;
  block->SetSeed(seed);
  vtkNew<vtkTransform> move;
  move->Translate(x, 0.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(block->GetOutputPort());
  place->SetTransform(move);
  place->Update();
  return place->GetOutput();
}

bool IsBlack(const unsigned char* p)
{
  return !p[0] && !p[1] && !p[2];
}
}

int TestIcePlacementBounds(int, char*[])
{
  IceTest::BlockScene scene;
  scene.Window->SetSize(320, 200);
  vtkIceMapper* mapper = scene.Mapper;
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  vtkSmartPointer<vtkPolyData> piece = Block(3, -0.9);
  vtkSmartPointer<vtkPolyData> other = Block(4, 0.9);
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(piece);
  append->AddInputData(other);
  append->Update();
  vtkPolyData* whole = append->GetOutput();
  double bounds[6];
  whole->GetBounds(bounds);

  // The silhouettes of the piece and of the other block (which hides part of the piece), then
  // the whole with cracks, air and bumps.
  mapper->SetInputData(other);
  const IceTest::Image otherSilhouette = scene.Render();
  mapper->SetInputData(piece);
  const IceTest::Image silhouette = scene.Render();
  mapper->GetIceProperty()->SetNumberOfCracks(4);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(8);
  mapper->GetIceProperty()->SetBumpStrength(0.5);
  mapper->SetInputData(whole);
  const IceTest::Image wholeImage = scene.Render();
  mapper->SetInputData(piece);
  const IceTest::Image own = scene.Render();
  mapper->SetPlacementBounds(bounds);
  const IceTest::Image placed = scene.Render();

  std::vector<double> placedDifference;
  size_t ownDiffering = 0;
  for (int y = 0; y < silhouette.Height; ++y)
  {
    for (int x = 0; x < silhouette.Width; ++x)
    {
      if (IsBlack(silhouette.At(x, y)) || !IsBlack(otherSilhouette.At(x, y)))
      {
        continue;
      }
      placedDifference.push_back(IceTest::PixelDifference(placed.At(x, y), wholeImage.At(x, y)));
      ownDiffering += IceTest::PixelDifference(own.At(x, y), wholeImage.At(x, y)) > 16 ? 1 : 0;
    }
  }
  const IceTest::Stats stats = IceTest::Summarize(placedDifference);
  std::cout << "piece in the whole's bounds vs the whole, over the piece's " << stats.Count
            << " pixels: mean " << stats.Mean << ", p99 " << stats.P99 << ", max " << stats.Max
            << "; in its own bounds " << ownDiffering << " pixels off by more than 16\n";
  bool ok = Expect(stats.Count > 5000, "the piece shows on many pixels");
  ok &= Expect(stats.Mean <= 0.5 && stats.P99 <= 4,
    "the piece placed in the whole's bounds looks as its part of the whole");
  ok &= Expect(ownDiffering > 500, "placed in its own bounds it does not (the check can fail)");
  const double* reported = mapper->GetBounds();
  ok &= Expect(reported[0] == bounds[0] && reported[1] == bounds[1] && reported[5] == bounds[5],
    "GetBounds returns PlacementBounds");

  // A rank without ice: nothing drawn, nothing reported.
  vtkNew<vtkPolyData> empty;
  mapper->SetInputData(empty);
  const IceTest::Image nothing = scene.Render();
  size_t drawn = 0;
  for (int y = 0; y < nothing.Height; ++y)
  {
    for (int x = 0; x < nothing.Width; ++x)
    {
      drawn += IsBlack(nothing.At(x, y)) ? 0 : 1;
    }
  }
  ok &= Expect(drawn == 0 && recorder->Errors.empty() && recorder->Warnings.empty(),
    "empty input with PlacementBounds: nothing drawn, no message (" + std::to_string(drawn) +
      " pixels, " + std::to_string(recorder->Errors.size()) + " errors)");
  double none[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  mapper->SetPlacementBounds(none);
  empty->Modified();
  scene.Render();
  ok &= Expect(
    recorder->Errors.size() == 1 && recorder->Errors[0].find("no polygons") != std::string::npos,
    "without PlacementBounds empty input is an error");
  return ok ? 0 : 1;
}
