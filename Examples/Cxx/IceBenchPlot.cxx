// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's plot: four VTK charts rendered offscreen into one PNG.
#include "IceBench.h"

#include "vtkIceMapper.h"
#include "IceOutputFile.h"

#include "vtkAxis.h"
#include "vtkChartLegend.h"
#include "vtkChartMatrix.h"
#include "vtkChartXY.h"
#include "vtkContextActor.h"
#include "vtkContextScene.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPen.h"
#include "vtkPlot.h"
#include "vtkPlotBar.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkVector.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace
{
using IceBench::Configuration;
using IceBench::Group;
using IceBench::Material;

const double Colors[6][3] = { { 0.35, 0.35, 0.35 }, { 0.30, 0.60, 0.85 }, { 0.10, 0.35, 0.70 },
  { 0.85, 0.45, 0.15 }, { 0.55, 0.20, 0.55 }, { 0.20, 0.60, 0.30 } };

vtkSmartPointer<vtkDoubleArray> Column(const char* name, vtkIdType rows)
{
  auto column = vtkSmartPointer<vtkDoubleArray>::New();
  column->SetName(name);
  column->SetNumberOfTuples(rows);
  column->Fill(0.0);
  return column;
}

void Style(vtkChartXY* chart, const std::string& title, const std::string& x, const std::string& y)
{
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(15);
  chart->GetTitleProperties()->BoldOn();
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(x);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(y);
  for (int axis : { vtkAxis::BOTTOM, vtkAxis::LEFT })
  {
    chart->GetAxis(axis)->GetTitleProperties()->SetFontSize(12);
    chart->GetAxis(axis)->GetLabelProperties()->SetFontSize(11);
  }
  chart->SetShowLegend(true);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(11);
}

void Labels(
  vtkAxis* axis, const std::vector<double>& positions, const std::vector<std::string>& labels)
{
  vtkNew<vtkDoubleArray> p;
  vtkNew<vtkStringArray> l;
  for (size_t i = 0; i < positions.size(); ++i)
  {
    p->InsertNextValue(positions[i]);
    l->InsertNextValue(labels[i]);
  }
  axis->SetCustomTickPositions(p, l);
}

void Line(vtkChartXY* chart, vtkTable* table, const char* x, const char* y, const double color[3],
  bool dashed = false)
{
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, x, y);
  line->SetColor(color[0], color[1], color[2]);
  line->SetWidth(2.0);
  if (dashed)
  {
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
}

const Group* FindGroup(const std::vector<Group>& groups, const std::string& id)
{
  for (const Group& g : groups)
  {
    if (g.Id == id && !g.Configurations.empty() && !g.Configurations[0].Times.empty())
    {
      return &g;
    }
  }
  return nullptr;
}

// Ratios of the three ice materials per object and coverage, with the targets as lines.
void Objects(
  vtkChartXY* chart, const std::vector<Group>& groups, std::vector<vtkSmartPointer<vtkTable>>& keep)
{
  Style(chart, "Ice / plain VTK, static environment", "object (share of the screen)", "ratio");
  std::vector<const Group*> shown;
  std::vector<std::string> names;
  for (const char* prefix : { "objects-", "fullscreen-" })
  {
    for (const char* object : { "sphere", "block", "teapot" })
    {
      if (const Group* g = FindGroup(groups, std::string(prefix) + object))
      {
        shown.push_back(g);
        names.push_back(std::string(object) + (prefix[0] == 'o' ? " 1/5" : " full"));
      }
    }
  }
  const vtkIdType rows = static_cast<vtkIdType>(shown.size());
  vtkNew<vtkTable> table;
  table->AddColumn(Column("x", rows));
  // The series: material and interior method.
  const int screen = vtkIceMapper::InteriorScreenSpace;
  const Material materials[4] = { Material::OneSided, Material::TwoSided, Material::FullLook,
    Material::FullLook };
  const int interior[4] = { screen, screen, vtkIceMapper::InteriorPaperPasses, screen };
  const char* series[4] = { "one-sided", "two-sided", "full look, paper passes",
    "full look, screen space" };
  const int colors[4] = { 1, 2, 3, 5 };
  for (const char* name : series)
  {
    table->AddColumn(Column(name, rows));
  }
  std::vector<double> positions;
  double largest = 3.6; // room above the targets' lines even when every bar is below them
  for (vtkIdType r = 0; r < rows; ++r)
  {
    table->SetValue(r, 0, static_cast<double>(r + 1));
    positions.push_back(static_cast<double>(r + 1));
    for (const Configuration& c : shown[r]->Configurations)
    {
      for (int m = 0; m < 4; ++m)
      {
        if (c.Ice == materials[m] && c.Interior == interior[m] && !c.DrawEveryFace)
        {
          table->SetValue(r, m + 1, c.Ratio);
          largest = std::max(largest, c.Ratio * 1.05);
        }
      }
    }
  }
  for (int m = 0; m < 4; ++m)
  {
    vtkPlot* bars = chart->AddPlot(vtkChart::BAR);
    bars->SetInputData(table, "x", series[m]);
    const double* color = Colors[colors[m]];
    bars->SetColor(color[0], color[1], color[2]);
  }
  // Targets: two-sided <= 1.3, full look <= 1.5.
  vtkNew<vtkTable> targets;
  targets->AddColumn(Column("x", 2));
  targets->AddColumn(Column("target two-sided 1.3", 2));
  targets->AddColumn(Column("target full look 1.5", 2));
  for (vtkIdType r = 0; r < 2; ++r)
  {
    targets->SetValue(r, 0, r == 0 ? 0.5 : static_cast<double>(rows) + 0.5);
    targets->SetValue(r, 1, 1.3);
    targets->SetValue(r, 2, 1.5);
  }
  Line(chart, targets, "x", "target two-sided 1.3", Colors[2], true);
  Line(chart, targets, "x", "target full look 1.5", Colors[3], true);
  Labels(chart->GetAxis(vtkAxis::BOTTOM), positions, names);
  chart->GetAxis(vtkAxis::BOTTOM)->SetBehavior(vtkAxis::FIXED);
  chart->GetAxis(vtkAxis::BOTTOM)->SetRange(0.4, static_cast<double>(rows) + 0.6);
  chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
  chart->GetAxis(vtkAxis::LEFT)->SetRange(0.0, largest);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  keep.push_back(table.Get());
  keep.push_back(targets.Get());
}

// A configuration's label short enough for the left axis of the dynamic chart.
std::string ShortLabel(std::string label)
{
  const std::pair<const char*, const char*> replacements[] = { { "cube map ", "" },
    { "two-sided, ", "" }, { " faces per frame, 512", " faces/frame" },
    { " face per frame, 512", " face/frame" }, { ", still scene", ", still" },
    { ", ball moving", ", moving" }, { "static environment", "static env." } };
  for (const auto& r : replacements)
  {
    const std::string::size_type at = label.find(r.first);
    if (at != std::string::npos)
    {
      label.replace(at, std::string(r.first).size(), r.second);
    }
  }
  return label;
}

// Ratios of the dynamic-environment configurations as horizontal bars.
void Dynamic(
  vtkChartXY* chart, const std::vector<Group>& groups, std::vector<vtkSmartPointer<vtkTable>>& keep)
{
  Style(chart, "Dynamic cube map: ice / plain VTK, teapot in the landscape", "ratio", "");
  chart->SetShowLegend(false);
  const Group* g = FindGroup(groups, "dynamic-teapot");
  if (!g)
  {
    return;
  }
  const vtkIdType rows = static_cast<vtkIdType>(g->Configurations.size()) - 1;
  vtkNew<vtkTable> table;
  table->AddColumn(Column("y", rows));
  table->AddColumn(Column("ratio", rows));
  std::vector<double> positions;
  std::vector<std::string> labels;
  for (vtkIdType r = 0; r < rows; ++r)
  {
    const Configuration& c = g->Configurations[r + 1];
    const double y = static_cast<double>(rows - r);
    table->SetValue(r, 0, y);
    table->SetValue(r, 1, c.Ratio);
    positions.push_back(y);
    labels.push_back(ShortLabel(c.Label));
  }
  vtkPlotBar* bars = vtkPlotBar::SafeDownCast(chart->AddPlot(vtkChart::BAR));
  bars->SetOrientation(vtkPlotBar::HORIZONTAL);
  bars->SetInputData(table, "y", "ratio");
  bars->SetColor(Colors[2][0], Colors[2][1], Colors[2][2]);
  vtkNew<vtkTable> target;
  target->AddColumn(Column("x", 2));
  target->AddColumn(Column("y", 2));
  target->SetValue(0, 0, 3.0);
  target->SetValue(1, 0, 3.0);
  target->SetValue(0, 1, 0.4);
  target->SetValue(1, 1, static_cast<double>(rows) + 0.6);
  Line(chart, target, "x", "y", Colors[3], true);
  Labels(chart->GetAxis(vtkAxis::LEFT), positions, labels);
  chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
  chart->GetAxis(vtkAxis::LEFT)->SetRange(0.4, static_cast<double>(rows) + 0.6);
  chart->GetAxis(vtkAxis::BOTTOM)->SetBehavior(vtkAxis::FIXED);
  double largest = 3.5;
  for (const Configuration& c : g->Configurations)
  {
    largest = std::max(largest, c.Ratio * 1.05);
  }
  chart->GetAxis(vtkAxis::BOTTOM)->SetRange(0.0, largest);
  keep.push_back(table.Get());
  keep.push_back(target.Get());
}

// Milliseconds per frame against the triangle count, log-log.
void Triangles(
  vtkChartXY* chart, const std::vector<Group>& groups, std::vector<vtkSmartPointer<vtkTable>>& keep)
{
  Style(chart, "Triangles: sphere, static environment, about 1/5 of the screen", "triangles",
    "ms per frame (median)");
  std::vector<const Group*> shown;
  for (const char* size : { "1k", "10k", "100k", "1M" })
  {
    if (const Group* g = FindGroup(groups, std::string("triangles-") + size))
    {
      shown.push_back(g);
    }
  }
  const vtkIdType rows = static_cast<vtkIdType>(shown.size());
  vtkNew<vtkTable> table;
  table->AddColumn(Column("triangles", rows));
  // The full look with its cost per fragment (paper passes) and per pixel (screen space).
  const char* series[5] = { "plain VTK", "one-sided ice", "two-sided ice",
    "full look, paper passes", "full look, screen space" };
  const Material materials[5] = { Material::Plain, Material::OneSided, Material::TwoSided,
    Material::FullLook, Material::FullLook };
  const int interior[5] = { 0, 0, 0, vtkIceMapper::InteriorPaperPasses,
    vtkIceMapper::InteriorScreenSpace };
  const int colors[5] = { 0, 1, 2, 3, 5 };
  for (const char* name : series)
  {
    table->AddColumn(Column(name, rows));
  }
  for (vtkIdType r = 0; r < rows; ++r)
  {
    table->SetValue(r, 0, static_cast<double>(shown[r]->Triangles));
    for (const Configuration& c : shown[r]->Configurations)
    {
      for (int m = 0; m < 5; ++m)
      {
        if (c.Ice == materials[m] && (c.Ice != Material::FullLook || c.Interior == interior[m]))
        {
          table->SetValue(r, m + 1, c.Stats.Median);
        }
      }
    }
  }
  if (rows > 0)
  {
    for (int m = 0; m < 5; ++m)
    {
      Line(chart, table, "triangles", series[m], Colors[colors[m]]);
    }
  }
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  keep.push_back(table.Get());
}

// Milliseconds per frame against the number of cracks.
void Cracks(
  vtkChartXY* chart, const std::vector<Group>& groups, std::vector<vtkSmartPointer<vtkTable>>& keep)
{
  Style(chart, "Cracks: teapot, two-sided, about 1/5 of the screen (log scale)", "cracks",
    "ms per frame (median)");
  const Group* g = FindGroup(groups, "cracks-teapot");
  if (!g)
  {
    return;
  }
  // One row per number of cracks, the two interior methods side by side.
  std::vector<int> counts;
  for (const Configuration& c : g->Configurations)
  {
    if (c.Ice != Material::Plain && c.Interior == vtkIceMapper::InteriorScreenSpace)
    {
      counts.push_back(c.Cracks);
    }
  }
  const vtkIdType rows = static_cast<vtkIdType>(counts.size());
  vtkNew<vtkTable> table;
  table->AddColumn(Column("position", rows));
  table->AddColumn(Column("plain VTK", rows));
  table->AddColumn(Column("paper passes", rows));
  table->AddColumn(Column("screen space", rows));
  std::vector<double> positions;
  std::vector<std::string> labels;
  for (vtkIdType r = 0; r < rows; ++r)
  {
    table->SetValue(r, 0, static_cast<double>(r));
    table->SetValue(r, 1, g->Configurations[0].Stats.Median);
    for (const Configuration& c : g->Configurations)
    {
      if (c.Ice != Material::Plain && c.Cracks == counts[r])
      {
        const int column = c.Interior == vtkIceMapper::InteriorPaperPasses ? 2 : 3;
        table->SetValue(r, column, c.Stats.Median);
      }
    }
    positions.push_back(static_cast<double>(r));
    labels.push_back(std::to_string(counts[r]));
  }
  Line(chart, table, "position", "plain VTK", Colors[0]);
  Line(chart, table, "position", "paper passes", Colors[3]);
  Line(chart, table, "position", "screen space", Colors[5]);
  Labels(chart->GetAxis(vtkAxis::BOTTOM), positions, labels);
  chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
  // Logarithmic: the paper passes' cost grows a hundredfold over the series.
  double largest = 1.0;
  double smallest = 1.0e9;
  for (const Configuration& c : g->Configurations)
  {
    largest = std::max(largest, c.Stats.Median * 1.3);
    smallest = std::min(smallest, c.Stats.Median * 0.7);
  }
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  chart->GetAxis(vtkAxis::LEFT)->SetRange(std::max(smallest, 0.1), largest);
  keep.push_back(table.Get());
}
}

std::string IceBench::WritePlot(
  const std::vector<Group>& groups, const std::string& path, const std::string& subtitle)
{
  const int width = 1600;
  const int height = 1100;
  // A context actor in a plain renderer: a vtkContextView would also make an X interactor.
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  window->SetOffScreenRendering(1);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  window->AddRenderer(renderer);
  vtkNew<vtkContextActor> charts;
  charts->GetScene()->SetRenderer(renderer);
  renderer->AddActor(charts);

  vtkNew<vtkChartMatrix> matrix;
  matrix->SetSize(vtkVector2i(2, 2));
  matrix->SetGutter(vtkVector2f(110.0f, 90.0f));
  matrix->SetBorders(90, 60, 30, 60);
  matrix->Allocate();
  charts->GetScene()->AddItem(matrix);

  std::vector<vtkSmartPointer<vtkTable>> keep;
  // Chart (0, 0) is the bottom left.
  Objects(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, 1))), groups, keep);
  Dynamic(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(1, 1))), groups, keep);
  Triangles(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, 0))), groups, keep);
  Cracks(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(1, 0))), groups, keep);
  vtkNew<vtkTextActor> caption;
  caption->SetInput(("ice-bench, 1024x768: " + subtitle).c_str());
  caption->GetTextProperty()->SetFontSize(14);
  caption->GetTextProperty()->SetColor(0.2, 0.2, 0.2);
  caption->SetDisplayPosition(12, 10);
  renderer->AddViewProp(caption);

  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  return IceOutputFile::WriteImage(path, grab->GetOutput());
}
