// Bad input for vtkIceMapper (empty polydata, lines only, NaN points) gives one clear VTK error
// per input, draws nothing for that actor, and leaves the rest of the scene rendering.
#include "IceTestUtilities.h"
#include "vtkIceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <limits>

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
  const bool oneError = recorder->Errors.size() == 1 &&
    recorder->Errors[0].find(expected) != std::string::npos;
  std::cout << name << ": " << recorder->Errors.size() << " error(s)"
            << (recorder->Errors.empty() ? std::string() : ": " + recorder->Errors[0])
            << "; cone pixel " << int(middle[0]) << "," << int(middle[1]) << "," << int(middle[2])
            << "\n";
  return coneDrawn && oneError;
}
}

int TestIceBadInput(int, char*[])
{
  vtkNew<vtkPolyData> empty;
  bool ok = CheckCase("empty", empty, "has no polygons");
  ok = CheckCase("lines only", LinesOnly(), "has no polygons") && ok;
  ok = CheckCase("NaN points", NaNTriangle(), "NaN or infinite") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
