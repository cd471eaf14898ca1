// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The milky core (MilkyCoreRadius) against the CPU reference: an ice sphere with
// IndexOfRefraction 1, no reflection and no absorption passes every view ray straight through,
// so each interior pixel must be the skybox behind it seen through the core: mixed towards the
// core's colour by 1 - exp(-depth), depth = vtkIceOpticsReference::CoreOpticalDepth of the ray's
// chord in the core's frame (the sphere's bounds, scaled by the radius) times its CoreStreaks. The centre is whiter
// than the rim; a core of radius 0 changes no pixel; the paper passes draw none and say so.
#include "IceTestUtilities.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceMapper.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
const double Milkiness = 0.8;
const double CoreRadius = 0.6;

struct Comparison
{
  IceTest::Stats Stats;
  double CentreWhiteness = 0.0; // mean mix towards the core's colour, inner third of the disk
  double RimWhiteness = 0.0;    // the same, outer third
};

// Every interior pixel: the background behind it seen through the core along its chord; how
// white the core makes the inner and the outer third of the disk.
Comparison CompareWithReference(IceTest::ClearSphereScene& scene, const IceTest::Image& image)
{
  double frameCentre[3];
  double frameScale[3];
  vtkIceInteriorLook::CoreFrame(scene.Bounds, CoreRadius, frameCentre, frameScale);
  const glm::dvec3 centre(frameCentre[0], frameCentre[1], frameCentre[2]);
  const glm::dvec3 scale(frameScale[0], frameScale[1], frameScale[2]);
  const double density = vtkIceInteriorLook::CoreDensity(Milkiness);
  double whiteness[2] = { 0.0, 0.0 };
  int counted[2] = { 0, 0 };
  Comparison comparison;
  comparison.Stats = scene.CompareAlongChords(
    image, [&](int x, int y, const glm::dvec3& entry, const glm::dvec3& e, double chord) {
      const glm::dvec3 origin = (entry - centre) * scale;
      const double covered = 1.0 -
        std::exp(-vtkIceOpticsReference::CoreOpticalDepth(origin, e * scale, chord, density) *
          vtkIceOpticsReference::CoreStreaks(origin, e * scale));
      // The ray's closest approach to the centre: the inner or the outer third of the disk.
      const double miss = glm::length(glm::cross(entry, e));
      if (miss < 1.0 / 3.0 || miss > 2.0 / 3.0)
      {
        whiteness[miss < 1.0 / 3.0 ? 0 : 1] += covered;
        ++counted[miss < 1.0 / 3.0 ? 0 : 1];
      }
      const unsigned char* behind = scene.Background.At(x, y);
      const glm::dvec3 background(behind[0], behind[1], behind[2]);
      const glm::dvec3 core(vtkIceInteriorLook::CoreColour[0], vtkIceInteriorLook::CoreColour[1],
        vtkIceInteriorLook::CoreColour[2]);
      return background + covered * (255.0 * core - background);
    });
  comparison.CentreWhiteness = whiteness[0] / std::max(counted[0], 1);
  comparison.RimWhiteness = whiteness[1] / std::max(counted[1], 1);
  return comparison;
}
}

int TestIceMilkyCore(int, char*[])
{
  IceTest::ClearSphereScene scene;
  scene.Mapper->GetIceProperty()->SetMilkiness(Milkiness);
  const IceTest::Image noCore = scene.Render();

  bool ok = true;
  scene.Mapper->GetIceProperty()->SetMilkyCoreRadius(CoreRadius);
  const Comparison comparison = CompareWithReference(scene, scene.Render());
  ok = IceTest::ReportReference("the milky core along the chord", comparison.Stats, 20000) && ok;
  std::cout << "whitening: centre " << comparison.CentreWhiteness << ", rim "
            << comparison.RimWhiteness << "\n";
  if (!(comparison.CentreWhiteness > 0.5 &&
        comparison.CentreWhiteness > 2.0 * comparison.RimWhiteness))
  {
    std::cerr << "The core's centre should be whiter than half and than twice its rim\n";
    ok = false;
  }

  // Radius 0: no core, the picture of a mapper never given one.
  scene.Mapper->GetIceProperty()->SetMilkyCoreRadius(0.0);
  const size_t changed = IceTest::CountDiffering(noCore, scene.Render(), 0);
  if (changed != 0)
  {
    std::cerr << "MilkyCoreRadius 0 changed " << changed << " pixels\n";
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
