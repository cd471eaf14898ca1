// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceCubeMapPass with a vtkIceCubeMapCompositor, the hook distributed rendering composites the
// dynamic cube map through (ParaView's plugin: vtkPVIceCubeMapCompositor over MPI). A stand-in
// compositor plays a second process:
// - its faces hold a red surface nearer than anything on the left half: the ice refracts red,
//   which it does not without the compositor;
// - UseBackground: the faces are rendered on the compositor's background (green) while the
//   renderer keeps its own (black) for the frame;
// - OnChange: a new compositor background (the renderer's stays as it was) renders the cube map
//   again;
// - the other process asks for an update (its restart flags reduced by maximum): a Manual cube
//   map is rendered again, and not when nobody asks.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapCompositor.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
class SecondProcess : public vtkIceCubeMapCompositor
{
public:
  static SecondProcess* New();
  vtkTypeMacro(SecondProcess, vtkIceCubeMapCompositor);
  void MaximumOverProcesses(double* values, int count) override
  {
    for (int i = 0; i < count; ++i)
    {
      // Restart flags are 0 or 1, the depth range is at least 1: only a flag can be raised.
      values[i] = this->WantsUpdate && values[i] < 1.0 ? 1.0 : values[i];
    }
  }
  void CompositeFace(vtkIdType pixels, float* rgba, float* depth) override
  {
    ++this->Faces;
    const vtkIdType size = static_cast<vtkIdType>(std::lround(std::sqrt(pixels)));
    for (vtkIdType p = 0; this->RedSurface && p < pixels; ++p)
    {
      if (p % size < size / 2 && depth[p] > 0.5f)
      {
        depth[p] = 0.5f;
        rgba[4 * p] = 1.0f;
        rgba[4 * p + 1] = rgba[4 * p + 2] = 0.0f;
        rgba[4 * p + 3] = 1.0f;
      }
    }
  }
  bool WantsUpdate = false;
  bool RedSurface = false;
  int Faces = 0;
};
vtkStandardNewMacro(SecondProcess);

using IceTest::Expect;

// Pixels of the silhouette that are mostly red, mostly green, and not black outside it.
struct Counts
{
  size_t Red = 0;
  size_t Green = 0;
  size_t Outside = 0;
};
Counts Count(const IceTest::Image& image, const IceTest::Image& silhouette)
{
  Counts counts;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const unsigned char* p = image.At(x, y);
      const unsigned char* s = silhouette.At(x, y);
      if (!s[0] && !s[1] && !s[2])
      {
        counts.Outside += p[0] || p[1] || p[2] ? 1 : 0;
        continue;
      }
      counts.Red += p[0] > 60 && p[0] > 2 * p[1] && p[0] > 2 * p[2] ? 1 : 0;
      counts.Green += p[1] > 60 && p[1] > 2 * p[0] && p[1] > 2 * p[2] ? 1 : 0;
    }
  }
  return counts;
}
}

int TestIceCubeMapCompositor(int, char*[])
{
  IceTest::BlockScene scene;
  const IceTest::Image silhouette = scene.Render(); // static sky environment on black
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  cubeMaps->SetFaceSize(64);
  cubeMaps->SetUpdateModeToEveryFrame();
  scene.Pass->SetCubeMapPass(cubeMaps);
  const Counts alone = Count(scene.Render(), silhouette);

  vtkNew<SecondProcess> other;
  other->RedSurface = true;
  cubeMaps->SetCompositor(other);
  const Counts red = Count(scene.Render(), silhouette);
  other->RedSurface = false;
  other->SetBackground(0.0, 1.0, 0.0);
  other->UseBackgroundOn();
  const Counts green = Count(scene.Render(), silhouette);
  double background[3];
  scene.Renderer->GetBackground(background);
  std::cout << "red pixels alone " << alone.Red << ", with the other process " << red.Red
            << "; green on its background " << green.Green << "\n";
  bool ok = Expect(alone.Red < 50 && red.Red > 2000, "the ice refracts the other process's red");
  ok &= Expect(
    green.Green > 2000 && alone.Green < 50, "faces are rendered on the compositor's background");
  ok &= Expect(green.Outside == 0 && background[0] == 0.0 && background[1] == 0.0,
    "the renderer keeps its own background");

  cubeMaps->SetUpdateModeToOnChange();
  scene.Render();
  const vtkIdType settled = cubeMaps->GetNumberOfFaceRenders();
  scene.Render();
  ok &= Expect(cubeMaps->GetNumberOfFaceRenders() == settled, "OnChange: no update when unchanged");
  other->SetBackground(0.0, 0.0, 1.0);
  scene.Render();
  ok &= Expect(cubeMaps->GetNumberOfFaceRenders() >= settled + 6,
    "OnChange: the compositor's new background updates the cube map");

  cubeMaps->SetUpdateModeToManual();
  scene.Render();
  const vtkIdType rendered = cubeMaps->GetNumberOfFaceRenders();
  const int composited = other->Faces;
  scene.Render();
  ok &= Expect(cubeMaps->GetNumberOfFaceRenders() == rendered && other->Faces == composited,
    "Manual: no update when no process asks");
  other->WantsUpdate = true;
  scene.Render(); // renders the frame twice (IceTest::Capture)
  const vtkIdType again = cubeMaps->GetNumberOfFaceRenders() - rendered;
  ok &= Expect(again >= 6 && again % 6 == 0 && other->Faces - composited == again,
    "Manual: all six faces rendered and composited when another process asks (" +
      std::to_string(again) + ")");
  scene.Pass->SetCubeMapPass(nullptr);
  return ok ? 0 : 1;
}
