// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceViewer.h"

#include "IceOutputFile.h"
#include "IceScene.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkIceMapper.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
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
  { '[', "ior down / up ]", "ior" },
  { '-', "milkiness down / up =", "milkiness" },
  { ',', "cracks fewer / more .", nullptr },
  { ';', "snow less / more '", "snow" },
  { 's', "save screenshot + preset", nullptr },
  { 'h', "this list on/off", nullptr },
};
}

//------------------------------------------------------------------------------
IceViewer::IceViewer()
{
  this->Legend->GetTextProperty()->SetFontSize(14);
  // Courier: key names read as typed ('[' is not '(' at small sizes).
  this->Legend->GetTextProperty()->SetFontFamilyToCourier();
  this->Legend->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  this->Legend->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
  this->Legend->GetTextProperty()->SetBackgroundOpacity(0.5);
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
    this->Renderer->RemoveObserver(this->StartObserver);
  }
}

//------------------------------------------------------------------------------
void IceViewer::Setup(const vtkIceLookTable::Target& target, vtkRenderer* renderer)
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
  // The legend follows the window's size, before each render draws it.
  vtkNew<vtkCallbackCommand> started;
  started->SetClientData(this);
  started->SetCallback([](vtkObject*, unsigned long, void* viewer, void*) {
    static_cast<IceViewer*>(viewer)->FitLegend();
  });
  this->StartObserver = renderer->AddObserver(vtkCommand::StartEvent, started);
  for (auto setting : { std::make_pair("cracks", &this->Cracks), std::make_pair("air", &this->Air),
         std::make_pair("bumps", &this->Bumps) })
  {
    const std::string value = vtkIceLookTable::Value(target, setting.first);
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
  return this->LegendText;
}

//------------------------------------------------------------------------------
int IceViewer::GetLegendFontSize() const
{
  return this->Legend->GetTextProperty()->GetFontSize();
}

//------------------------------------------------------------------------------
void IceViewer::FitLegend()
{
  const int* size = this->Renderer ? this->Renderer->GetSize() : nullptr;
  if (!size || size[0] <= 0 || size[1] <= 0)
  {
    return;
  }
  // 14 px at 1024x768, in proportion to the smaller side's share of that; 8 px stays readable.
  const double scale = std::min(size[0] / 1024.0, size[1] / 768.0);
  const int font = std::max(8, std::min(28, static_cast<int>(std::lround(14.0 * scale))));
  this->Legend->GetTextProperty()->SetFontSize(font);
  this->FrameTime->GetTextProperty()->SetFontSize(font);
  this->Legend->SetPosition(font / 2 + 1, font / 2 + 1);
  const double window = static_cast<double>(size[0]) * size[1];
  auto share = [this, window](const std::string& text) {
    this->Legend->SetInput(text.c_str());
    double box[4] = { 0.0, 0.0, 0.0, 0.0 };
    this->Legend->GetBoundingBox(this->Renderer, box);
    return (box[1] - box[0]) * (box[3] - box[2]) / window;
  };
  const bool fits = share(this->LegendText) <= MaximumLegendShare;
  if (fits)
  {
    this->Shown = this->LegendToggled ? LegendNone : LegendFull;
  }
  else
  {
    this->Shown = this->LegendToggled ? LegendFull : LegendHint;
  }
  const std::string hint = "h  keys";
  this->Share =
    this->Shown == LegendNone ? 0.0 : share(this->Shown == LegendFull ? this->LegendText : hint);
  this->Legend->SetVisibility(this->Shown != LegendNone && !this->TextHidden);
  this->FrameTime->SetVisibility(!this->TextHidden);
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
      text << ": " << vtkIceLookTable::Value(this->Target, key.Setting);
    }
    text << "\n";
  }
  text << "mouse: trackball camera, e: quit";
  this->LegendText = text.str();
  this->FitLegend();
}

//------------------------------------------------------------------------------
void IceViewer::Follow(vtkActor* image)
{
  this->Mirror = this->Target;
  this->Mirror.Mapper = vtkIceMapper::SafeDownCast(image->GetMapper());
  this->MirrorImage = image;
}

//------------------------------------------------------------------------------
void IceViewer::Set(const std::string& name, const std::string& value)
{
  vtkIceLookTable::Apply(this->Target, name, value);
  if (this->Mirror.Mapper)
  {
    vtkIceLookTable::Apply(this->Mirror, name, value);
    IceScene::ShowMirrorImage(this->MirrorImage, vtkIceLookTable::Value(this->Target, "debug-view"));
  }
}

//------------------------------------------------------------------------------
void IceViewer::Toggle(const std::string& name)
{
  this->Set(name, vtkIceLookTable::Value(this->Target, name) == "on" ? "off" : "on");
}

//------------------------------------------------------------------------------
void IceViewer::OffOrBack(const std::string& name, std::string& remembered)
{
  const std::string value = vtkIceLookTable::Value(this->Target, name);
  if (std::stod(value) != 0.0)
  {
    remembered = value;
    this->Set(name, "0");
  }
  else
  {
    this->Set(name, remembered);
  }
}

//------------------------------------------------------------------------------
void IceViewer::Cycle(const std::string& name)
{
  const std::vector<std::string> names = vtkIceLookTable::Choices(name);
  const std::string current = vtkIceLookTable::Value(this->Target, name);
  for (size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == current)
    {
      this->Set(name, names[(i + 1) % names.size()]);
      return;
    }
  }
}

//------------------------------------------------------------------------------
void IceViewer::Step(const std::string& name, double delta)
{
  // Within the library's range: a step past an end stops at it.
  const std::string range = vtkIceLookTable::Range(name);
  double low = 0.0;
  double high = 0.0;
  std::sscanf(range.c_str(), "[%lf, %lf]", &low, &high);
  const double value = std::stod(vtkIceLookTable::Value(this->Target, name)) + delta;
  std::ostringstream text;
  text.precision(10);
  text << std::min(std::max(value, low), high);
  this->Set(name, text.str());
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
      this->Step("ior", key == '[' ? -0.02 : 0.02);
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
      this->LegendToggled = !this->LegendToggled;
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
  this->TextHidden = true;
  vtkRenderWindow* window = this->Renderer->GetRenderWindow();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  this->TextHidden = false;
  this->FitLegend();
  std::string problem = IceOutputFile::WriteImage(base + ".png", grab->GetOutput());
  if (problem.empty())
  {
    problem = IceOutputFile::Write(base + ".ice", vtkIceLookTable::WritePreset(this->Target, {}));
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
