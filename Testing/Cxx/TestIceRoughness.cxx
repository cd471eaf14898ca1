// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Frost (Roughness) against the brute-force integral: an ice sphere with IndexOfRefraction 1 and
// no reflection passes every view ray straight through, so a rough sphere must show at each
// interior pixel the environment averaged over the GGX lobe around the view ray:
// vtkIceOpticsReference::PrefilteredEnvironment summed over every texel of the skybox's cube map.
// Checked at the roughness of each prefiltered level, on a grid of interior pixels; with
// --dynamic the ice samples a dynamic cube map (vtkIceCubeMapPass) of the same skybox instead.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkImageData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Every texel of the environment cube map, with its world direction and solid angle.
std::vector<vtkIceOpticsReference::EnvironmentTexel> EnvironmentTexels(vtkTexture* environment)
{
  std::vector<vtkIceOpticsReference::EnvironmentTexel> texels;
  for (int face = 0; face < 6; ++face)
  {
    auto* image = vtkImageData::SafeDownCast(environment->GetInputDataObject(face, 0));
    int dims[3];
    image->GetDimensions(dims);
    const int size = dims[0];
    const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
    const int components = image->GetNumberOfScalarComponents();
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        double direction[3];
        vtkIceCubeMapSource::TexelDirection(face, i, j, size, direction);
        const glm::dvec3 d(direction[0], direction[1], direction[2]);
        // The texel's area on the unit cube, (2 / size)^2, seen from the centre.
        const double length = glm::length(d);
        const unsigned char* rgb = pixels + components * (j * size + i);
        texels.push_back({ d / length, 4.0 / (size * size) / (length * length * length),
          glm::dvec3(rgb[0], rgb[1], rgb[2]) });
      }
    }
  }
  return texels;
}
}

int TestIceRoughness(int argc, char* argv[])
{
  IceTest::ClearSphereScene scene;
  const auto texels = EnvironmentTexels(scene.Renderer->GetEnvironmentTexture());
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  if (argc > 1 && std::string(argv[1]) == "--dynamic")
  {
    cubeMaps->SetFaceSize(128);
    scene.Pass->SetCubeMapPass(cubeMaps);
  }
  bool ok = true;
  for (const double roughness : { 0.25, 0.5, 0.75, 1.0 })
  {
    scene.Mapper->GetIceProperty()->SetRoughness(roughness);
    const IceTest::Image image = scene.Render();
    std::vector<double> differences;
    for (int y = 0; y < image.Height; y += 6)
    {
      for (int x = 0; x < image.Width; x += 6)
      {
        if (!scene.Interior[static_cast<size_t>(y) * image.Width + x])
        {
          continue;
        }
        double origin[3];
        double direction[3];
        IceTest::PixelRay(scene.Renderer, x, y, origin, direction);
        const glm::dvec3 expected = vtkIceOpticsReference::PrefilteredEnvironment(
          glm::dvec3(direction[0], direction[1], direction[2]), roughness, texels);
        const unsigned char* rendered = image.At(x, y);
        double largest = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          largest = std::max(largest, std::abs(rendered[c] - expected[c]));
        }
        differences.push_back(largest);
      }
    }
    const IceTest::Stats stats = IceTest::Summarize(differences);
    std::cout << "roughness " << roughness << ": " << stats.Count
              << " pixels, |rendered - integral| mean " << stats.Mean << "/255, p99 " << stats.P99
              << "/255, max " << stats.Max << "/255\n";
    ok = IceTest::Expect(stats.Count >= 300 && stats.Max <= 3.0,
           "roughness " + std::to_string(roughness) + " within 3/255 of the GGX integral") &&
      ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
