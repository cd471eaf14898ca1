// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceTestUtilities.h"

#include "vtkIceCubeMapSource.h"
#include "vtkIceBlockSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkRenderer.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPolyData.h"
#include "vtkPNGWriter.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace IceTest
{
namespace
{
Image FromImageData(vtkImageData* data)
{
  Image image;
  int dims[3];
  data->GetDimensions(dims);
  image.Width = dims[0];
  image.Height = dims[1];
  image.RGB.resize(3 * static_cast<size_t>(dims[0]) * dims[1]);
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  const int components = scalars->GetNumberOfComponents();
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(dims[0]) * dims[1]; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.RGB[3 * p + c] =
        static_cast<unsigned char>(scalars->GetComponent(p, std::min(c, components - 1)));
    }
  }
  return image;
}
}

Image Capture(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  return FromImageData(grab->GetOutput());
}

Image ReadPNG(const std::string& path)
{
  if (!std::filesystem::exists(path))
  {
    return Image();
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return FromImageData(reader->GetOutput());
}

void WritePNG(const Image& image, const std::string& path)
{
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.Width, image.Height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(
    image.RGB.begin(), image.RGB.end(), static_cast<unsigned char*>(data->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->Write();
}

int RunCases(const char* test, int argc, char* argv[], const Cases& cases)
{
  std::string only;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "--case")
    {
      only = argv[i + 1];
    }
  }
  bool ok = true;
  bool found = only.empty();
  for (const auto& entry : cases)
  {
    if (only.empty() || only == entry.first)
    {
      found = true;
      ok = entry.second() && ok;
    }
  }
  if (!found)
  {
    std::cerr << test << ": no case '" << only << "'\n";
    return EXIT_FAILURE;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

int PixelDifference(const unsigned char* a, const unsigned char* b)
{
  int worst = 0;
  for (int c = 0; c < 3; ++c)
  {
    worst = std::max(worst, std::abs(static_cast<int>(a[c]) - static_cast<int>(b[c])));
  }
  return worst;
}

size_t CountDiffering(const Image& a, const Image& b, int threshold)
{
  size_t count = 0;
  for (size_t p = 0; 3 * p < a.RGB.size() && 3 * p < b.RGB.size(); ++p)
  {
    count += PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]) > threshold ? 1 : 0;
  }
  return count;
}

Stats Summarize(std::vector<double> values)
{
  Stats stats;
  stats.Count = values.size();
  if (values.empty())
  {
    return stats;
  }
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values)
  {
    sum += v;
  }
  stats.Mean = sum / values.size();
  stats.P99 = values[std::min(values.size() - 1, static_cast<size_t>(0.99 * values.size()))];
  stats.Max = values.back();
  return stats;
}

bool CheckImage(int argc, char* argv[], vtkRenderWindow* window)
{
  const int regression = vtkRegressionTestImage(window);
  if (regression != vtkTesting::PASSED)
  {
    std::cerr << "VTK image regression test failed\n";
    return false;
  }

  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const Image rendered = Capture(window);
  // The baseline and its alternatives (Name_1.png, Name_2.png, ... as VTK's regression test
  // accepts them, where a platform draws the scene around the ice differently): the render must
  // meet the strict bounds against one of them.
  const std::string valid = testing->GetValidImageFileName();
  const std::string stem = valid.substr(0, valid.size() - 4);
  bool ok = false;
  for (int alternative = 0; !ok; ++alternative)
  {
    const std::string path =
      alternative == 0 ? valid : stem + "_" + std::to_string(alternative) + ".png";
    if (alternative > 0 && !std::filesystem::exists(path))
    {
      break;
    }
    const Image baseline = ReadPNG(path);
    if (baseline.Width != rendered.Width || baseline.Height != rendered.Height)
    {
      std::cerr << "Baseline " << path << " is " << baseline.Width << "x" << baseline.Height
                << ", render is " << rendered.Width << "x" << rendered.Height << "\n";
      continue;
    }
    double sum = 0.0;
    size_t far = 0;
    const size_t pixels = static_cast<size_t>(rendered.Width) * rendered.Height;
    for (size_t p = 0; p < pixels; ++p)
    {
      const int d = PixelDifference(&baseline.RGB[3 * p], &rendered.RGB[3 * p]);
      sum += d;
      far += d > 16 ? 1 : 0;
    }
    const double mean = sum / pixels;
    const double farFraction = static_cast<double>(far) / pixels;
    std::cout << "Strict baseline comparison with " << path.substr(path.find_last_of('/') + 1)
              << ": mean " << mean << "/255, " << 100.0 * farFraction
              << "% of pixels off by more than 16/255\n";
    ok = mean <= 1.0 && farFraction <= 0.002;
  }
  if (!ok)
  {
    // VTK writes its test image only when its own (looser) comparison fails: write this render
    // so that what is reviewed is what failed.
    const std::string name = valid.substr(valid.find_last_of('/') + 1);
    const std::string path = std::string(testing->GetTempDirectory()) + "/" + name;
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::cout << "Rendered image written to " << path << "\n";
  }
  return ok;
}

void UseCleanOptics(vtkIceMapper* mapper)
{
  mapper->GetIceProperty()->SetNumberOfCracks(0);
  mapper->GetIceProperty()->SetNumberOfAirPlanes(0);
  mapper->GetIceProperty()->SetBumpStrength(0.0);
}

vtkSmartPointer<vtkTexture> MakeCubeMap(int pattern, int faceSize)
{
  vtkNew<vtkIceCubeMapSource> source;
  source->SetPattern(pattern);
  source->SetFaceSize(faceSize);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  source->ConfigureTexture(texture);
  return texture;
}

void AddSky(vtkRenderer* renderer, int faceSize)
{
  vtkSmartPointer<vtkTexture> sky = MakeCubeMap(vtkIceCubeMapSource::Sky, faceSize);
  renderer->SetEnvironmentTexture(sky);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(sky);
  renderer->AddActor(skybox);
}

void PixelRay(vtkRenderer* renderer, int x, int y, double origin[3], double direction[3])
{
  PixelRay(renderer, x + 0.5, y + 0.5, origin, direction);
}

void PixelRay(vtkRenderer* renderer, double x, double y, double origin[3], double direction[3])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  if (camera->GetParallelProjection())
  {
    // Every ray runs along the direction of projection, from the pixel on the near plane.
    renderer->SetDisplayPoint(x, y, 0.0);
    renderer->DisplayToWorld();
    double world[4];
    renderer->GetWorldPoint(world);
    for (int i = 0; i < 3; ++i)
    {
      origin[i] = world[i] / world[3];
    }
    camera->GetDirectionOfProjection(direction);
    return;
  }
  camera->GetPosition(origin);
  renderer->SetDisplayPoint(x, y, 0.5);
  renderer->DisplayToWorld();
  double world[4];
  renderer->GetWorldPoint(world);
  for (int i = 0; i < 3; ++i)
  {
    direction[i] = world[i] / world[3] - origin[i];
  }
  vtkMath::Normalize(direction);
}

bool IntersectSphere(const double origin[3], const double direction[3], const double center[3],
  double radius, double& tNear, double& tFar)
{
  double oc[3];
  vtkMath::Subtract(origin, center, oc);
  const double b = vtkMath::Dot(oc, direction);
  const double c = vtkMath::Dot(oc, oc) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0)
  {
    return false;
  }
  tNear = -b - std::sqrt(discriminant);
  tFar = -b + std::sqrt(discriminant);
  return tNear > 0.0;
}

std::vector<bool> SphereInterior(
  vtkRenderer* renderer, const double center[3], double radius, int margin)
{
  const int* windowSize = renderer->GetRenderWindow()->GetSize();
  const int width = windowSize[0];
  const int* origin = renderer->GetOrigin();
  const int* size = renderer->GetSize();
  std::vector<bool> hit(static_cast<size_t>(width) * windowSize[1], false);
  for (int y = origin[1]; y < origin[1] + size[1]; ++y)
  {
    for (int x = origin[0]; x < origin[0] + size[0]; ++x)
    {
      double eye[3];
      double direction[3];
      double tNear;
      double tFar;
      PixelRay(renderer, x, y, eye, direction);
      hit[y * width + x] = IntersectSphere(eye, direction, center, radius, tNear, tFar);
    }
  }
  std::vector<bool> interior(hit.size(), false);
  for (int y = origin[1] + margin; y < origin[1] + size[1] - margin; ++y)
  {
    for (int x = origin[0] + margin; x < origin[0] + size[0] - margin; ++x)
    {
      bool all = true;
      for (int dy = -margin; dy <= margin && all; ++dy)
      {
        for (int dx = -margin; dx <= margin && all; ++dx)
        {
          all = hit[(y + dy) * width + x + dx];
        }
      }
      interior[y * width + x] = all;
    }
  }
  return interior;
}

Environment PatternEnvironment(const vtkIceCubeMapSource* source)
{
  return [source](const glm::dvec3& d) {
    double rgb[3];
    const double dir[3] = { d.x, d.y, d.z };
    source->Evaluate(dir, rgb);
    return glm::dvec3(rgb[0], rgb[1], rgb[2]);
  };
}

Stats CompareSphereWithReference(vtkRenderer* renderer, const Image& image, const double center[3],
  double radius, const vtkIceOpticsReference::Material& material, const Environment& environment,
  bool twoSided)
{
  using glm::dvec3;
  const std::vector<bool> interior = SphereInterior(renderer, center, radius, 3);
  const dvec3 c(center[0], center[1], center[2]);
  std::vector<double> differences;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      if (!interior[y * image.Width + x])
      {
        continue;
      }
      double origin[3];
      double direction[3];
      double tNear;
      double tFar;
      PixelRay(renderer, x, y, origin, direction);
      IntersectSphere(origin, direction, center, radius, tNear, tFar);
      const dvec3 o(origin[0], origin[1], origin[2]);
      const dvec3 e(direction[0], direction[1], direction[2]);
      const dvec3 nFront = glm::normalize(o + tNear * e - c);
      const dvec3 nBack = glm::normalize(o + tFar * e - c);
      const dvec3 expected = 255.0 *
        vtkIceOpticsReference::Shade(e, nFront, twoSided ? &nBack : nullptr, material, environment);
      if (std::isnan(expected.x + expected.y + expected.z))
      {
        continue;
      }
      const unsigned char* pixel = image.At(x, y);
      double worst = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(pixel[k] - expected[k]));
      }
      differences.push_back(worst);
    }
  }
  return Summarize(differences);
}

bool ReportReference(const std::string& name, const Stats& stats, size_t minimumPixels)
{
  const bool ok = stats.Count >= minimumPixels && stats.Mean <= 2.0 && stats.P99 <= 8.0;
  std::cout << (ok ? "ok   " : "FAIL ") << name << ": " << stats.Count
            << " interior pixels, |rendered - reference| mean " << stats.Mean << "/255, p99 "
            << stats.P99 << "/255, max " << stats.Max << "/255\n";
  return ok;
}

namespace
{
Stats MaskedDifference(const Image& a, const Image& b, const std::vector<bool>& mask)
{
  std::vector<double> differences;
  for (size_t p = 0; p < mask.size(); ++p)
  {
    if (mask[p])
    {
      differences.push_back(PixelDifference(&a.RGB[3 * p], &b.RGB[3 * p]));
    }
  }
  return Summarize(differences);
}

Invisibility MeasureAgainst(vtkTexture* environment, vtkSkybox* skybox)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(environment);
  skybox->SetTexture(environment);
  renderer->AddActor(skybox);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0); // the sphere the interior pixels are found for
  sphere->SetThetaResolution(128);
  sphere->SetPhiResolution(128);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  const double center[3] = { 0.0, 0.0, 0.0 };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(1.5, 0.4, 3.2);
  renderer->ResetCameraClippingRange();

  Invisibility result;
  ice->VisibilityOff();
  window->Render();
  result.Background = Capture(window);
  const std::vector<bool> interior = SphereInterior(renderer, center, 1.0, 3);

  ice->VisibilityOn();
  mapper->GetIceProperty()->SetRefractionRatio(1.0);
  mapper->GetIceProperty()->SetFresnelPower(1.0e6);
  window->Render();
  result.Invisible = MaskedDifference(result.Background, Capture(window), interior);

  mapper->GetIceProperty()->SetIndexOfRefraction(1.31);
  mapper->GetIceProperty()->SetFresnelPower(3.0);
  window->Render();
  result.Visible = MaskedDifference(result.Background, Capture(window), interior);
  return result;
}
}

Invisibility MeasureInvisibility(vtkTexture* environment)
{
  vtkNew<vtkSkybox> skybox;
  return MeasureAgainst(environment, skybox);
}

Invisibility MeasurePanoramaInvisibility(vtkTexture* panorama, bool gammaCorrect)
{
  vtkNew<vtkSkybox> skybox;
  skybox->SetProjection(vtkSkybox::Sphere);
  skybox->SetGammaCorrect(gammaCorrect);
  skybox->SetFloorRight(0.0, 0.0, 1.0);
  return MeasureAgainst(panorama, skybox);
}

bool ReportInvisibility(const std::string& name, const Invisibility& result)
{
  const Stats& invisible = result.Invisible;
  const Stats& visible = result.Visible;
  const bool ok =
    invisible.Count > 20000 && invisible.Mean <= 1.0 && invisible.P99 <= 4.0 && visible.Mean >= 5.0;
  std::cout << (ok ? "ok   " : "FAIL ") << name << ": eta 1: " << invisible.Count
            << " interior pixels differ from the skybox by mean " << invisible.Mean << "/255, p99 "
            << invisible.P99 << "/255, max " << invisible.Max << "/255; default ice: mean "
            << visible.Mean << "/255, p99 " << visible.P99 << "/255\n";
  return ok;
}

BlockScene::BlockScene()
  : Mapper(vtkSmartPointer<vtkIceMapper>::New())
  , Ice(vtkSmartPointer<vtkActor>::New())
  , Renderer(vtkSmartPointer<vtkRenderer>::New())
  , Pass(vtkSmartPointer<vtkIcePass>::New())
  , Window(vtkSmartPointer<vtkRenderWindow>::New())
{
  vtkNew<vtkIceBlockSource> block;
  block->Update();
  this->Mapper->SetInputData(block->GetOutput());
  UseCleanOptics(this->Mapper);
  this->Ice->SetMapper(this->Mapper);
  this->Renderer->AddActor(this->Ice);
  this->Renderer->SetEnvironmentTexture(MakeCubeMap(vtkIceCubeMapSource::Sky, 128));
  this->Renderer->SetBackground(0.0, 0.0, 0.0);
  this->Renderer->SetPass(this->Pass);
  this->Window->SetSize(240, 240);
  this->Window->SetOffScreenRendering(1);
  this->Window->AddRenderer(this->Renderer);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetPosition(2.5, 2.0, 4.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  this->Renderer->ResetCameraClippingRange();
}

BlockScene::~BlockScene() = default;

Image BlockScene::Render()
{
  this->Window->Render();
  return Capture(this->Window);
}

ClearSphereScene::ClearSphereScene()
  : Renderer(vtkSmartPointer<vtkRenderer>::New())
  , Mapper(vtkSmartPointer<vtkIceMapper>::New())
  , Ice(vtkSmartPointer<vtkActor>::New())
  , Pass(vtkSmartPointer<vtkIcePass>::New())
  , Window(vtkSmartPointer<vtkRenderWindow>::New())
{
  vtkSmartPointer<vtkTexture> environment = MakeCubeMap(vtkIceCubeMapSource::Sky, 256);
  this->Renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(environment);
  this->Renderer->AddActor(skybox);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(128);
  sphere->SetPhiResolution(128);
  sphere->Update();
  sphere->GetOutput()->GetBounds(this->Bounds);
  this->Mapper->SetInputData(sphere->GetOutput());
  UseCleanOptics(this->Mapper);
  this->Mapper->GetIceProperty()->SetIndexOfRefraction(1.0);
  this->Mapper->GetIceProperty()->SetFresnelPower(1.0e6);
  this->Ice->SetMapper(this->Mapper);
  this->Renderer->AddActor(this->Ice);
  this->Renderer->SetPass(this->Pass);
  this->Window->SetSize(300, 300);
  this->Window->SetOffScreenRendering(1);
  this->Window->AddRenderer(this->Renderer);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(1.5, 0.4, 3.2);
  this->Renderer->ResetCameraClippingRange();
  const double center[3] = { 0.0, 0.0, 0.0 };
  this->Interior = SphereInterior(this->Renderer, center, 1.0, 3);
  this->Ice->VisibilityOff();
  this->Background = this->Render();
  this->Ice->VisibilityOn();
}

ClearSphereScene::~ClearSphereScene() = default;

Stats ClearSphereScene::CompareAlongChords(const Image& image, const Expected& expected)
{
  const double center[3] = { 0.0, 0.0, 0.0 };
  std::vector<double> differences;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      if (!this->Interior[static_cast<size_t>(y) * image.Width + x])
      {
        continue;
      }
      double origin[3];
      double direction[3];
      double tNear;
      double tFar;
      PixelRay(this->Renderer, x, y, origin, direction);
      IntersectSphere(origin, direction, center, 1.0, tNear, tFar);
      const glm::dvec3 e(direction[0], direction[1], direction[2]);
      const glm::dvec3 colour =
        expected(x, y, glm::dvec3(origin[0], origin[1], origin[2]) + tNear * e, e, tFar - tNear);
      const unsigned char* rendered = image.At(x, y);
      double largest = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest, std::abs(rendered[c] - colour[c]));
      }
      differences.push_back(largest);
    }
  }
  return Summarize(differences);
}

Image ClearSphereScene::Render()
{
  this->Window->Render();
  return Capture(this->Window);
}

void MessageRecorder::Execute(vtkObject*, unsigned long event, void* data)
{
  // Keep only the message itself, not VTK's "ERROR: In file, line" preamble.
  std::string text = data ? static_cast<const char*>(data) : "";
  const std::string::size_type start = text.find("): ");
  if (start != std::string::npos)
  {
    text = text.substr(start + 3);
  }
  text.erase(text.find_last_not_of("\n") + 1);
  (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
}

void MessageRecorder::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

//------------------------------------------------------------------------------
bool Expect(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
  return condition;
}
}
