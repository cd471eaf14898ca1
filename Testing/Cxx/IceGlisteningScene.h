// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Shared by the glistening tests: a clear-sky cube map without bright spots, a large glistening
// plane receding to the horizon, and the sparkle detector.
#ifndef IceGlisteningScene_h
#define IceGlisteningScene_h

#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace IceGlistening
{
// A sky from pale at the horizon to blue at the zenith over dark ground, smooth everywhere: no sun
// or edge the sparkle detector could take for a glint.
inline vtkSmartPointer<vtkTexture> ClearSky(int size)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->CubeMapOn();
  for (int face = 0; face < 6; ++face)
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(size, size, 1);
    vtkNew<vtkUnsignedCharArray> pixels;
    pixels->SetNumberOfComponents(3);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        double d[3];
        vtkIceCubeMapSource::TexelDirection(face, i, j, size, d);
        vtkMath::Normalize(d);
        double rgb[3];
        const double horizon[3] = { 0.78, 0.86, 0.95 };
        if (d[1] >= 0.0)
        {
          const double zenith[3] = { 0.16, 0.34, 0.72 };
          const double t = std::pow(d[1], 0.6);
          for (int c = 0; c < 3; ++c)
          {
            rgb[c] = horizon[c] + t * (zenith[c] - horizon[c]);
          }
        }
        else
        {
          const double ground[3] = { 0.05, 0.08, 0.12 };
          const double t = std::min(1.0, -8.0 * d[1]);
          for (int c = 0; c < 3; ++c)
          {
            rgb[c] = 0.6 * horizon[c] + t * (ground[c] - 0.6 * horizon[c]);
          }
        }
        for (int c = 0; c < 3; ++c)
        {
          pixels->SetTypedComponent(static_cast<vtkIdType>(j) * size + i, c,
            static_cast<unsigned char>(std::round(255.0 * rgb[c])));
        }
      }
    }
    image->GetPointData()->SetScalars(pixels);
    texture->SetInputDataObject(face, image);
  }
  texture->InterpolateOn();
  texture->MipmapOff();
  texture->EdgeClampOn();
  texture->SetColorModeToDirectScalars();
  return texture;
}

// Direction towards a distant light: elevation above the ground, azimuth from -Z (the camera's
// view direction) towards +X, in degrees.
inline void SunDirection(double elevation, double azimuth, double direction[3])
{
  const double e = vtkMath::RadiansFromDegrees(elevation);
  const double a = vtkMath::RadiansFromDegrees(azimuth);
  direction[0] = std::cos(e) * std::sin(a);
  direction[1] = std::sin(e);
  direction[2] = -std::cos(e) * std::cos(a);
}

// A 4 km square of glistening ice at y = 0, seen from eye height 1.7 looking along -Z, tilted
// down by `pitch` degrees; lit by one scene light (a distant sun).
struct Plane
{
  vtkNew<vtkPlaneSource> Source;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkLight> Sun;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkTexture> Sky;
  vtkNew<vtkSkybox> Skybox;

  // In a window of its own.
  Plane(int width, int height, double pitch)
    : Plane(vtkSmartPointer<vtkRenderWindow>::New(), pitch)
  {
    this->Window->SetSize(width, height);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
  }

  // In `window` (whose size the caller sets), over the whole window until SetViewport.
  Plane(vtkRenderWindow* window, double pitch)
    : Window(window)
  {
    this->Source->SetOrigin(-2000.0, 0.0, 2000.0);
    this->Source->SetPoint1(2000.0, 0.0, 2000.0);
    this->Source->SetPoint2(-2000.0, 0.0, -2000.0);
    this->Source->SetResolution(64, 64);
    this->Mapper->SetInputConnection(this->Source->GetOutputPort());
    IceTest::UseCleanOptics(this->Mapper); // the glistening alone on the paper's ice
    this->Mapper->GetIceProperty()->GlisteningOn();
    this->Mapper->GetIceProperty()->SetIceColor(0.75, 0.85, 0.95);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Sky = ClearSky(128);
    this->Renderer->SetEnvironmentTexture(this->Sky);
    this->Skybox->SetTexture(this->Sky);
    this->Renderer->AddActor(this->Skybox);
    this->Sun->SetLightTypeToSceneLight();
    this->Renderer->AddLight(this->Sun);
    this->SetSun(35.0, 120.0);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetViewAngle(40.0);
    this->Look(1.7, pitch);
  }

  void Look(double eyeHeight, double pitch)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    const double p = vtkMath::RadiansFromDegrees(pitch);
    camera->SetPosition(0.0, eyeHeight, 0.0);
    camera->SetFocalPoint(0.0, eyeHeight - std::sin(p), -std::cos(p));
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetClippingRange(0.02 * eyeHeight, 6000.0);
  }

  void SetSun(double elevation, double azimuth)
  {
    double d[3];
    SunDirection(elevation, azimuth, d);
    this->Sun->SetPosition(d);
    this->Sun->SetFocalPoint(0.0, 0.0, 0.0);
  }

  IceTest::Image Render()
  {
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }

  // The window row of the plane's far edge (about the horizon): rows below it show the plane.
  int TopRow()
  {
    this->Renderer->SetWorldPoint(0.0, 0.0, -2000.0, 1.0);
    this->Renderer->WorldToDisplay();
    double display[3];
    this->Renderer->GetDisplayPoint(display);
    return static_cast<int>(std::floor(display[1]));
  }
};

inline double Luminance(const unsigned char* p)
{
  return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

// Sparkles of one band of rows.
struct Band
{
  int Count = 0;       // isolated bright pixels
  double Energy = 0.0; // sum of their contrast (luminance above the local background)
  double MedianContrast = 0.0;
  double MeanArea = 0.0; // mean size in pixels of the bright spot around each
};

// A sparkle is an isolated bright pixel: a local maximum of luminance over its 3x3 neighbourhood
// (ties go to the first pixel in scan order, so a flat top counts once) that is at least
// `contrast` above the median of its 9x9 window, the local background. Its area is the number of
// pixels of its 8-connected spot at least contrast / 2 above that background (within 15x15).
// Rows [y0, y1) are split into `bands` equal bands, bottom (near) first.
inline std::vector<Band> Sparkles(
  const IceTest::Image& image, int y0, int y1, int bands = 3, double contrast = 50.0)
{
  const int w = image.Width;
  std::vector<double> lum(static_cast<size_t>(w) * image.Height);
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      lum[static_cast<size_t>(y) * w + x] = Luminance(image.At(x, y));
    }
  }
  auto L = [&](int x, int y) { return lum[static_cast<size_t>(y) * w + x]; };
  std::vector<Band> result(bands);
  std::vector<std::vector<double>> contrasts(bands);
  std::vector<double> window;
  y0 = std::max(y0, 4);
  y1 = std::min(y1, image.Height - 4);
  for (int y = y0; y < y1; ++y)
  {
    const int band = std::min(bands - 1, (y - y0) * bands / std::max(1, y1 - y0));
    for (int x = 4; x < w - 4; ++x)
    {
      const double v = L(x, y);
      bool peak = true;
      for (int dy = -1; dy <= 1 && peak; ++dy)
      {
        for (int dx = -1; dx <= 1 && peak; ++dx)
        {
          if (dx == 0 && dy == 0)
          {
            continue;
          }
          const double n = L(x + dx, y + dy);
          const bool earlier = dy < 0 || (dy == 0 && dx < 0);
          peak = earlier ? v > n : v >= n;
        }
      }
      if (!peak)
      {
        continue;
      }
      window.clear();
      for (int dy = -4; dy <= 4; ++dy)
      {
        for (int dx = -4; dx <= 4; ++dx)
        {
          window.push_back(L(x + dx, y + dy));
        }
      }
      std::nth_element(window.begin(), window.begin() + 40, window.end());
      const double background = window[40];
      if (v - background < contrast)
      {
        continue;
      }
      // Area of the spot: flood fill within 15x15.
      std::vector<bool> seen(15 * 15, false);
      std::vector<std::pair<int, int>> stack{ { x, y } };
      seen[7 * 15 + 7] = true;
      int area = 0;
      while (!stack.empty())
      {
        const auto p = stack.back();
        stack.pop_back();
        ++area;
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int qx = p.first + dx;
            const int qy = p.second + dy;
            const int i = qx - x + 7;
            const int j = qy - y + 7;
            if (i < 0 || i >= 15 || j < 0 || j >= 15 || qx < 0 || qx >= w || qy < 0 ||
              qy >= image.Height || seen[j * 15 + i])
            {
              continue;
            }
            seen[j * 15 + i] = true;
            if (L(qx, qy) - background >= 0.5 * contrast)
            {
              stack.emplace_back(qx, qy);
            }
          }
        }
      }
      Band& b = result[band];
      ++b.Count;
      b.Energy += v - background;
      b.MeanArea += area;
      contrasts[band].push_back(v - background);
    }
  }
  for (int b = 0; b < bands; ++b)
  {
    if (result[b].Count > 0)
    {
      result[b].MeanArea /= result[b].Count;
      std::vector<double>& c = contrasts[b];
      std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
      result[b].MedianContrast = c[c.size() / 2];
    }
  }
  return result;
}

// Sum over rows [y0, y1) of how much brighter `image` is than `reference` (luminance, 0..255).
inline double ExtraLight(
  const IceTest::Image& image, const IceTest::Image& reference, int y0, int y1)
{
  double sum = 0.0;
  for (int y = std::max(0, y0); y < std::min(y1, image.Height); ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      sum += std::max(0.0, Luminance(image.At(x, y)) - Luminance(reference.At(x, y)));
    }
  }
  return sum;
}
}

#endif
