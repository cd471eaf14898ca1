// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceScene.h"
#include "IceGround.h"
#include "vtkIceModelFileChecks.h"
#include "IceReading.h"

#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceCubeMapTexture.h"
#include "vtkIceEnvironmentReader.h"
#include "vtkIceMapper.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkImageData.h"
#include "vtkConeSource.h"
#include "vtkCylinderSource.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkLight.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataReader.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkReverseSense.h"
#include "vtkSTLReader.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

namespace IceScene
{
namespace
{
vtkSmartPointer<vtkPolyDataMapper> MakeMapper(vtkAlgorithm* source)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  return mapper;
}

std::string Extension(const std::string& path)
{
  const std::string::size_type dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

vtkSmartPointer<vtkAlgorithm> ModelReader(const std::string& path, std::string& error)
{
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == "vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    error = "unknown model '" + vtkIceModelFileChecks::Printable(path) +
      "' (use cube, teapot, block, sphere or a .vtp, .vtk, .stl, .obj or .ply file)";
  }
  return reader;
}

// Centres the model at the origin with its largest extent scaled to 2; nullptr when the extent
// is too small to scale (the model passed vtkIceMapper::CheckInput, so it is not 0).
vtkSmartPointer<vtkPolyData> Normalize(vtkPolyData* model)
{
  double bounds[6];
  model->GetBounds(bounds);
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  if (!std::isfinite(2.0 / extent))
  {
    return nullptr;
  }
  vtkNew<vtkTransform> transform;
  transform->Scale(2.0 / extent, 2.0 / extent, 2.0 / extent);
  transform->Translate(
    -0.5 * (bounds[0] + bounds[1]), -0.5 * (bounds[2] + bounds[3]), -0.5 * (bounds[4] + bounds[5]));
  vtkNew<vtkTransformPolyDataFilter> apply;
  apply->SetInputData(model);
  apply->SetTransform(transform);
  apply->Update();
  return apply->GetOutput();
}
}

void AddLandscape(vtkRenderer* renderer, double groundHeight)
{
  // Checkered snow and grass, half a unit per square, mip-mapped for the distance.
  const double halfSize = 12.0;
  const int texels = 1024;
  const int squares = 48;
  vtkNew<vtkImageData> checker;
  checker->SetDimensions(texels, texels, 1);
  checker->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  // Written directly: a million SetScalarComponentFromDouble calls took a noticeable part of a
  // second for every landscape.
  unsigned char* texel = static_cast<unsigned char*>(checker->GetScalarPointer(0, 0, 0));
  for (int j = 0; j < texels; ++j)
  {
    for (int i = 0; i < texels; ++i, texel += 3)
    {
      const bool snow = ((i * squares / texels) + (j * squares / texels)) % 2 == 0;
      texel[0] = static_cast<unsigned char>(snow ? 225 : 80);
      texel[1] = static_cast<unsigned char>(snow ? 230 : 120);
      texel[2] = static_cast<unsigned char>(snow ? 235 : 75);
    }
  }
  vtkNew<vtkTexture> groundTexture;
  groundTexture->SetInputData(checker);
  groundTexture->InterpolateOn();
  groundTexture->MipmapOn();
  vtkNew<vtkPlaneSource> groundPlane;
  groundPlane->SetOrigin(-halfSize, groundHeight, halfSize);
  groundPlane->SetPoint1(halfSize, groundHeight, halfSize);
  groundPlane->SetPoint2(-halfSize, groundHeight, -halfSize);
  vtkNew<vtkActor> ground;
  ground->SetMapper(MakeMapper(groundPlane));
  ground->SetTexture(groundTexture);
  ground->GetProperty()->SetAmbient(0.4);
  renderer->AddActor(ground);

  // Rocks: ice-block shapes, rounder and rougher, in stone colours.
  const double rocks[][5] = { // x, z, size, seed, shade
    { -3.5, -2.0, 1.4, 3, 0.55 }, { 3.8, -3.5, 2.2, 5, 0.45 }, { -1.5, 4.5, 1.0, 8, 0.6 },
    { 5.0, 2.5, 1.2, 11, 0.5 }, { -6.0, 3.0, 2.0, 13, 0.4 }
  };
  for (const auto& rock : rocks)
  {
    vtkNew<vtkIceBlockSource> shape;
    shape->SetSeed(static_cast<int>(rock[3]));
    shape->SetSize(rock[2]);
    shape->SetRoundness(0.6);
    shape->SetDisplacement(0.25);
    shape->SetResolution(10);
    vtkNew<vtkActor> actor;
    actor->SetMapper(MakeMapper(shape));
    actor->SetPosition(rock[0], groundHeight + 0.3 * rock[2], rock[1]);
    actor->GetProperty()->SetColor(rock[4] + 0.05, rock[4], rock[4] - 0.05);
    actor->GetProperty()->SetAmbient(0.35);
    renderer->AddActor(actor);
  }

  // Pine trees: a trunk and a cone.
  const double trees[][3] = { // x, z, height
    { -2.0, -5.5, 3.0 }, { 1.0, -7.0, 3.6 }, { 6.5, -1.0, 2.6 }, { -5.0, -0.5, 2.8 },
    { 2.5, 5.5, 3.2 }, { -4.0, 6.5, 3.4 }
  };
  for (const auto& tree : trees)
  {
    vtkNew<vtkCylinderSource> trunkShape;
    trunkShape->SetRadius(0.12 * tree[2] / 3.0);
    trunkShape->SetHeight(0.3 * tree[2]);
    trunkShape->SetResolution(12);
    vtkNew<vtkActor> trunk;
    trunk->SetMapper(MakeMapper(trunkShape));
    trunk->SetPosition(tree[0], groundHeight + 0.15 * tree[2], tree[1]);
    trunk->GetProperty()->SetColor(0.4, 0.27, 0.15);
    trunk->GetProperty()->SetAmbient(0.35);
    renderer->AddActor(trunk);

    vtkNew<vtkConeSource> crownShape;
    crownShape->SetRadius(0.35 * tree[2]);
    crownShape->SetHeight(0.8 * tree[2]);
    crownShape->SetDirection(0.0, 1.0, 0.0);
    crownShape->SetResolution(24);
    vtkNew<vtkActor> crown;
    crown->SetMapper(MakeMapper(crownShape));
    crown->SetPosition(tree[0], groundHeight + 0.6 * tree[2], tree[1]);
    crown->GetProperty()->SetColor(0.12, 0.38, 0.18);
    crown->GetProperty()->SetAmbient(0.35);
    renderer->AddActor(crown);
  }

  // The sky's sun, plus a soft fill from the camera side.
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(45.0, 55.0, -70.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(0.9);
  renderer->AddLight(sun);
  vtkNew<vtkLight> fill;
  fill->SetLightTypeToHeadlight();
  fill->SetIntensity(0.35);
  renderer->AddLight(fill);
}

vtkSmartPointer<vtkPolyData> LoadModel(
  const std::string& model, std::string& error, std::string* warning)
{
  vtkSmartPointer<vtkAlgorithm> source;
  const bool file =
    model != "teapot" && model != "block" && model != "cube" && model != "sphere";
  if (model == "teapot")
  {
    source = vtkSmartPointer<vtkIceTeapotSource>::New();
  }
  else if (model == "block")
  {
    source = vtkSmartPointer<vtkIceBlockSource>::New();
  }
  else if (model == "cube")
  {
    // An ice cube: flat faces, slightly melted round edges, a gentle unevenness (the block
    // source's displacement noise at three eighths of its default), fine enough for the rounding.
    auto cube = vtkSmartPointer<vtkIceBlockSource>::New();
    cube->SetResolution(48);
    cube->SetRoundness(0.22);
    cube->SetDisplacement(0.03);
    cube->SetSeed(3);
    source = cube;
  }
  else if (model == "sphere")
  {
    // About 960 triangles, the sphere of the paper's measurements.
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(17);
    source = sphere;
  }
  else
  {
    source = ModelReader(model, error);
    if (!source)
    {
      return nullptr;
    }
    error = vtkIceModelFileChecks::CheckFile(model);
    if (!error.empty())
    {
      return nullptr;
    }
  }
  const std::string name = vtkIceModelFileChecks::Printable(model);
  // Files are read in a child process: VTK's readers crash on some broken files.
  vtkSmartPointer<vtkPolyData> output;
  if (file)
  {
    output = IceReading::ReadPolyDataIsolated(source, error, warning);
  }
  else if (IceReading::UpdateQuietly(source, error))
  {
    output = vtkPolyData::SafeDownCast(source->GetOutputDataObject(0));
  }
  if (!error.empty())
  {
    error = "cannot read model '" + name + "': " + error;
    return nullptr;
  }
  if (!output || output->GetNumberOfPolys() + output->GetNumberOfStrips() == 0)
  {
    error = "model '" + name + "' has no polygons";
    return nullptr;
  }
  // Broken connectivity crashes VTK's filters (bounds, normals): check before any of them runs.
  const std::string problem = vtkIceMapper::CheckInput(output);
  if (!problem.empty())
  {
    error = "cannot use model '" + name + "': " + problem;
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> normalized = Normalize(output);
  if (!normalized)
  {
    error = "cannot use model '" + name + "': its extent is too small to scale";
  }
  return normalized;
}

const std::vector<std::string>& Panoramas()
{
  static const std::vector<std::string> names = { "city", "courtyard", "forest", "interior",
    "night", "studio", "sunrise", "sunset" };
  return names;
}

bool IsPanorama(const std::string& name)
{
  const std::vector<std::string>& names = Panoramas();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string PanoramaFolder()
{
  return "/usr/share/blender/datafiles/studiolights/world";
}

vtkSmartPointer<vtkTexture> LoadEnvironment(const std::string& environment, std::string& error)
{
  if (IsPanorama(environment))
  {
    // A name, not a path: ./courtyard names a file of that name.
    const std::string path = PanoramaFolder() + "/" + environment + ".exr";
    if (!std::ifstream(path).good())
    {
      error = "cannot load environment '" + environment + "': the panorama " + environment +
        " comes with Debian's blender-data package, which is not installed (" + path +
        " is missing): apt-get install blender-data, or give a path";
      return nullptr;
    }
    return LoadEnvironment(path, error);
  }

  auto texture = vtkSmartPointer<vtkTexture>::New();
  if (environment == "sky" || environment == "test")
  {
    vtkNew<vtkIceCubeMapSource> source;
    source->SetFaceSize(environment == "sky" ? 512 : 256);
    source->SetPattern(
      environment == "sky" ? vtkIceCubeMapSource::Sky : vtkIceCubeMapSource::DirectionTest);
    source->ConfigureTexture(texture);
    return texture;
  }

  // A folder of six faces, a cross or a panorama; the reader names the file and the problem.
  vtkNew<vtkIceEnvironmentReader> reader;
  reader->SetFileName(environment.c_str());
  if (!IceReading::UpdateQuietly(reader, error))
  {
    error = "cannot load environment '" + environment + "': " + error;
    return nullptr;
  }
  reader->ConfigureTexture(texture);
  return texture;
}

void AddEnvironment(vtkRenderer* renderer, vtkTexture* environment)
{
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(environment);
  // An HDR environment holds linear light: shown gamma-corrected, as the ice then shows it too.
  skybox->SetGammaCorrect(vtkIceCubeMapTexture::HoldsHighDynamicRange(environment));
  renderer->AddActor(skybox);
}

namespace
{
const double ViewDirection[3] = { 2.1, 0.9, 3.9 };
}

double DefaultCameraDistance()
{
  return vtkMath::Norm(ViewDirection);
}

void PlaceCamera(vtkRenderer* renderer, double distance)
{
  const double scale = distance / DefaultCameraDistance(); // exactly 1 at the default distance
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(scale * ViewDirection[0], scale * ViewDirection[1], scale * ViewDirection[2]);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(32.0);
  renderer->ResetCameraClippingRange();
}

vtkActor* Populate(
  vtkRenderer* renderer, vtkPolyData* model, vtkTexture* environment, const Options& options)
{
  vtkNew<vtkIcePass> icePass;
  renderer->SetPass(icePass);
  if (options.DynamicEnvironment)
  {
    vtkNew<vtkIceCubeMapPass> cubeMapPass;
    icePass->SetCubeMapPass(cubeMapPass);
  }
  if (options.Landscape)
  {
    AddLandscape(renderer, model->GetBounds()[2]);
  }
  if (options.Ground)
  {
    double ground[3];
    double horizon[3];
    IceGround::EnvironmentColour(environment, { 3 }, ground);
    IceGround::EnvironmentColour(environment, { 0, 1, 4, 5 }, horizon);
    renderer->AddActor(IceGround::MakeGround(model, ground, horizon));
  }
  AddEnvironment(renderer, environment);

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputData(model);
  // Standing on the ground, the ice stands in its melt water: its base shows the ground.
  mapper->SetWetBase(options.Ground);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);
  PlaceCamera(renderer, DefaultCameraDistance());
  if (options.Ground)
  {
    // Farther and lower on the ice: the ground and the shadow in the picture.
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(3.2, 1.4, 5.6);
    camera->SetFocalPoint(0.0, -0.2, 0.0);
    renderer->ResetCameraClippingRange();
  }
  return ice;
}

vtkActor* AddMirrorImage(vtkRenderer* renderer, vtkPolyData* model)
{
  double bounds[6];
  model->GetBounds(bounds);
  vtkNew<vtkTransform> reflect;
  reflect->Translate(0.0, 2.0 * bounds[2], 0.0);
  reflect->Scale(1.0, -1.0, 1.0);
  // Reflected in its points, not by the actor's matrix: the ice's passes cull faces by their
  // turn on the screen, which a reflecting matrix reverses (the image showed its inside). The
  // cells turned back keep the surface facing out.
  vtkNew<vtkTransformPolyDataFilter> reflected;
  reflected->SetInputData(model);
  reflected->SetTransform(reflect);
  vtkNew<vtkReverseSense> turned;
  turned->SetInputConnection(reflected->GetOutputPort());
  turned->ReverseCellsOn();
  turned->ReverseNormalsOff();
  turned->Update();
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputData(turned->GetOutput());
  // It shows the sky where the ice shows the sky, as a reflection does.
  mapper->MirroredEnvironmentOn();
  vtkNew<vtkActor> image;
  image->SetMapper(mapper);
  image->PickableOff();
  renderer->AddActor(image);
  return image;
}

void ShowMirrorImage(vtkActor* image, const std::string& debugView)
{
  image->SetVisibility(debugView == "off");
}
}
