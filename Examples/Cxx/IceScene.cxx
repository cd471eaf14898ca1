#include "IceScene.h"

#include "vtkIceBlockSource.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceEnvironmentReader.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkIceTeapotSource.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkLogger.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <fstream>

namespace IceScene
{
namespace
{
// Collects VTK's error text while loading files, so that ice-render reports one clean line.
class CapturedOutput : public vtkOutputWindow
{
public:
  static CapturedOutput* New() { VTK_STANDARD_NEW_BODY(CapturedOutput); }
  void DisplayText(const char* text) override
  {
    if (this->FirstMessage.empty() && text)
    {
      // Keep the message, not VTK's "ERROR: In file, line N / vtkClass (address): " preamble.
      std::string message = text;
      const std::string::size_type start = message.find("): ");
      message = start == std::string::npos ? message : message.substr(start + 3);
      message.erase(std::remove(message.begin(), message.end(), '\n'), message.end());
      this->FirstMessage = message;
    }
  }
  std::string FirstMessage;
};

// Runs `algorithm` with VTK's console output captured; false and `error` set if it complained.
bool UpdateQuietly(vtkAlgorithm* algorithm, std::string& error)
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<CapturedOutput> capture;
  vtkOutputWindow::SetInstance(capture);
  // VTK also logs errors to stderr through vtkLogger, bypassing the output window.
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  algorithm->Update();
  vtkLogger::SetStderrVerbosity(verbosity);
  vtkOutputWindow::SetInstance(previous);
  error = capture->FirstMessage;
  return error.empty();
}

std::string Extension(const std::string& path)
{
  const std::string::size_type dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool Readable(const std::string& path)
{
  return std::ifstream(path).good();
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
    error = "unknown model '" + path + "' (use teapot, block, sphere or a .vtp, .vtk, .stl, .obj or .ply file)";
  }
  return reader;
}

// Centres the model at the origin with its largest extent scaled to 2.
vtkSmartPointer<vtkPolyData> Normalize(vtkPolyData* model)
{
  double bounds[6];
  model->GetBounds(bounds);
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  vtkNew<vtkTransform> transform;
  transform->Scale(2.0 / extent, 2.0 / extent, 2.0 / extent);
  transform->Translate(-0.5 * (bounds[0] + bounds[1]), -0.5 * (bounds[2] + bounds[3]),
    -0.5 * (bounds[4] + bounds[5]));
  vtkNew<vtkTransformPolyDataFilter> apply;
  apply->SetInputData(model);
  apply->SetTransform(transform);
  apply->Update();
  return apply->GetOutput();
}
}

vtkSmartPointer<vtkPolyData> LoadModel(const std::string& model, std::string& error)
{
  vtkSmartPointer<vtkAlgorithm> source;
  if (model == "teapot")
  {
    source = vtkSmartPointer<vtkIceTeapotSource>::New();
  }
  else if (model == "block")
  {
    source = vtkSmartPointer<vtkIceBlockSource>::New();
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
    if (!Readable(model))
    {
      error = "cannot open model file '" + model + "'";
      return nullptr;
    }
  }
  if (!UpdateQuietly(source, error))
  {
    error = "cannot read model '" + model + "': " + error;
    return nullptr;
  }
  vtkPolyData* output = vtkPolyData::SafeDownCast(source->GetOutputDataObject(0));
  if (!output || output->GetNumberOfPolys() + output->GetNumberOfStrips() == 0)
  {
    error = "model '" + model + "' has no polygons";
    return nullptr;
  }
  return Normalize(output);
}

vtkSmartPointer<vtkTexture> LoadEnvironment(const std::string& environment, std::string& error)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  if (environment == "sky" || environment == "test")
  {
    vtkNew<vtkIceCubeMapSource> source;
    source->SetFaceSize(environment == "sky" ? 512 : 256);
    source->SetPattern(environment == "sky" ? vtkIceCubeMapSource::Sky
                                            : vtkIceCubeMapSource::DirectionTest);
    source->ConfigureTexture(texture);
    return texture;
  }

  // A folder of six faces, a cross or a panorama; the reader names the file and the problem.
  vtkNew<vtkIceEnvironmentReader> reader;
  reader->SetFileName(environment.c_str());
  if (!UpdateQuietly(reader, error))
  {
    error = "cannot load environment '" + environment + "': " + error;
    return nullptr;
  }
  reader->ConfigureTexture(texture);
  return texture;
}

vtkActor* Populate(vtkRenderer* renderer, vtkPolyData* model, vtkTexture* environment)
{
  vtkNew<vtkIcePass> icePass;
  renderer->SetPass(icePass);
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(environment);
  renderer->AddActor(skybox);

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputData(model);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(2.1, 0.9, 3.9);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(32.0);
  renderer->ResetCameraClippingRange();
  return ice;
}
}
