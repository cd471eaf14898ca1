// Cracks (paper section 3.3): drawn in red (DebugCracksClipped) no crack pixel lies outside the
// ice's silhouette while many lie inside, and unclipped they do stick out; the highlights change
// the picture inside the ice only; the same seed gives the same image and another seed another;
// the ice costs the same passes and one crack draw per frame whatever NumberOfCracks; and crack
// normals perturb the refraction only when asked.
#include "IceTestUtilities.h"
#include "vtkIceDepthIntervalPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <functional>
#include <iostream>
#include <string>

namespace
{

bool IsRed(const unsigned char* p)
{
  return p[0] >= 250 && p[1] <= 5 && p[2] <= 5;
}

bool Expect(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
  return condition;
}

// Counts pixels selected by `select` inside and outside the ice's silhouette.
void Count(const IceTest::Image& image, const IceTest::Image& silhouette,
  const std::function<bool(size_t)>& select, size_t& inside, size_t& outside)
{
  inside = outside = 0;
  for (size_t p = 0; p < image.RGB.size() / 3; ++p)
  {
    if (select(p))
    {
      const unsigned char* s = &silhouette.RGB[3 * p];
      (s[0] || s[1] || s[2] ? inside : outside)++;
    }
  }
}

bool Clipping()
{
  IceTest::BlockScene scene;
  const IceTest::Image silhouette = scene.Render(); // black background: ice is non-black
  scene.Mapper->SetNumberOfCracks(2);
  bool ok = true;
  size_t inside;
  size_t outside;
  for (int view : { vtkIceMapper::DebugCracksClipped, vtkIceMapper::DebugCracksUnclipped })
  {
    scene.Mapper->SetDebugView(view);
    const IceTest::Image image = scene.Render();
    Count(
      image, silhouette, [&image](size_t p) { return IsRed(&image.RGB[3 * p]); }, inside, outside);
    const bool clipped = view == vtkIceMapper::DebugCracksClipped;
    std::cout << (clipped ? "clipped" : "unclipped") << " cracks in red: " << inside
              << " pixels inside the silhouette, " << outside << " outside\n";
    ok =
      Expect(clipped ? (outside == 0 && inside > 2000) : outside > 500,
        clipped ? "clipped cracks stay inside the ice and show" : "unclipped cracks stick out") &&
      ok;
  }

  scene.Mapper->SetDebugView(vtkIceMapper::DebugOff);
  scene.Mapper->SetNumberOfCracks(0);
  const IceTest::Image clear = scene.Render();
  scene.Mapper->SetNumberOfCracks(2);
  const IceTest::Image cracked = scene.Render();
  Count(
    cracked, silhouette,
    [&](size_t p) { return IceTest::PixelDifference(&clear.RGB[3 * p], &cracked.RGB[3 * p]) > 8; },
    inside, outside);
  std::cout << "highlights change " << inside << " pixels inside the ice, " << outside
            << " outside\n";
  ok = Expect(inside > 200 && outside == 0, "highlights show inside the ice only") && ok;
  return ok;
}

bool Seeds()
{
  auto render = [](int seed) {
    IceTest::BlockScene scene;
    scene.Mapper->SetNumberOfCracks(2);
    scene.Mapper->SetCrackSeed(seed);
    scene.Mapper->SetDebugView(vtkIceMapper::DebugCracksClipped);
    return scene.Render();
  };
  const IceTest::Image first = render(3);
  const IceTest::Image again = render(3);
  const IceTest::Image other = render(4);
  return Expect(first.RGB == again.RGB, "the same seed gives the same image") &&
    Expect(first.RGB != other.RGB, "another seed gives other cracks");
}

bool PassCount()
{
  IceTest::BlockScene scene;
  scene.Mapper->SetNumberOfCracks(2);
  bool ok = true;
  for (int cracks : { 2, 128 })
  {
    scene.Mapper->SetNumberOfCracks(cracks);
    scene.Window->Render();
    const vtkIdType passes = scene.Pass->GetDepthIntervalPass()->GetNumberOfGeometryPasses();
    const vtkIdType draws = scene.Mapper->GetNumberOfCrackDraws();
    scene.Window->Render();
    const vtkIdType framePasses =
      scene.Pass->GetDepthIntervalPass()->GetNumberOfGeometryPasses() - passes;
    const vtkIdType frameDraws = scene.Mapper->GetNumberOfCrackDraws() - draws;
    std::cout << cracks << " cracks: " << framePasses << " depth passes and " << frameDraws
              << " crack draw per frame\n";
    ok = Expect(framePasses == 2 && frameDraws == 1,
           std::to_string(cracks) + " cracks cost two depth passes and one draw") &&
      ok;
  }
  return ok;
}

bool PerturbRefraction()
{
  IceTest::BlockScene scene;
  scene.Mapper->SetNumberOfCracks(2);
  scene.Mapper->SetCrackIntensity(0.0); // look at the refraction alone
  const IceTest::Image plain = scene.Render();
  scene.Mapper->CracksPerturbRefractionOn();
  const IceTest::Image perturbed = scene.Render();
  size_t different = 0;
  for (size_t p = 0; p < plain.RGB.size() / 3; ++p)
  {
    different += IceTest::PixelDifference(&plain.RGB[3 * p], &perturbed.RGB[3 * p]) > 8 ? 1 : 0;
  }
  std::cout << "crack normals in the refraction change " << different << " pixels\n";
  return Expect(different > 500, "CracksPerturbRefraction changes the refraction");
}
}

int TestIceCracks(int, char*[])
{
  bool ok = Clipping();
  ok = Seeds() && ok;
  ok = PassCount() && ok;
  ok = PerturbRefraction() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
