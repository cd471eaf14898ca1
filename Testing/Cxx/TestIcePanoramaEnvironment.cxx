// A 2D equirectangular panorama as the renderer's environment (as ParaView's skybox sets it): the
// ice converts it to a cube map, and with RefractionRatio 1 it is invisible against a vtkSkybox
// of sphere projection oriented as ParaView orients it. An sRGB panorama is shown as the skybox
// shows it, gamma-corrected (as ParaView's) or not.
#include "IceTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>

namespace
{
// Smooth colour everywhere (so that a turned or mirrored lookup shows), no sharp edge (which
// the conversion to a cube map softens by a pixel).
vtkSmartPointer<vtkTexture> MakePanorama()
{
  const int width = 512;
  const int height = 256;
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double u = (i + 0.5) / width;
      const double v = (j + 0.5) / height;
      unsigned char* t = texels->GetPointer(3 * (j * width + i));
      t[0] = static_cast<unsigned char>(127.5 + 120.0 * std::sin(8.0 * vtkMath::Pi() * u));
      t[1] = static_cast<unsigned char>(127.5 + 100.0 * std::sin(10.0 * vtkMath::Pi() * v));
      t[2] = static_cast<unsigned char>(127.5 + 100.0 * std::cos(14.0 * vtkMath::Pi() * u));
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
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
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
