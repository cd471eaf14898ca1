// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input for vtkIceMapper gives one clear VTK message and leaves the rest of the scene
// rendering:
// - input that cannot be ice (empty polydata, lines only, vertices only, NaN or infinite
//   points): one error per input, that actor is not drawn;
// - ice without volume (flat): one warning, drawn as a surface without cracks;
// - an open (not closed) surface: drawn as the surface it is; with Geometry crack clipping, which
//   needs an inside, one warning and its cracks are clipped to the depth interval instead;
// - a huge mesh (1 M triangles): drawn, no message, the time is reported;
// - absurd parameter values: out of range, clamped as VTK's clamp macros do (silently); NaN, one
//   warning and the value is kept; 10^6 cracks are clamped to 1000 and render;
// - an environment texture whose image files are missing or corrupt: the reader's one error and
//   one warning of the mapper, which uses its built-in sky.
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceEnvironmentReader.h"
#include "vtkIceMapper.h"
#include "vtkIcePaperInterior.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> LinesOnly()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[3] = { 0, 1, 2 };
  lines->InsertNextCell(3, line);
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

vtkSmartPointer<vtkPolyData> VerticesOnly()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(0.3 * i, 0.1 * i, 0.0);
    verts->InsertNextCell(1, &i);
  }
  data->SetPoints(points);
  data->SetVerts(verts);
  return data;
}

vtkSmartPointer<vtkPolyData> InfiniteSphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  data->GetPoints()->SetPoint(5, 0.0, -std::numeric_limits<double>::infinity(), 0.0);
  return data;
}

vtkSmartPointer<vtkPolyData> NaNTriangle()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1, 0, 0);
  points->InsertNextPoint(1, std::numeric_limits<double>::quiet_NaN(), 0);
  points->InsertNextPoint(0, 1, std::numeric_limits<double>::infinity());
  vtkNew<vtkCellArray> polys;
  const vtkIdType triangle[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, triangle);
  data->SetPoints(points);
  data->SetPolys(polys);
  return data;
}

bool CheckCase(const char* name, vtkPolyData* input, const char* expected)
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkConeSource> cone;
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(1.0, 0.0, 0.0);
  coneActor->GetProperty()->LightingOff();
  renderer->AddActor(coneActor);

  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputData(input);
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  ice->SetPosition(0.0, 0.0, 0.5);
  renderer->AddActor(ice);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(0, 0, 5);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  window->Render();

  const IceTest::Image image = IceTest::Capture(window);
  const unsigned char* middle = image.At(100, 100);
  const bool coneDrawn = middle[0] == 255 && middle[1] == 0 && middle[2] == 0;
  const bool oneError =
    recorder->Errors.size() == 1 && recorder->Errors[0].find(expected) != std::string::npos;
  std::cout << name << ": " << recorder->Errors.size() << " error(s)"
            << (recorder->Errors.empty() ? std::string() : ": " + recorder->Errors[0])
            << "; cone pixel " << int(middle[0]) << "," << int(middle[1]) << "," << int(middle[2])
            << "\n";
  return coneDrawn && oneError;
}
}

namespace
{
using IceTest::Expect;

// A scene in which the ice is drawn: a red unlit cone on the left, the ice on the right, the
// ice pass with cracks. Reports the messages of the whole process, whether the cone is drawn,
// how many pixels the ice changes, OpenGL errors and the time of the first frame.
struct DrawnResult
{
  int Errors = 0;
  int Warnings = 0;
  std::string Last;
  bool ConeDrawn = false;
  size_t IcePixels = 0;
  std::string GLErrors;
  double Seconds = 0.0;
  vtkIdType CrackPolygons = -1;
  std::string Describe() const
  {
    return std::to_string(this->Errors) + " error(s), " + std::to_string(this->Warnings) +
      " warning(s)" + (this->Last.empty() ? std::string() : " (\"" + this->Last + "\")") +
      "; cone " + (this->ConeDrawn ? "drawn" : "NOT drawn") + "; ice changes " +
      std::to_string(this->IcePixels) + " pixels" +
      (this->GLErrors.empty() ? std::string() : "; OpenGL errors: " + this->GLErrors);
  }
};

DrawnResult RenderDrawn(vtkAlgorithm* source, const std::function<void(vtkIceMapper*)>& configure,
  vtkTexture* environment = nullptr)
{
  vtkSmartPointer<vtkTexture> sky = environment
    ? vtkSmartPointer<vtkTexture>(environment)
    : IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 64);
  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(sky);
  vtkNew<vtkConeSource> cone;
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->SetPosition(-1.2, 0.0, 0.0);
  coneActor->GetProperty()->SetColor(1.0, 0.0, 0.0);
  coneActor->GetProperty()->LightingOff();
  renderer->AddActor(coneActor);
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->GetIceProperty()->SetNumberOfCracks(8);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  ice->SetPosition(1.0, 0.0, 0.0);
  renderer->AddActor(ice);
  vtkNew<vtkIcePass> pass;
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(240, 160);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 1.5, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetClippingRange(1.0, 20.0);

  DrawnResult result;
  ice->VisibilityOff();
  window->Render();
  const IceTest::Image without = IceTest::Capture(window);
  ice->VisibilityOn();
  IceTest::MessageCounter messages;
  messages.Install(true);
  configure(mapper);
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  window->Render();
  messages.Uninstall();
  result.Errors = messages.Errors();
  result.Warnings = messages.Warnings();
  result.Last = messages.Last();
  const std::string::size_type preamble = result.Last.find("): ");
  if (preamble != std::string::npos)
  {
    result.Last = result.Last.substr(preamble + 3);
  }
  result.Last.erase(result.Last.find_last_not_of("\n") + 1);
  result.GLErrors = IceTest::TakeGLErrors(window);
  if (vtkPolyData* cracks = mapper->GetCrackGeometry())
  {
    result.CrackPolygons = cracks->GetNumberOfPolys();
  }
  const IceTest::Image with = IceTest::Capture(window);
  int coneX;
  int coneY;
  {
    renderer->SetWorldPoint(-1.2, 0.0, 0.0, 1.0);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    coneX = static_cast<int>(display[0]);
    coneY = static_cast<int>(display[1]);
  }
  const unsigned char* conePixel = with.At(coneX, coneY);
  result.ConeDrawn = conePixel[0] == 255 && conePixel[1] == 0 && conePixel[2] == 0;
  for (size_t p = 0; p < with.RGB.size() / 3; ++p)
  {
    result.IcePixels += IceTest::PixelDifference(&with.RGB[3 * p], &without.RGB[3 * p]) > 8;
  }
  return result;
}

vtkSmartPointer<vtkAlgorithm> Flat()
{
  // A square sheet, tilted so that its plane is none of the axis planes.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(8, 8);
  vtkNew<vtkTransform> tilt;
  tilt->RotateX(-50.0);
  tilt->RotateY(25.0);
  tilt->Scale(1.5, 1.5, 1.5);
  auto place = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  place->SetInputConnection(plane->GetOutputPort());
  place->SetTransform(tilt);
  return place;
}

vtkSmartPointer<vtkAlgorithm> Bowl()
{
  // The lower half of a sphere: open at the top.
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  sphere->SetStartPhi(90.0);
  sphere->SetRadius(0.8);
  return sphere;
}

bool CheckFlat()
{
  vtkSmartPointer<vtkAlgorithm> flat = Flat();
  const DrawnResult r = RenderDrawn(flat, [](vtkIceMapper*) {});
  const bool noCracks = r.CrackPolygons == 0;
  return Expect(r.Errors == 0 && r.Warnings == 1 && r.Last.find("flat") != std::string::npos &&
      r.ConeDrawn && r.IcePixels > 1000 && r.GLErrors.empty() && noCracks,
    "flat ice (a tilted sheet, no volume): " + r.Describe() + "; cracks " +
      (noCracks ? "left out" : "NOT left out"));
}

bool CheckOpen()
{
  vtkSmartPointer<vtkAlgorithm> bowl = Bowl();
  const DrawnResult screen = RenderDrawn(bowl, [](vtkIceMapper*) {});
  bool ok = Expect(screen.Errors + screen.Warnings == 0 && screen.ConeDrawn &&
      screen.IcePixels > 1000 && screen.GLErrors.empty(),
    "open surface (a bowl), screen-space interior: " + screen.Describe());
  const DrawnResult interval =
    RenderDrawn(bowl, [](vtkIceMapper* m) { m->SetInteriorMethodToPaperPasses(); });
  ok = Expect(interval.Errors + interval.Warnings == 0 && interval.ConeDrawn &&
           interval.IcePixels > 1000 && interval.GLErrors.empty(),
         "open surface (a bowl), paper passes, depth-interval crack clipping: " +
           interval.Describe()) &&
    ok;
  // Crack clipping belongs to the paper's passes.
  const DrawnResult geometry = RenderDrawn(bowl, [](vtkIceMapper* m) {
    m->SetInteriorMethodToPaperPasses();
    m->GetPaperInterior()->SetCrackClippingToGeometry();
  });
  ok = Expect(geometry.Errors == 0 && geometry.Warnings == 1 &&
           geometry.Last.find("not a closed surface") != std::string::npos && geometry.ConeDrawn &&
           geometry.IcePixels > 1000 && geometry.GLErrors.empty(),
         "open surface (a bowl), paper passes, geometry crack clipping: " + geometry.Describe()) &&
    ok;
  return ok;
}

// A program that did not load VTKIce::RenderingIcePaper (its factory override disabled here):
// the paper's passes say once what to link, and the rest of the ice and the scene are drawn.
bool CheckPaperWithoutModule()
{
  vtkObjectFactory::SetAllEnableFlags(0, "vtkIcePaperInterior");
  vtkSmartPointer<vtkIcePaperInterior> bare = vtkSmartPointer<vtkIcePaperInterior>::New();
  vtkObjectFactory::SetAllEnableFlags(1, "vtkIcePaperInterior");
  vtkNew<vtkSphereSource> sphere;
  const DrawnResult r = RenderDrawn(sphere, [bare](vtkIceMapper* m) {
    m->SetInteriorMethodToPaperPasses();
    m->SetPaperInterior(bare);
  });
  return Expect(!bare->CanDraw() && r.Errors == 1 && r.Warnings == 0 &&
      r.Last.find("VTKIce::RenderingIcePaper") != std::string::npos && r.ConeDrawn &&
      r.IcePixels > 1000 && r.GLErrors.empty(),
    "paper passes without their module: " + r.Describe());
}

bool CheckHuge()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(1000);
  sphere->SetPhiResolution(502);
  sphere->SetRadius(0.8);
  sphere->Update();
  const vtkIdType triangles = sphere->GetOutput()->GetNumberOfPolys();
  const DrawnResult r = RenderDrawn(sphere, [](vtkIceMapper*) {});
  return Expect(triangles >= 1000000 && r.Errors + r.Warnings == 0 && r.ConeDrawn &&
      r.IcePixels > 1000 && r.GLErrors.empty(),
    "huge mesh (" + std::to_string(triangles) + " triangles): " + r.Describe() + "; first frame " +
      std::to_string(r.Seconds) + " s");
}

bool CheckParameters()
{
  bool ok = true;
  vtkNew<vtkIceMapper> mapper;
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(mapper);
  // The look's parameters are its ice property's, which warns about them.
  recorder->Watch(mapper->GetIceProperty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // Out of range: clamped, silently, as vtkSetClampMacro does.
  mapper->GetIceProperty()->SetRefractionRatio(-1.0);
  const double eta = mapper->GetIceProperty()->GetRefractionRatio();
  mapper->GetIceProperty()->SetRefractionRatio(inf);
  const double etaInf = mapper->GetIceProperty()->GetRefractionRatio();
  mapper->GetIceProperty()->SetBackNormalWeight(1.5);
  const double aHigh = mapper->GetIceProperty()->GetBackNormalWeight();
  mapper->GetIceProperty()->SetBackNormalWeight(-0.5);
  const double aLow = mapper->GetIceProperty()->GetBackNormalWeight();
  mapper->GetIceProperty()->SetNumberOfCracks(1000000);
  const int cracks = mapper->GetIceProperty()->GetNumberOfCracks();
  mapper->GetIceProperty()->SetIceColor(2.0, -1.0, 0.5);
  const double* tint = mapper->GetIceProperty()->GetIceColor();
  ok =
    Expect(eta == 0.05 && etaInf == 20.0 && aHigh == 1.0 && aLow == 0.0 && cracks == 1000 &&
        tint[0] == 1.0 && tint[1] == 0.0 && tint[2] == 0.5 && recorder->Warnings.empty(),
      "out of range: eta -1 -> " + std::to_string(eta) + ", inf -> " + std::to_string(etaInf) +
        "; a 1.5 -> " + std::to_string(aHigh) + ", -0.5 -> " + std::to_string(aLow) +
        "; 10^6 cracks -> " + std::to_string(cracks) + "; colour (2, -1, 0.5) -> (" +
        std::to_string(tint[0]) + ", " + std::to_string(tint[1]) + ", " + std::to_string(tint[2]) +
        "); " + std::to_string(recorder->Warnings.size()) + " warnings") &&
    ok;

  // NaN: one warning each, the value is kept.
  mapper->GetIceProperty()->SetRefractionRatio(0.75);
  mapper->GetIceProperty()->SetBackNormalWeight(0.33);
  const vtkMTimeType before = mapper->GetMTime();
  mapper->GetIceProperty()->SetRefractionRatio(nan);
  mapper->GetIceProperty()->SetBackNormalWeight(nan);
  mapper->GetIceProperty()->SetFresnelPower(nan);
  mapper->GetIceProperty()->SetCrackIntensity(nan);
  mapper->GetIceProperty()->SetIceColor(0.5, nan, 0.5);
  const bool kept = mapper->GetIceProperty()->GetRefractionRatio() == 0.75 &&
    mapper->GetIceProperty()->GetBackNormalWeight() == 0.33 &&
    mapper->GetIceProperty()->GetFresnelPower() == 3.0 &&
    mapper->GetIceProperty()->GetCrackIntensity() == 1.0 &&
    mapper->GetIceProperty()->GetIceColor()[1] == 0.0 && mapper->GetMTime() == before;
  bool named = recorder->Warnings.size() == 5;
  for (const std::string& warning : recorder->Warnings)
  {
    named = named && warning.find("NaN") != std::string::npos;
  }
  ok = Expect(kept && named,
         "NaN eta, a, Fresnel power, crack intensity, colour: " +
           std::to_string(recorder->Warnings.size()) + " warnings" +
           (recorder->Warnings.empty() ? std::string() : " (\"" + recorder->Warnings[0] + "\")") +
           ", values " + (kept ? "kept" : "CHANGED")) &&
    ok;

  // The clamped extremes render; 10^6 cracks (1000) cost one draw.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  const DrawnResult r = RenderDrawn(sphere, [](vtkIceMapper* m) {
    m->GetIceProperty()->SetRefractionRatio(-5.0);
    m->GetIceProperty()->SetBackNormalWeight(7.0);
    m->GetIceProperty()->SetFresnelPower(1e300);
    m->GetIceProperty()->SetNumberOfCracks(1000000);
    m->GetIceProperty()->SetCrackIntensity(1e9);
  });
  ok = Expect(r.Errors + r.Warnings == 0 && r.ConeDrawn && r.IcePixels > 1000 && r.GLErrors.empty(),
         "clamped extremes (eta, a, Fresnel power, 1000 cracks, crack intensity) render: " +
           r.Describe() + "; first frame " + std::to_string(r.Seconds) + " s") &&
    ok;
  return ok;
}

bool CheckEnvironment(const std::string& temporary)
{
  bool ok = true;
  for (const std::string& path :
    { temporary + "/no-such-environment.hdr", temporary + "/corrupt-environment.png" })
  {
    if (path.find("corrupt") != std::string::npos)
    {
      std::ofstream(path) << "\x89PNG\r\n\x1a\nthis is not an image";
    }
    vtkNew<vtkIceEnvironmentReader> reader;
    reader->SetFileName(path.c_str());
    vtkNew<vtkTexture> texture;
    reader->ConfigureTexture(texture);
    vtkNew<vtkSphereSource> sphere;
    const DrawnResult r = RenderDrawn(
      sphere, [](vtkIceMapper*) {}, texture);
    ok =
      Expect(r.Errors == 1 && r.Warnings == 1 && r.Last.find("built-in sky") != std::string::npos &&
          r.ConeDrawn && r.IcePixels > 1000 && r.GLErrors.empty(),
        "environment '" + path.substr(path.rfind('/') + 1) + "': " + r.Describe()) &&
      ok;
  }
  return ok;
}
}

int TestIceBadInput(int argc, char* argv[])
{
  vtkNew<vtkPolyData> empty;
  bool ok = CheckCase("empty", empty, "has no polygons");
  ok = CheckCase("lines only", LinesOnly(), "has no polygons") && ok;
  ok = CheckCase("vertices only", VerticesOnly(), "has no polygons") && ok;
  ok = CheckCase("NaN points", NaNTriangle(), "NaN or infinite") && ok;
  ok = CheckCase("infinite point", InfiniteSphere(), "NaN or infinite") && ok;
  ok = CheckFlat() && ok;
  ok = CheckOpen() && ok;
  ok = CheckPaperWithoutModule() && ok;
  ok = CheckHuge() && ok;
  ok = CheckParameters() && ok;
  std::string temporary = ".";
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-T")
    {
      temporary = argv[i + 1];
    }
  }
  ok = CheckEnvironment(temporary) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
