// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceGround.h"
#include "vtkIceCubeMapTexture.h"
#include "vtkIceNoise.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTexture.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace IceGround
{
namespace
{
// A separable Gaussian blur of an n x n image, sigma in texels (the border repeats).
std::vector<double> Blur(const std::vector<double>& image, int n, double sigma)
{
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<double> kernel(2 * radius + 1);
  double sum = 0.0;
  for (int k = -radius; k <= radius; ++k)
  {
    kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
    sum += kernel[k + radius];
  }
  for (double& k : kernel)
  {
    k /= sum;
  }
  std::vector<double> rows(image.size());
  std::vector<double> out(image.size());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      double v = 0.0;
      for (int k = -radius; k <= radius; ++k)
      {
        v += kernel[k + radius] * image[j * n + std::clamp(i + k, 0, n - 1)];
      }
      rows[j * n + i] = v;
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      double v = 0.0;
      for (int k = -radius; k <= radius; ++k)
      {
        v += kernel[k + radius] * rows[std::clamp(j + k, 0, n - 1) * n + i];
      }
      out[j * n + i] = v;
    }
  }
  return out;
}

// How wet the melt water running off the pool leaves the ground at (x, z) from the ice's centre
// (`extent` its size): a narrow trickle, meandering away from the foot towards the front left of
// ice-render's camera, narrowing to a rounded end (the ground is never quite level).
double Trickle(double x, double z, double extent)
{
  const double direction[2] = { -0.552, 0.834 };
  const double along = (x * direction[0] + z * direction[1]) / extent;
  const double across = (z * direction[0] - x * direction[1]) / extent;
  const double start = 0.3; // inside the pool
  const double end = 1.1;
  if (along <= start || along >= end)
  {
    return 0.0;
  }
  const double bend[3] = { 1.5 * along, 0.0, 17.0 };
  const double wobble[3] = { 4.0 * along, 0.0, 5.0 };
  const double middle = 0.12 * vtkIceNoise::FractalNoise(bend, 29);
  const double width = 0.06 * (1.0 - 0.5 * (along - start) / (end - start)) +
    0.006 * vtkIceNoise::FractalNoise(wobble, 31);
  return std::clamp((width - std::abs(across - middle)) / 0.01, 0.0, 1.0) *
    std::sqrt(std::clamp((end - along) / 0.12, 0.0, 1.0));
}
}

vtkSmartPointer<vtkImageData> ContactShadow(vtkPolyData* model, double halfSize, int texels)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(model);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* surface = triangles->GetOutput();
  double bounds[6];
  model->GetBounds(bounds);
  const double floor = bounds[2];
  const double centre[2] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[4] + bounds[5]) };
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1.0e-9 });
  // A surface this far above the ground (a fraction of the model) shades it e times less: the
  // shadow is darkest where the ice touches and fades where the ice rises.
  const double falloff = 0.12 * extent;
  const double texel = 2.0 * halfSize / texels;

  // The footprint: for each texel the nearest the surface comes to the ground above it.
  std::vector<double> cover(static_cast<size_t>(texels) * texels, 0.0);
  vtkPoints* points = surface->GetPoints();
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    if (ids->GetNumberOfIds() != 3)
    {
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids->GetId(k), p[k]);
    }
    // Texel coordinates: i along x, j from +z to -z (the ground's texture runs so).
    double u[3], v[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = (p[k][0] + halfSize) / texel - 0.5;
      v[k] = (halfSize - p[k][2]) / texel - 0.5;
    }
    const double area = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if (std::abs(area) < 1.0e-12)
    {
      continue; // seen edge on from below: it covers nothing
    }
    const int i0 = std::max(0, static_cast<int>(std::floor(std::min({ u[0], u[1], u[2] }))));
    const int i1 = std::min(texels - 1, static_cast<int>(std::ceil(std::max({ u[0], u[1], u[2] }))));
    const int j0 = std::max(0, static_cast<int>(std::floor(std::min({ v[0], v[1], v[2] }))));
    const int j1 = std::min(texels - 1, static_cast<int>(std::ceil(std::max({ v[0], v[1], v[2] }))));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double b1 = ((i - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (j - v[0])) / area;
        const double b2 = ((u[1] - u[0]) * (j - v[0]) - (i - u[0]) * (v[1] - v[0])) / area;
        const double b0 = 1.0 - b1 - b2;
        if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0)
        {
          continue;
        }
        const double height = b0 * p[0][1] + b1 * p[1][1] + b2 * p[2][1] - floor;
        double& c = cover[static_cast<size_t>(j) * texels + i];
        c = std::max(c, std::exp(-std::max(height, 0.0) / falloff));
      }
    }
  }

  // A tight shadow along the line where the ice touches and a wide, faint one around it (the
  // sky it hides), but none under the ice: clear ice lets the light through and gathers it there
  // (the third component, a caustic); in the second component the wet ground the melting ice
  // leaves around its foot, with an uneven edge.
  const std::vector<double> tight = Blur(cover, texels, 0.02 * extent / texel);
  const std::vector<double> wide = Blur(cover, texels, 0.25 * extent / texel);
  // The melt water: a pool a little wider than the foot.
  const std::vector<double> pool = Blur(cover, texels, 0.18 * extent / texel);
  vtkNew<vtkImageData> image;
  image->SetDimensions(texels, texels, 1);
  image->AllocateScalars(VTK_DOUBLE, 3);
  double* out = static_cast<double*>(image->GetScalarPointer());
  for (int j = 0; j < texels; ++j)
  {
    for (int i = 0; i < texels; ++i)
    {
      const size_t k = static_cast<size_t>(j) * texels + i;
      const double at[3] = { 6.0 * ((i + 0.5) * texel - halfSize) / extent, 0.0,
        6.0 * (halfSize - (j + 0.5) * texel) / extent };
      const double edge = pool[k] + 0.15 * vtkIceNoise::FractalNoise(at, 7);
      // Well inside the footprint (seen only through the ice), and along its outline.
      const double t = std::clamp((tight[k] - 0.93) / 0.06, 0.0, 1.0);
      const double under = t * t * (3.0 - 2.0 * t);
      const double outline = std::min(1.0, 4.0 * tight[k] * (1.0 - tight[k]));
      const double shadow = 0.55 * std::max(outline, tight[k]) + 0.45 * wide[k];
      out[3 * k] = std::min(1.0, shadow * (1.0 - under));
      // Only near the foot: no wet spots of noise alone far from the ice.
      out[3 * k + 1] = std::max(
        std::clamp((edge - 0.08) / 0.05, 0.0, 1.0) * std::min(1.0, 20.0 * pool[k]),
        Trickle((i + 0.5) * texel - halfSize - centre[0], halfSize - (j + 0.5) * texel - centre[1],
          extent));
      // The light the ice gathers, uneven as its surface is.
      const double ripples[3] = { 3.0 * at[0], 0.0, 3.0 * at[2] };
      out[3 * k + 2] =
        under * std::clamp(0.75 + 0.5 * vtkIceNoise::FractalNoise(ripples, 11), 0.0, 1.0);
    }
  }
  return image;
}

void EnvironmentColour(vtkTexture* environment, const std::vector<int>& faces, double colour[3])
{
  colour[0] = colour[1] = colour[2] = 0.5;
  if (!environment)
  {
    return;
  }
  const bool linear = vtkIceCubeMapTexture::HoldsHighDynamicRange(environment);
  double sum[3] = { 0.0, 0.0, 0.0 };
  vtkIdType count = 0;
  for (int face : faces)
  {
    if (environment->GetNumberOfInputConnections(face) == 0)
    {
      return;
    }
    environment->GetInputAlgorithm(face, 0)->Update();
    vtkImageData* image = vtkImageData::SafeDownCast(environment->GetInputDataObject(face, 0));
    vtkDataArray* texels = image ? image->GetPointData()->GetScalars() : nullptr;
    if (!texels || texels->GetNumberOfComponents() < 3)
    {
      return;
    }
    const double scale = texels->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
    for (vtkIdType k = 0; k < texels->GetNumberOfTuples(); ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += scale * texels->GetComponent(k, c);
      }
    }
    count += texels->GetNumberOfTuples();
  }
  for (int c = 0; c < 3 && count > 0; ++c)
  {
    const double mean = std::max(0.0, sum[c] / count);
    colour[c] = std::min(1.0, linear ? std::pow(mean, 1.0 / 2.2) : mean);
  }
}

vtkSmartPointer<vtkActor> MakeGround(
  vtkPolyData* model, const double colour[3], const double sheen[3])
{
  double bounds[6];
  model->GetBounds(bounds);
  const double extent = std::max({ bounds[1] - bounds[0], bounds[5] - bounds[4], 1.0e-9 });
  const double halfSize = 6.0 * extent;
  const int texels = 512; // the shadow's; the ground's own grain is finer
  const int fine = 1024;
  vtkSmartPointer<vtkImageData> shadow = ContactShadow(model, halfSize, texels);
  const double* dark = static_cast<const double*>(shadow->GetScalarPointer());
  // The shadow bilinearly between its texels, at a fine texel's centre (i, j).
  const auto shadowAt = [&](int i, int j, int c) {
    const double x = std::clamp((i + 0.5) * texels / fine - 0.5, 0.0, texels - 1.0);
    const double y = std::clamp((j + 0.5) * texels / fine - 0.5, 0.0, texels - 1.0);
    const int x0 = std::min(static_cast<int>(x), texels - 2);
    const int y0 = std::min(static_cast<int>(y), texels - 2);
    const double fx = x - x0;
    const double fy = y - y0;
    const auto at = [&](int xi, int yi) {
      return dark[3 * (static_cast<size_t>(yi) * texels + xi) + c];
    };
    return (1.0 - fy) * ((1.0 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
      fy * ((1.0 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
  };

  // Transparent ice lets most light through: its shadow darkens the ground by at most this much
  // (Mitsuba's path-traced ground beside the foot is nearly as bright as far from it), and the
  // light it gathers under itself brightens the ground by up to this much more.
  const double strength = 0.25;
  const double caustic = 0.6;
  // What the pool shows of the world mirrored below it (the ice's mirror image, through the
  // texture's alpha) and of the surroundings' mean colour (a sheen): water reflects 15 % at the
  // camera's glancing view of the pool (about 72 degrees), and the ice it mirrors is brighter than
  // the ground (it shows the sky): with these shares the pool is closest to the path-traced
  // target's (Testing/PathTraced/natural_ice_cube.py, FLIP 0.2224 against 0.2230 with 0.15 and
  // 0.15): the image and the ground mix as displayed colours, not as light.
  const double mirrorShare = 0.3;
  const double sheenShare = 0.09;
  // The stone's brightness first, then blurred: its single grains a few pixels wide at the ice's
  // distance, softened to what a photograph resolves, and more with the distance from the ice, as
  // a camera focused on the ice blurs them (and as the panorama behind is blurred).
  std::vector<double> stone(static_cast<size_t>(fine) * fine);
  for (int j = 0; j < fine; ++j)
  {
    for (int i = 0; i < fine; ++i)
    {
      const double x = ((i + 0.5) / fine - 0.5) * 2.0;
      const double z = ((j + 0.5) / fine - 0.5) * 2.0;
      // Stone: patches a few ice extents across, a finer mottle and single grains, so the ice
      // has something to refract and the eye a scale.
      const double at[3] = { x * halfSize / extent, 0.0, z * halfSize / extent };
      const double coarse[3] = { 0.8 * at[0], 0.0, 0.8 * at[2] };
      const double mottle[3] = { 9.0 * at[0], 0.0, 9.0 * at[2] };
      const double grain = vtkIceNoise::Uniform(31, static_cast<std::uint32_t>(j * fine + i));
      stone[static_cast<size_t>(j) * fine + i] = (1.0 +
                                                   0.18 * vtkIceNoise::FractalNoise(coarse, 21) +
                                                   0.1 * vtkIceNoise::FractalNoise(mottle, 23)) *
        (grain < 0.03 ? 0.8 : grain > 0.985 ? 1.15 : 1.0);
    }
  }
  const std::vector<double> sharp = Blur(stone, fine, 0.8);
  const std::vector<double> soft = Blur(stone, fine, 3.0);

  vtkNew<vtkImageData> rgba;
  rgba->SetDimensions(fine, fine, 1);
  rgba->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  unsigned char* texel = static_cast<unsigned char*>(rgba->GetScalarPointer());
  for (int j = 0; j < fine; ++j)
  {
    for (int i = 0; i < fine; ++i, texel += 4)
    {
      // The texture's rows run with t, from +z (j = 0) to -z, as ContactShadow's do.
      const double x = ((i + 0.5) / fine - 0.5) * 2.0;
      const double z = ((j + 0.5) / fine - 0.5) * 2.0;
      const double r = std::sqrt(x * x + z * z);
      const double t = std::clamp((r - 0.35) / 0.6, 0.0, 1.0);
      const double fade = 1.0 - t * t * (3.0 - 2.0 * t);
      // Sharp within an extent of the ice's centre, fully soft from three on.
      const double focus = std::clamp((r * halfSize / extent - 1.0) / 2.0, 0.0, 1.0);
      const size_t k = static_cast<size_t>(j) * fine + i;
      const double stoneHere = sharp[k] + focus * (soft[k] - sharp[k]);
      // Wet ground is darker: the water film lets half the light the stone scatters out, and
      // mirrors the surroundings instead, less where the ice hides them (there it mirrors the
      // ice): the sheen must not wash out the contact shadow.
      const double shadowed = shadowAt(i, j, 0);
      const double wet = shadowAt(i, j, 1);
      const double shade =
        (1.0 - strength * shadowed) * (1.0 - 0.5 * wet) + caustic * shadowAt(i, j, 2);
      const double mirrored = sheenShare * wet * (1.0 - shadowed);
      for (int c = 0; c < 3; ++c)
      {
        texel[c] = static_cast<unsigned char>(std::lround(
          255.0 * std::clamp(colour[c] * stoneHere * shade + mirrored * sheen[c], 0.0, 1.0)));
      }
      // What lies below the ground shows through the pool: the ice's mirror image there
      // (IceScene::AddMirrorImage).
      texel[3] = static_cast<unsigned char>(std::lround(255.0 * fade * (1.0 - mirrorShare * wet)));
    }
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(rgba);
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->RepeatOff();
  texture->EdgeClampOn();

  const double y = bounds[2];
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-halfSize, y, halfSize);
  plane->SetPoint1(halfSize, y, halfSize);
  plane->SetPoint2(-halfSize, y, -halfSize);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto ground = vtkSmartPointer<vtkActor>::New();
  ground->SetMapper(mapper);
  ground->SetTexture(texture);
  ground->GetProperty()->LightingOff();
  ground->GetProperty()->SetColor(1.0, 1.0, 1.0); // the albedo is in the texture
  return ground;
}
}
