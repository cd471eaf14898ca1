// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Glistening ice and snow (Liquidiced) as options of vtkIceMapper, on a large plane receding to
// the horizon: isolated bright sparkle pixels in the near, middle and far thirds (none with
// Glistening off), crisp in the distance (as bright as near ones, one pixel) and facets up close;
// the intensification where the view looks along the light; every kind of VTK light; snow whiter
// and more diffuse than ice; with vtkIcePass and vtkIceCubeMapPass too.
#include "IceTestUtilities.h"
#include "IceGlisteningScene.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIcePass.h"

#include "vtkPNGWriter.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using IceGlistening::Band;

using IceTest::Expect;

void Print(const std::string& name, const std::vector<Band>& bands)
{
  const char* names[3] = { "near", "middle", "far" };
  std::cout << name << ":\n";
  for (size_t b = 0; b < bands.size() && b < 3; ++b)
  {
    std::cout << "  " << names[b] << " third: " << bands[b].Count << " sparkles, energy "
              << bands[b].Energy << ", median contrast " << bands[b].MedianContrast
              << "/255, mean spot area " << bands[b].MeanArea << " px\n";
  }
}

// Writes the window to $VTKICE_GLISTENING_IMAGES/name.png when that is set (for review).
void Keep(vtkRenderWindow* window, const std::string& name)
{
  const char* folder = std::getenv("VTKICE_GLISTENING_IMAGES");
  if (!folder)
  {
    return;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((std::string(folder) + "/" + name + ".png").c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
}

// Sparkles in all three thirds of the receding plane, none without Glistening; distant ones as
// crisp as near ones.
bool Thirds()
{
  IceGlistening::Plane plane(480, 360, 12.0);
  const int top = plane.TopRow() - 3; // leave the plane's far edge out
  const IceTest::Image on = plane.Render();
  Keep(plane.Window, "thirds-on");
  const std::vector<Band> bands = IceGlistening::Sparkles(on, 0, top);
  Print("Glistening on (sun 35 degrees up, 120 degrees right of the view)", bands);
  plane.Mapper->GetIceProperty()->GlisteningOff();
  const std::vector<Band> off = IceGlistening::Sparkles(plane.Render(), 0, top);
  Keep(plane.Window, "thirds-off");
  Print("Glistening off", off);

  bool ok = Expect(bands[0].Count >= 20 && bands[1].Count >= 50 && bands[2].Count >= 80,
    "sparkles in the near (>= 20), middle (>= 50) and far (>= 80) thirds");
  ok = Expect(off[0].Count == 0 && off[1].Count == 0 && off[2].Count == 0,
         "no sparkles anywhere with Glistening off") &&
    ok;
  ok = Expect(bands[2].MedianContrast >= 0.6 * bands[0].MedianContrast,
         "distant sparkles are crisp: median contrast at least 60 % of the near ones'") &&
    ok;
  ok = Expect(bands[2].MeanArea <= 1.5,
         "distant sparkles are single pixels (mean spot area <= 1.5 px)") &&
    ok;
  ok = Expect(bands[0].MeanArea >= 2.0 * bands[2].MeanArea,
         "near sparkles are crack facets, not pixel noise (mean area >= twice the far one)") &&
    ok;
  return ok;
}

// The glints' light: how much brighter the plane is than without glints, and the sparkles.
struct Glints
{
  double Light = 0.0;
  int Sparkles = 0;
};

// Glints at a quarter of their default brightness, so that doubled ones do not clip at white.
Glints Measure(IceGlistening::Plane& plane, double gain, int top)
{
  plane.Mapper->GetIceProperty()->SetGlisteningAlignmentGain(gain);
  plane.Mapper->GetIceProperty()->SetGlisteningIntensity(0.0);
  const IceTest::Image plain = plane.Render();
  plane.Mapper->GetIceProperty()->SetGlisteningIntensity(0.25);
  const IceTest::Image glinting = plane.Render();
  Glints glints;
  glints.Light = IceGlistening::ExtraLight(glinting, plain, 0, top);
  for (const Band& band : IceGlistening::Sparkles(glinting, 0, top, 1))
  {
    glints.Sparkles += band.Count;
  }
  return glints;
}

// Looking along the light, the glints are intensified (AlignmentGain 2, the default) and not
// otherwise; the headlight is always aligned with the view.
bool Intensification()
{
  IceGlistening::Plane plane(400, 300, 30.0);
  const int top = plane.TopRow() - 3;
  bool ok = true;
  struct Case
  {
    const char* Name;
    double Elevation;
    double Azimuth;
    bool Headlight;
    bool Aligned;
  };
  const Case cases[3] = { { "sun behind the viewer, along the view", 30.0, 180.0, false, true },
    { "headlight", 0.0, 0.0, true, true }, { "sun from the side", 30.0, 90.0, false, false } };
  double alongTheView = 0.0;
  for (const Case& c : cases)
  {
    plane.Renderer->RemoveAllLights();
    vtkNew<vtkLight> headlight;
    if (c.Headlight)
    {
      headlight->SetLightTypeToHeadlight();
      plane.Renderer->AddLight(headlight);
    }
    else
    {
      plane.Renderer->AddLight(plane.Sun);
      plane.SetSun(c.Elevation, c.Azimuth);
    }
    const Glints single = Measure(plane, 1.0, top);
    const Glints doubled = Measure(plane, 2.0, top);
    const char* picture = c.Headlight ? "headlight" : c.Aligned ? "sun" : "side";
    Keep(plane.Window, std::string("aligned-") + picture);
    const double ratio = doubled.Light / std::max(single.Light, 1.0);
    std::cout << c.Name << ": glint light " << single.Light << " without intensification, "
              << doubled.Light << " with (x" << ratio << "); sparkles " << single.Sparkles
              << " and " << doubled.Sparkles << "\n";
    if (c.Headlight)
    {
      // VTK's headlight (light complexity 1) shines along the view: the same light as the sun
      // placed along the view (complexity 2).
      ok = Expect(std::abs(doubled.Light - alongTheView) <= 0.01 * alongTheView,
             "the headlight glints like a sun along the view (within 1 %)") &&
        ok;
    }
    else if (c.Aligned)
    {
      alongTheView = doubled.Light;
    }
    if (c.Aligned)
    {
      ok = Expect(single.Sparkles > 0 && ratio >= 1.4 && doubled.Sparkles > single.Sparkles,
             std::string(c.Name) + ": intensified (glint light x >= 1.4, more sparkles)") &&
        ok;
    }
    else
    {
      ok = Expect(single.Sparkles > 0 && doubled.Light == single.Light,
             std::string(c.Name) + ": glints present, not intensified (same light)") &&
        ok;
    }
  }
  return ok;
}

// Every kind of VTK light gives glints; without lighting there are none.
bool Lights()
{
  IceGlistening::Plane plane(400, 300, 20.0);
  const int top = plane.TopRow() - 3;
  auto count = [&]() {
    int n = 0;
    for (const Band& band : IceGlistening::Sparkles(plane.Render(), 0, top, 1))
    {
      n += band.Count;
    }
    return n;
  };
  bool ok = true;
  plane.Renderer->RemoveAllLights();
  vtkNew<vtkLight> first;
  vtkNew<vtkLight> second;
  first->SetLightTypeToSceneLight();
  first->SetPosition(1.0, 1.0, -1.0);
  first->SetFocalPoint(0.0, 0.0, 0.0);
  second->SetLightTypeToSceneLight();
  second->SetPosition(-1.0, 0.8, 1.0);
  second->SetFocalPoint(0.0, 0.0, 0.0);
  second->SetIntensity(0.7);
  plane.Renderer->AddLight(first);
  plane.Renderer->AddLight(second);
  const int directional = count();
  std::cout << "two directional lights: " << directional << " sparkles\n";
  ok = Expect(directional > 50, "two directional lights give sparkles") && ok;

  // A spot light 6 above the ground at 8 in front, pointing down with a 30 degree cone: it lights
  // the ground up to 8 + 6 tan 30 in front, so no glint lies beyond that row.
  plane.Renderer->RemoveAllLights();
  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->PositionalOn();
  spot->SetPosition(0.0, 6.0, -8.0);
  spot->SetFocalPoint(0.0, 0.0, -8.0);
  spot->SetConeAngle(30.0);
  spot->SetAttenuationValues(1.0, 0.0, 0.0);
  plane.Renderer->AddLight(spot);
  plane.Renderer->SetWorldPoint(0.0, 0.0, -8.0 - 6.0 * std::tan(vtkMath::Pi() / 6.0), 1.0);
  plane.Renderer->WorldToDisplay();
  const int coneEdge = static_cast<int>(std::ceil(plane.Renderer->GetDisplayPoint()[1])) + 2;
  const IceTest::Image spotImage = plane.Render();
  Keep(plane.Window, "lights-positional");
  const std::vector<Band> spotBands = IceGlistening::Sparkles(spotImage, 0, top, 1);
  const std::vector<Band> beyond = IceGlistening::Sparkles(spotImage, coneEdge, top, 1);
  std::cout << "a positional spot light: " << spotBands[0].Count << " sparkles, " << beyond[0].Count
            << " beyond its cone (rows " << coneEdge << " to " << top << ")\n";
  ok = Expect(spotBands[0].Count > 20 && beyond[0].Count == 0,
         "a positional spot light gives sparkles inside its cone only") &&
    ok;

  plane.Actor->GetProperty()->LightingOff();
  const int unlit = count();
  plane.Actor->GetProperty()->LightingOn();
  std::cout << "lighting off: " << unlit << " sparkles\n";
  ok = Expect(unlit == 0, "no lighting, no glints") && ok;
  return ok;
}

// Mean luminance and mean chroma (largest minus smallest channel) over the pixels of `mask`.
void Tone(
  const IceTest::Image& image, const std::vector<bool>& mask, double& luminance, double& chroma)
{
  luminance = chroma = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p)
  {
    if (mask[p])
    {
      const unsigned char* c = &image.RGB[3 * p];
      luminance += IceGlistening::Luminance(c);
      chroma += std::max({ c[0], c[1], c[2] }) - std::min({ c[0], c[1], c[2] });
      ++n;
    }
  }
  luminance /= std::max<size_t>(n, 1);
  chroma /= std::max<size_t>(n, 1);
}

// Snow (SnowAmount 1) against ice (0) on a sphere lit from the right: snow is whiter (less
// coloured, brighter where lit) and diffuse (its lit side much brighter than its shadow side, where
// ice shows the environment all round); 0.5 lies between.
bool SnowAndIce()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->GetIceProperty()->GlisteningOn();
  mapper->GetIceProperty()->SetGlisteningScale(0.02);
  mapper->GetIceProperty()->SetIceColor(0.75, 0.85, 0.95);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetEnvironmentTexture(IceGlistening::ClearSky(128));
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(1.0, 0.3, 0.2);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(240, 240);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 3.2);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();

  // Pixels of the sphere's left (shadow) and right (lit) thirds, 3 px inside the silhouette.
  const double center[3] = { 0.0, 0.0, 0.0 };
  window->Render();
  const std::vector<bool> inside = IceTest::SphereInterior(renderer, center, 0.5, 3);
  std::vector<bool> left(inside.size(), false);
  std::vector<bool> right(inside.size(), false);
  for (size_t p = 0; p < inside.size(); ++p)
  {
    const int x = static_cast<int>(p % 240);
    left[p] = inside[p] && x < 100;
    right[p] = inside[p] && x >= 140;
  }
  double luminance[3];
  double chroma[3];
  double lit[3];
  double shadow[3];
  const double amounts[3] = { 0.0, 0.5, 1.0 };
  for (int i = 0; i < 3; ++i)
  {
    mapper->GetIceProperty()->SetSnowAmount(amounts[i]);
    const IceTest::Image image = IceTest::Capture((window->Render(), window.GetPointer()));
    Keep(window, "snow-" + std::to_string(i));
    Tone(image, inside, luminance[i], chroma[i]);
    double unused;
    Tone(image, right, lit[i], unused);
    Tone(image, left, shadow[i], unused);
    std::cout << "SnowAmount " << amounts[i] << ": mean luminance " << luminance[i]
              << ", mean chroma " << chroma[i] << ", lit side " << lit[i] << ", shadow side "
              << shadow[i] << "\n";
  }
  bool ok = Expect(chroma[2] < chroma[0] - 15.0 && lit[2] > lit[0] + 10.0,
    "snow is whiter than ice: less coloured (chroma lower by > 15/255), brighter where lit "
    "(by > 10/255)");
  const double contrast[3] = { lit[0] - shadow[0], lit[1] - shadow[1], lit[2] - shadow[2] };
  ok = Expect(contrast[2] > 2.0 * std::abs(contrast[0]) && contrast[2] > 60.0,
         "snow is diffuse: its lit side is brighter than its shadow side by > 60/255, more than "
         "twice as much as for ice") &&
    ok;
  ok = Expect(chroma[1] < chroma[0] && chroma[1] > chroma[2] && contrast[1] > contrast[0] &&
           contrast[1] < contrast[2],
         "SnowAmount 0.5 lies between ice and snow (chroma, lit against shadow side)") &&
    ok;
  return ok;
}

// The cracks are fixed to the surface: moving the plane and the camera together (actor
// position) leaves the picture as it was, while moving the camera alone by 0.2 changes it.
bool FixedToTheSurface()
{
  IceGlistening::Plane plane(400, 300, 20.0);
  const IceTest::Image before = plane.Render();
  const double offset[3] = { 37.3, 0.0, -12.1 };
  plane.Actor->SetPosition(offset[0], offset[1], offset[2]);
  vtkCamera* camera = plane.Renderer->GetActiveCamera();
  double position[3];
  double focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->SetPosition(position[0] + offset[0], position[1], position[2] + offset[2]);
  camera->SetFocalPoint(focal[0] + offset[0], focal[1], focal[2] + offset[2]);
  const IceTest::Image moved = plane.Render();
  camera->SetPosition(position[0] + offset[0] + 0.2, position[1], position[2] + offset[2]);
  camera->SetFocalPoint(focal[0] + offset[0] + 0.2, focal[1], focal[2] + offset[2]);
  const IceTest::Image elsewhere = plane.Render();
  size_t same = 0;
  size_t changed = 0;
  for (size_t p = 0; p < before.RGB.size() / 3; ++p)
  {
    same += IceTest::PixelDifference(&before.RGB[3 * p], &moved.RGB[3 * p]) > 8 ? 1 : 0;
    changed += IceTest::PixelDifference(&moved.RGB[3 * p], &elsewhere.RGB[3 * p]) > 8 ? 1 : 0;
  }
  std::cout << "plane and camera moved together: " << same
            << " pixels differ by more than 8/255; the camera alone moved by 0.2: " << changed
            << "\n";
  return Expect(same <= 20 && changed > 500,
    "cracks are fixed to the surface (<= 20 pixels change when plane and camera move together, "
    "> 500 when the camera alone moves by 0.2)");
}

// The glistening layer works on the paper's ice too: two-sided refraction and a dynamic cube map.
bool WithPasses()
{
  IceGlistening::Plane plane(400, 300, 12.0);
  const int top = plane.TopRow() - 3;
  vtkNew<vtkIcePass> pass;
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  cubeMaps->SetFaceSize(64);
  pass->SetCubeMapPass(cubeMaps);
  plane.Renderer->SetPass(pass);
  const std::vector<Band> bands = IceGlistening::Sparkles(plane.Render(), 0, top);
  Keep(plane.Window, "passes");
  Print("with vtkIcePass and vtkIceCubeMapPass", bands);
  return Expect(bands[0].Count > 0 && bands[1].Count > 0 && bands[2].Count > 0,
    "with vtkIcePass and vtkIceCubeMapPass: sparkles in all thirds");
}
}

int TestIceGlistening(int, char*[])
{
  bool ok = Thirds();
  ok = Intensification() && ok;
  ok = Lights() && ok;
  ok = SnowAndIce() && ok;
  ok = FixedToTheSurface() && ok;
  ok = WithPasses() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
