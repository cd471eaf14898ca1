// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// A 2D equirectangular panorama as the renderer's environment (as ParaView's skybox sets it): the
// ice converts it to a cube map, and with RefractionRatio 1 it is invisible against a vtkSkybox
// of sphere projection oriented as ParaView orients it. An sRGB panorama is shown as the skybox
// shows it, gamma-corrected (as ParaView's) or not; so is a float (HDR) panorama.
#include "IceTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTexture.h"
#include "vtkDataArray.h"

#include <cmath>
#include <iostream>

namespace
{
// Smooth colour everywhere (so that a turned or mirrored lookup shows), no sharp edge (which
// the conversion to a cube map softens by a pixel).
// 8-bit, or float with values up to 1.5 (an HDR panorama).
vtkSmartPointer<vtkTexture> MakePanorama(bool hdr = false)
{
  const int width = 512;
  const int height = 256;
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(hdr ? VTK_FLOAT : VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* texels = image->GetPointData()->GetScalars();
  const double scale = hdr ? 1.5 / 255.0 : 1.0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double u = (i + 0.5) / width;
      const double v = (j + 0.5) / height;
      const vtkIdType t = j * width + i;
      texels->SetComponent(
        t, 0, scale * static_cast<int>(127.5 + 120.0 * std::sin(8.0 * vtkMath::Pi() * u)));
      texels->SetComponent(
        t, 1, scale * static_cast<int>(127.5 + 100.0 * std::sin(10.0 * vtkMath::Pi() * v)));
      texels->SetComponent(
        t, 2, scale * static_cast<int>(127.5 + 100.0 * std::cos(14.0 * vtkMath::Pi() * u)));
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->SetColorModeToDirectScalars(); // float texels are colours, not values to map
  return texture;
}
}

int TestIcePanoramaEnvironment(int, char*[])
{
  vtkSmartPointer<vtkTexture> panorama = MakePanorama();
  bool ok = IceTest::ReportInvisibility("panorama", IceTest::MeasurePanoramaInvisibility(panorama));

  vtkSmartPointer<vtkTexture> srgb = MakePanorama();
  srgb->UseSRGBColorSpaceOn();
  ok = IceTest::ReportInvisibility("sRGB panorama, gamma-corrected skybox",
         IceTest::MeasurePanoramaInvisibility(srgb, true)) &&
    ok;
  ok = IceTest::ReportInvisibility("sRGB panorama, skybox without gamma correction",
         IceTest::MeasurePanoramaInvisibility(srgb, false)) &&
    ok;

  // An HDR (float) panorama, as ParaView's skybox shows an .hdr image: gamma-corrected.
  vtkSmartPointer<vtkTexture> hdr = MakePanorama(true);
  ok = IceTest::ReportInvisibility(
         "HDR panorama, gamma-corrected skybox", IceTest::MeasurePanoramaInvisibility(hdr, true)) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
