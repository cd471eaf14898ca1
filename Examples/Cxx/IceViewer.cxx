#include "IceViewer.h"

#include "IceOutputFile.h"

#include "vtkCallbackCommand.h"
#include "vtkIceMapper.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <sstream>

vtkStandardNewMacro(IceViewer);

namespace
{
// The viewer's keys: what each does, for the legend.
struct Key
{
  char Code;
  const char* What;
  const char* Setting; // shown with its current value
};
const Key Keys[] = {
  { '1', "one-/two-sided", "two-sided" },
  { '2', "two-sided method", "two-sided-method" },
  { 'i', "interior method", "interior" },
  { 'c', "cracks on/off", "cracks" },
  { 'a', "air on/off", "air" },
  { 'b', "bumps on/off", "bumps" },
  { 'g', "glistening on/off", "glistening" },
  { 'd', "dynamic cube map on/off", "cube-map" },
  { 'v', "next debug view", "debug-view" },
  { '[', "eta down / up ]", "eta" },
  { '-', "milkiness down / up =", "milkiness" },
  { ',', "cracks fewer / more .", nullptr },
  { ';', "snow less / more '", "snow" },
  { 's', "save screenshot + preset", nullptr },
  { 'h', "hide / show this legend", nullptr },
};
}

//------------------------------------------------------------------------------
IceViewer::IceViewer()
{
  this->Legend->GetTextProperty()->SetFontSize(14);
  this->Legend->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  this->Legend->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
  this->Legend->GetTextProperty()->SetBackgroundOpacity(0.5);
  this->Legend->SetPosition(8, 8);
  this->FrameTime->GetTextProperty()->SetFontSize(14);
  this->FrameTime->GetTextProperty()->SetColor(1.0, 1.0, 0.6);
  this->FrameTime->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
  this->FrameTime->GetTextProperty()->SetBackgroundOpacity(0.5);
  this->FrameTime->GetTextProperty()->SetJustificationToRight();
  this->FrameTime->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->FrameTime->SetPosition(0.99, 0.96);
  this->FrameTime->SetInput("frame: -");
}

//------------------------------------------------------------------------------
IceViewer::~IceViewer()
{
  if (this->Renderer && this->EndObserver)
  {
    this->Renderer->RemoveObserver(this->EndObserver);
  }
}

//------------------------------------------------------------------------------
void IceViewer::Setup(const IceLook::Target& target, vtkRenderer* renderer)
{
  this->Target = target;
  this->Renderer = renderer;
  renderer->AddViewProp(this->Legend);
  renderer->AddViewProp(this->FrameTime);
  // The frame time of every render, shown in the next frame.
  vtkNew<vtkCallbackCommand> ended;
  ended->SetClientData(this);
  ended->SetCallback([](vtkObject*, unsigned long, void* viewer, void*) {
    static_cast<IceViewer*>(viewer)->ShowFrameTime();
  });
  this->EndObserver = renderer->AddObserver(vtkCommand::EndEvent, ended);
  for (auto setting : { std::make_pair("cracks", &this->Cracks), std::make_pair("air", &this->Air),
         std::make_pair("bumps", &this->Bumps) })
  {
    const std::string value = IceLook::Value(target, setting.first);
    if (std::stod(value) != 0.0)
    {
      *setting.second = value;
    }
  }
  this->UpdateLegend();
}

//------------------------------------------------------------------------------
void IceViewer::ShowFrameTime()
{
  char text[64];
  std::snprintf(
    text, sizeof(text), "frame: %.1f ms", 1000.0 * this->Renderer->GetLastRenderTimeInSeconds());
  this->FrameTime->SetInput(text);
}

//------------------------------------------------------------------------------
std::string IceViewer::GetFrameTime() const
{
  return this->FrameTime->GetInput() ? this->FrameTime->GetInput() : "";
}

//------------------------------------------------------------------------------
std::string IceViewer::GetLegend() const
{
  return this->Legend->GetInput() ? this->Legend->GetInput() : "";
}

//------------------------------------------------------------------------------
void IceViewer::UpdateLegend()
{
  std::ostringstream text;
  for (const Key& key : Keys)
  {
    text << key.Code << "  " << key.What;
    if (key.Setting)
    {
      text << ": " << IceLook::Value(this->Target, key.Setting);
    }
    text << "\n";
  }
  text << "mouse: trackball camera, e: quit";
  this->Legend->SetInput(text.str().c_str());
  this->Legend->SetVisibility(this->LegendVisible);
}

//------------------------------------------------------------------------------
void IceViewer::Toggle(const std::string& name)
{
  IceLook::Apply(this->Target, name, IceLook::Value(this->Target, name) == "on" ? "off" : "on");
}

//------------------------------------------------------------------------------
void IceViewer::OffOrBack(const std::string& name, std::string& remembered)
{
  const std::string value = IceLook::Value(this->Target, name);
  if (std::stod(value) != 0.0)
  {
    remembered = value;
    IceLook::Apply(this->Target, name, "0");
  }
  else
  {
    IceLook::Apply(this->Target, name, remembered);
  }
}

//------------------------------------------------------------------------------
void IceViewer::Cycle(const std::string& name)
{
  const std::vector<std::string> names = IceLook::Choices(name);
  const std::string current = IceLook::Value(this->Target, name);
  for (size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == current)
    {
      IceLook::Apply(this->Target, name, names[(i + 1) % names.size()]);
      return;
    }
  }
}

//------------------------------------------------------------------------------
void IceViewer::Step(const std::string& name, double delta)
{
  // Within the library's range: a step past an end stops at it.
  const std::string range = IceLook::Range(name);
  double low = 0.0;
  double high = 0.0;
  std::sscanf(range.c_str(), "[%lf, %lf]", &low, &high);
  const double value = std::stod(IceLook::Value(this->Target, name)) + delta;
  std::ostringstream text;
  text.precision(10);
  text << std::min(std::max(value, low), high);
  IceLook::Apply(this->Target, name, text.str());
}

//------------------------------------------------------------------------------
bool IceViewer::HandleKey(char key)
{
  switch (key)
  {
    case '1':
      this->Toggle("two-sided");
      break;
    case '2':
      this->Cycle("two-sided-method");
      break;
    case 'i':
      this->Cycle("interior");
      break;
    case 'c':
      this->OffOrBack("cracks", this->Cracks);
      break;
    case 'a':
      this->OffOrBack("air", this->Air);
      break;
    case 'b':
      this->OffOrBack("bumps", this->Bumps);
      break;
    case 'g':
      this->Toggle("glistening");
      break;
    case 'd':
      this->Toggle("cube-map");
      break;
    case 'v':
      this->Cycle("debug-view");
      break;
    case '[':
    case ']':
      this->Step("eta", key == '[' ? -0.02 : 0.02);
      break;
    case '-':
    case '=':
      this->Step("milkiness", key == '-' ? -0.1 : 0.1);
      break;
    case ',':
    case '.':
      this->Step("cracks", key == ',' ? -1.0 : 1.0);
      break;
    case ';':
    case '\'':
      this->Step("snow", key == ';' ? -0.1 : 0.1);
      break;
    case 's':
      this->Save();
      break;
    case 'h':
      this->LegendVisible = !this->LegendVisible;
      break;
    default:
      return false;
  }
  this->UpdateLegend();
  return true;
}

//------------------------------------------------------------------------------
void IceViewer::Save()
{
  ++this->Saves;
  const std::string base = this->OutputDirectory + "/ice-view-" + std::to_string(this->Saves);
  // The picture without the legend and the readout.
  const bool legend = this->Legend->GetVisibility() != 0;
  this->Legend->SetVisibility(0);
  this->FrameTime->SetVisibility(0);
  vtkRenderWindow* window = this->Renderer->GetRenderWindow();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  this->Legend->SetVisibility(legend);
  this->FrameTime->SetVisibility(1);
  std::string problem = IceOutputFile::WriteImage(base + ".png", grab->GetOutput());
  if (problem.empty())
  {
    problem = IceOutputFile::Write(base + ".ice", IceLook::WritePreset(this->Target, {}));
  }
  this->LastSaved = problem.empty() ? base + ".png " + base + ".ice" : problem;
}

//------------------------------------------------------------------------------
void IceViewer::OnChar()
{
  vtkRenderWindowInteractor* interactor = this->Interactor;
  if (interactor && this->Target.Mapper && this->HandleKey(interactor->GetKeyCode()))
  {
    interactor->Render();
    return;
  }
  this->Superclass::OnChar();
}
