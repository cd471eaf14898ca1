// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Two-sided refraction measured against the truth. An ice sphere, and an ellipsoid (the sphere
// scaled by its actor), over the DirectionTest cube map (a smooth colour per direction, so a
// colour error is a direction error) are rendered with the paper's blended normals (eq 1), with
// the exit point (TwoSidedExitPoint) and one-sided; every interior pixel is compared with exact
// double refraction (vtkIceOpticsReference::EllipsoidDoubleRefraction; pixels whose light is
// totally reflected inside are left out), and the three errors are printed. The exit
// point must be closer to the truth than the paper's method (by half the mean error at least,
// and in p99), and match its own CPU reference (ExitPointDirection fed with
// the sphere's analytic back faces) within the reference bounds (mean <= 2/255, p99 <= 8/255).
// With every effect on (cracks perturbing the refraction, air, bumps, glistening, a dynamic cube
// map) it renders without an OpenGL error. With VTKICE_FIGURE set to a .png path the test writes
// the figure of Documentation/optics.md there.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using glm::dvec3;
using vtkIceOpticsReference::BackTexel;

using IceTest::Expect;

struct Scene
{
  vtkNew<vtkIceCubeMapSource> Pattern;
  vtkNew<vtkTexture> Environment;
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Ice;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
  const double Center[3] = { 0.0, 0.0, 0.0 };
  dvec3 Radii;

  explicit Scene(const dvec3& radii)
    : Radii(radii)
  {
    this->Pattern->SetPatternToDirectionTest();
    this->Pattern->SetFaceSize(256);
    this->Pattern->ConfigureTexture(this->Environment);
    this->Sphere->SetRadius(1.0);
    this->Ice->SetScale(radii.x, radii.y, radii.z);
    this->Sphere->SetThetaResolution(256);
    this->Sphere->SetPhiResolution(256);
    this->Mapper->SetInputConnection(this->Sphere->GetOutputPort());
    IceTest::UseCleanOptics(this->Mapper);
    this->Ice->SetMapper(this->Mapper);
    this->Renderer->SetEnvironmentTexture(this->Environment);
    this->Renderer->AddActor(this->Ice);
    this->Renderer->SetPass(this->Pass);
    this->Window->SetSize(300, 300);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.9, 1.2, 3.6);
    this->Renderer->ResetCameraClippingRange();
  }

  IceTest::Image Render()
  {
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }

  // The back-face texel at window pixel (x, y), from the analytic sphere.
  BackTexel BackAt(int x, int y) const
  {
    BackTexel texel;
    const int* size = this->Window->GetSize();
    if (x < 0 || y < 0 || x >= size[0] || y >= size[1])
    {
      return texel;
    }
    dvec3 origin;
    dvec3 e;
    double tNear;
    double tFar;
    if (!this->Hit(x, y, origin, e, tNear, tFar))
    {
      return texel;
    }
    const dvec3 back = origin + tFar * e;
    const vtkIceOpticsReference::View view = this->View();
    texel.Normal = vtkIceOpticsReference::EllipsoidNormal(back, this->CenterVector(), this->Radii);
    texel.Depth = glm::dot(back - view.Position, view.Direction);
    return texel;
  }

  // The back-face texel under a world point, as the shader finds it.
  BackTexel BackUnder(const dvec3& p) const
  {
    this->Renderer->SetWorldPoint(p.x, p.y, p.z, 1.0);
    this->Renderer->WorldToDisplay();
    double display[3];
    this->Renderer->GetDisplayPoint(display);
    const int* size = this->Window->GetSize();
    const int x = std::min(std::max(static_cast<int>(std::floor(display[0])), 0), size[0] - 1);
    const int y = std::min(std::max(static_cast<int>(std::floor(display[1])), 0), size[1] - 1);
    return this->BackAt(x, y);
  }

  dvec3 CenterVector() const { return dvec3(this->Center[0], this->Center[1], this->Center[2]); }

  // The ray through pixel (x, y) (unit e) and its near and far distances to the ellipsoid.
  bool Hit(int x, int y, dvec3& origin, dvec3& e, double& tNear, double& tFar) const
  {
    double o[3];
    double d[3];
    IceTest::PixelRay(this->Renderer, x, y, o, d);
    origin = dvec3(o[0], o[1], o[2]);
    e = glm::normalize(dvec3(d[0], d[1], d[2]));
    return vtkIceOpticsReference::IntersectEllipsoid(
             origin, e, this->CenterVector(), this->Radii, tNear, tFar) &&
      tNear > 0.0;
  }

  // Pixels whose ray and those of every pixel within `margin` hit the ellipsoid.
  std::vector<bool> Interior(int margin) const
  {
    const int* size = this->Window->GetSize();
    std::vector<bool> hit(static_cast<size_t>(size[0]) * size[1]);
    for (int y = 0; y < size[1]; ++y)
    {
      for (int x = 0; x < size[0]; ++x)
      {
        dvec3 o;
        dvec3 e;
        double n;
        double f;
        hit[static_cast<size_t>(y) * size[0] + x] = this->Hit(x, y, o, e, n, f);
      }
    }
    std::vector<bool> interior(hit.size(), false);
    for (int y = margin; y < size[1] - margin; ++y)
    {
      for (int x = margin; x < size[0] - margin; ++x)
      {
        bool all = true;
        for (int dy = -margin; dy <= margin && all; ++dy)
        {
          for (int dx = -margin; dx <= margin && all; ++dx)
          {
            all = hit[static_cast<size_t>(y + dy) * size[0] + x + dx];
          }
        }
        interior[static_cast<size_t>(y) * size[0] + x] = all;
      }
    }
    return interior;
  }

  vtkIceOpticsReference::View View() const
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    vtkIceOpticsReference::View view;
    view.Position =
      dvec3(camera->GetPosition()[0], camera->GetPosition()[1], camera->GetPosition()[2]);
    const double* d = camera->GetDirectionOfProjection();
    view.Direction = dvec3(d[0], d[1], d[2]);
    return view;
  }
};

// Per interior pixel: the exact colour (double refraction) and the exit point's CPU reference.
struct Expected
{
  std::vector<bool> Interior;
  std::vector<dvec3> Exact;
  std::vector<dvec3> ExitPoint;
};

Expected Evaluate(Scene& scene)
{
  Expected expected;
  const int* size = scene.Window->GetSize();
  expected.Interior = scene.Interior(3);
  expected.Exact.assign(expected.Interior.size(), dvec3(0.0));
  expected.ExitPoint.assign(expected.Interior.size(), dvec3(0.0));
  const IceTest::Environment environment = IceTest::PatternEnvironment(scene.Pattern);
  const vtkIceOpticsReference::Material material;
  const dvec3 center = scene.CenterVector();
  const vtkIceOpticsReference::View view = scene.View();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const size_t i = static_cast<size_t>(y) * size[0] + x;
      if (!expected.Interior[i])
      {
        continue;
      }
      dvec3 o;
      dvec3 e;
      double tNear;
      double tFar;
      scene.Hit(x, y, o, e, tNear, tFar);
      const dvec3 front = o + tNear * e;
      dvec3 nFront;
      dvec3 exitDirection;
      // Light totally reflected inside: no exact colour here (NaN: left out of the errors).
      expected.Exact[i] = vtkIceOpticsReference::EllipsoidDoubleRefraction(o, e, center,
                            scene.Radii, material.RefractionRatio, nFront, exitDirection)
        ? 255.0 *
          vtkIceOpticsReference::ShadeWithDirection(e, nFront, exitDirection, material, environment)
        : dvec3(nan);
      nFront = vtkIceOpticsReference::EllipsoidNormal(front, center, scene.Radii);
      const dvec3 approximated =
        vtkIceOpticsReference::ExitPointDirection(e, front, nFront, material.RefractionRatio,
          scene.BackAt(x, y), view, [&scene](const dvec3& p) { return scene.BackUnder(p); });
      expected.ExitPoint[i] = 255.0 *
        vtkIceOpticsReference::ShadeWithDirection(e, nFront, approximated, material, environment);
    }
  }
  return expected;
}

// Largest channel error of every interior pixel of `image` against `colours` (NaN skipped), and
// the per-pixel errors (0 outside).
IceTest::Stats Errors(const IceTest::Image& image, const Expected& expected,
  const std::vector<dvec3>& colours, std::vector<double>& perPixel)
{
  std::vector<double> errors;
  perPixel.assign(colours.size(), 0.0);
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * image.Width + x;
      const dvec3& c = colours[i];
      if (!expected.Interior[i] || std::isnan(c.x + c.y + c.z))
      {
        continue;
      }
      double worst = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(image.At(x, y)[k] - c[k]));
      }
      perPixel[i] = worst;
      errors.push_back(worst);
    }
  }
  return IceTest::Summarize(errors);
}

std::string Describe(const IceTest::Stats& s)
{
  return "mean " + std::to_string(s.Mean) + "/255, p99 " + std::to_string(s.P99) + "/255, max " +
    std::to_string(s.Max) + "/255 over " + std::to_string(s.Count) + " pixels";
}

// The figure: renderings on top (exact on the CPU, paper, exit point, one-sided), their errors
// against the exact colours below (x2, white = 128/255 or more).
void WriteFigure(const char* path, const IceTest::Image& exact,
  const std::vector<IceTest::Image>& images, const std::vector<std::vector<double>>& errors)
{
  const int w = exact.Width;
  const int h = exact.Height;
  const int columns = 1 + static_cast<int>(images.size());
  vtkNew<vtkImageData> figure;
  figure->SetDimensions(columns * w, 2 * h, 1);
  figure->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(figure->GetScalarPointer());
  std::fill(out, out + 3 * columns * w * 2 * h, static_cast<unsigned char>(0));
  auto put = [&](int column, int row, int x, int y, const unsigned char* rgb) {
    unsigned char* p = out + 3 * ((row * h + y) * columns * w + column * w + x);
    std::copy(rgb, rgb + 3, p);
  };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      put(0, 1, x, y, exact.At(x, y));
      for (size_t c = 0; c < images.size(); ++c)
      {
        put(static_cast<int>(c) + 1, 1, x, y, images[c].At(x, y));
        const double e = std::min(255.0, 2.0 * errors[c][static_cast<size_t>(y) * w + x]);
        const unsigned char grey[3] = { static_cast<unsigned char>(e),
          static_cast<unsigned char>(e), static_cast<unsigned char>(e) };
        put(static_cast<int>(c) + 1, 0, x, y, grey);
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path);
  writer->SetInputData(figure);
  writer->Write();
  std::cout << "figure written to " << path << "\n";
}

// Every effect with the exit point: no OpenGL error, and the picture is not the blended one.
bool WithEverything()
{
  IceTest::BlockScene scene;
  scene.Mapper->GetIceProperty()->SetNumberOfCracks(3);
  scene.Mapper->GetPaperInterior()->CracksPerturbRefractionOn();
  scene.Mapper->GetIceProperty()->SetNumberOfAirPlanes(19);
  scene.Mapper->GetIceProperty()->SetBumpStrength(0.08);
  scene.Mapper->GetIceProperty()->GlisteningOn();
  // The dynamic cube map sees the sky through a skybox.
  vtkNew<vtkSkybox> sky;
  sky->SetTexture(scene.Renderer->GetEnvironmentTexture());
  scene.Renderer->AddActor(sky);
  vtkNew<vtkIceCubeMapPass> cubeMaps;
  cubeMaps->SetFaceSize(64);
  scene.Pass->SetCubeMapPass(cubeMaps);
  const IceTest::Image blended = scene.Render();
  scene.Mapper->SetTwoSidedMethodToExitPoint();
  const IceTest::Image exitPoint = scene.Render();
  const size_t differing = IceTest::CountDiffering(blended, exitPoint, 2);
  bool ok = Expect(IceTest::TakeGLErrors(scene.Window).empty(),
    "exit point with cracks in the refraction, air, bumps, glistening and a dynamic cube map: "
    "no OpenGL error");
  ok = Expect(differing > 500,
         "and it refracts otherwise than the blended normals (" + std::to_string(differing) +
           " pixels differ by more than 2/255)") &&
    ok;
  return ok;
}

// One shape: the three methods against exact double refraction, the exit point against its own
// reference; the figure for the sphere when VTKICE_FIGURE is set.
bool CheckShape(const char* name, const dvec3& radii, const char* figure)
{
  Scene scene(radii);
  // The window exists before the reference projects through the renderer.
  const IceTest::Image blended = scene.Render();
  const Expected expected = Evaluate(scene);
  scene.Mapper->SetTwoSidedMethodToExitPoint();
  const IceTest::Image exitPoint = scene.Render();
  scene.Mapper->TwoSidedRefractionOff();
  const IceTest::Image oneSided = scene.Render();

  std::vector<std::vector<double>> errors(3);
  const IceTest::Stats blendedError = Errors(blended, expected, expected.Exact, errors[0]);
  const IceTest::Stats exitError = Errors(exitPoint, expected, expected.Exact, errors[1]);
  const IceTest::Stats oneSidedError = Errors(oneSided, expected, expected.Exact, errors[2]);
  std::vector<double> unused;
  const IceTest::Stats ownReference = Errors(exitPoint, expected, expected.ExitPoint, unused);

  std::cout << name << ", against exact double refraction:\n  blended normals (paper, eq 1): "
            << Describe(blendedError) << "\n  exit point: " << Describe(exitError)
            << "\n  one-sided: " << Describe(oneSidedError) << "\n";
  bool ok = IceTest::ReportReference(
    std::string(name) + ": exit point against its CPU reference", ownReference, 20000);
  ok = Expect(exitError.Mean < 0.5 * blendedError.Mean && exitError.P99 < blendedError.P99,
         std::string(name) +
           ": the exit point is closer to exact double refraction than the blended normals "
           "(mean " +
           std::to_string(exitError.Mean) + " vs " + std::to_string(blendedError.Mean) + ", p99 " +
           std::to_string(exitError.P99) + " vs " + std::to_string(blendedError.P99) + ")") &&
    ok;
  if (figure)
  {
    IceTest::Image exact = blended;
    for (size_t i = 0; i < expected.Interior.size(); ++i)
    {
      const dvec3& c = expected.Exact[i];
      if (expected.Interior[i] && !std::isnan(c.x + c.y + c.z))
      {
        for (int k = 0; k < 3; ++k)
        {
          exact.RGB[3 * i + k] =
            static_cast<unsigned char>(std::min(255.0, std::max(0.0, c[k] + 0.5)));
        }
      }
    }
    WriteFigure(figure, exact, { blended, exitPoint, oneSided }, errors);
  }
  return ok;
}
}

int TestIceExitPoint(int, char*[])
{
  bool ok = CheckShape("sphere", dvec3(1.0), std::getenv("VTKICE_FIGURE"));
  ok = CheckShape("ellipsoid", dvec3(1.3, 0.8, 0.9), nullptr) && ok;
  ok = WithEverything() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
