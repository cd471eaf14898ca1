// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's output: the tables on standard output, the CSV and the Markdown, and the writing of
// the files (IceOutputFile: each whole or not at all).
#include "IceBench.h"
#include "IceOutputFile.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using IceBench::Configuration;
using IceBench::Fixed;
using IceBench::Group;
using IceBench::Height;
using IceBench::Machine;
using IceBench::Material;
using IceBench::StepNames;
using IceBench::Steps;
using IceBench::Width;

std::string CoverageText(const Group& g)
{
  return Fixed(100.0 * g.MeasuredCoverage, 1) + " %";
}

std::string TargetValue(const IceBench::Target& t)
{
  if (!t.Measured)
  {
    return "not measured";
  }
  return t.IsIncrease ? (t.Value >= 0 ? "+" : "") + Fixed(100.0 * t.Value, 1) + " %"
                      : Fixed(t.Value, 2) + "x";
}

std::string TargetVerdict(const IceBench::Target& t)
{
  if (!t.Measured)
  {
    return "-";
  }
  if (t.Met)
  {
    return "met";
  }
  const double over =
    t.IsIncrease ? 100.0 * (t.Value - t.Bound) : 100.0 * (t.Value / t.Bound - 1.0);
  return "missed by " + Fixed(over, over < 10.0 ? 1 : 0) + (t.IsIncrease ? " points" : " %");
}

const char* MaterialName(Material m)
{
  switch (m)
  {
    case Material::Plain:
      return "plain";
    case Material::OneSided:
      return "one-sided";
    case Material::TwoSided:
      return "two-sided";
    case Material::FullLook:
      return "full-look";
    case Material::ExitPoint:
      return "exit-point";
  }
  return "";
}

// The measured steps' median GPU times, e.g. "back_faces 1.50, scene 20.84"; "" when none.
std::string StepTimesText(const Configuration& c)
{
  std::string text;
  for (int step = 0; step < Steps; ++step)
  {
    if (c.StepMedians[step] >= 0.0)
    {
      text += (text.empty() ? "" : ", ") + std::string(StepNames[step]) + " " +
        Fixed(c.StepMedians[step], 2);
    }
  }
  return text;
}

std::string Csv(const std::vector<Group>& groups, const Machine& machine)
{
  std::ostringstream out;
  out << "group,object,triangles,scene,coverage,configuration,material,cracks,air_planes,interior,"
         "cube_map,update_mode,face_size,faces_per_frame,culling,moving,frames,median_ms,p25_ms,"
         "p75_ms,min_ms,max_ms,mean_ms,fps,baseline_median_ms,ratio,cpu_median_ms,cpu_ratio,"
         "cube_faces_per_frame,";
  for (const char* step : StepNames)
  {
    out << "gpu_" << step << "_ms,";
  }
  out << "renderer,multisamples\n";
  const char* modes[3] = { "every-frame", "on-change", "manual" };
  for (const Group& g : groups)
  {
    for (const Configuration& c : g.Configurations)
    {
      out << g.Id << "," << g.Object << "," << g.Triangles << ","
          << (g.Landscape ? "landscape" : "static") << "," << Fixed(g.MeasuredCoverage, 4) << ",\""
          << c.Label << "\"," << MaterialName(c.Ice) << "," << c.Cracks << "," << c.AirPlanes << ","
          << (c.Ice == Material::Plain || c.Ice == Material::OneSided
                 ? ""
                 : IceBench::InteriorId(c.Interior))
          << "," << (c.CubeMap ? 1 : 0) << "," << (c.CubeMap ? modes[c.UpdateMode] : "") << ","
          << (c.CubeMap ? std::to_string(c.FaceSize) : "") << ","
          << (c.CubeMap ? std::to_string(c.FacesPerFrame) : "") << ","
          << (c.CubeMap ? (c.Culling ? "1" : "0") : "") << "," << (c.Moving ? 1 : 0) << ","
          << c.Times.size() << "," << Fixed(c.Stats.Median, 3) << "," << Fixed(c.Stats.P25, 3)
          << "," << Fixed(c.Stats.P75, 3) << "," << Fixed(c.Stats.Min, 3) << ","
          << Fixed(c.Stats.Max, 3) << "," << Fixed(c.Stats.Mean, 3) << ","
          << Fixed(1000.0 / c.Stats.Median, 2) << "," << Fixed(g.Configurations[0].Stats.Median, 3)
          << "," << Fixed(c.Ratio, 4) << "," << Fixed(c.CpuMedian, 3) << "," << Fixed(c.CpuRatio, 4)
          << "," << Fixed(c.CubeFacesPerFrame, 3) << ",";
      for (double median : c.StepMedians)
      {
        out << (median >= 0.0 ? Fixed(median, 3) : "") << ",";
      }
      out << "\"" << machine.Renderer << "\"," << machine.MultiSamples << "\n";
    }
  }
  return out.str();
}

std::string Markdown(const std::vector<Group>& groups, const std::vector<IceBench::Target>& targets,
  const Machine& machine, int frames)
{
  std::ostringstream out;
  out << "| machine | |\n|---|---|\n";
  out << "| renderer | " << machine.Renderer << " (OpenGL " << machine.GLVersion << ") |\n";
  out << "| CPU | " << machine.CPU << ", " << machine.Threads << " threads |\n";
  out << "| back end | " << machine.Backend << " |\n";
  out << "| VTK | " << machine.VTK << " |\n";
  out << "| window | " << Width << "x" << Height << ", multisampling " << machine.MultiSamples
      << (machine.MultiSamples > 0 ? " samples" : " (off)") << " |\n";
  out << "| frames | " << Width << "x" << Height << " offscreen, " << frames
      << " timed frames per configuration (fewer for frames over 200 ms: see the CSV), glFinish "
         "after each |\n\n";
  out << "| target | limit | measured | |\n|---|---|---|---|\n";
  for (const IceBench::Target& t : targets)
  {
    out << "| " << t.Name << " | " << t.Limit << " | " << TargetValue(t) << " | "
        << TargetVerdict(t) << " |\n";
  }
  for (const Group& g : groups)
  {
    out << "\n**" << g.Title << "** (" << g.Triangles << " triangles, object covers "
        << CoverageText(g) << " of the window)\n\n";
    out << "| configuration | median ms | IQR ms | min - max ms | fps | ratio | CPU ms | CPU ratio "
           "| GPU ms by step |\n";
    out << "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const Configuration& c : g.Configurations)
    {
      out << "| " << c.Label << " | " << Fixed(c.Stats.Median, 2) << " | " << Fixed(c.Stats.P25, 2)
          << " - " << Fixed(c.Stats.P75, 2) << " | " << Fixed(c.Stats.Min, 2) << " - "
          << Fixed(c.Stats.Max, 2) << " | " << Fixed(1000.0 / c.Stats.Median, 1) << " | "
          << Fixed(c.Ratio, 2) << " | " << Fixed(c.CpuMedian, 1) << " | " << Fixed(c.CpuRatio, 2)
          << " | " << StepTimesText(c) << " |\n";
    }
  }
  return out.str();
}
}

std::string IceBench::Fixed(double value, int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

void IceBench::PrintRun(std::ostream& out, const Machine& machine, const Schedule& schedule)
{
  out << "ice-bench: " << machine.Renderer << ", " << machine.CPU << " (" << machine.Threads
      << " threads), " << machine.Backend << "\n"
      << "ice-bench: " << Width << "x" << Height << ", " << schedule.Rounds * schedule.PerRound
      << " timed frames per configuration (" << schedule.Rounds << " rounds of "
      << schedule.PerRound << (schedule.TurnBudget > 0.0 ? "; fewer for frames over 200 ms" : "")
      << "), multisamples " << machine.MultiSamples << "\n";
}

void IceBench::PrintGroup(std::ostream& out, const Group& g)
{
  out << "\n== " << g.Title << "\n   " << g.Triangles << " triangles, object covers "
      << CoverageText(g) << " of " << Width << "x" << Height << ", " << Fixed(g.Seconds, 1)
      << " s\n";
  out << "   " << std::left << std::setw(42) << "configuration" << std::right << std::setw(10)
      << "median ms" << std::setw(18) << "IQR ms" << std::setw(9) << "fps" << std::setw(8)
      << "ratio" << std::setw(10) << "CPU ms" << std::setw(10) << "CPU ratio"
      << "\n";
  for (const Configuration& c : g.Configurations)
  {
    out << "   " << std::left << std::setw(42) << c.Label << std::right << std::setw(10)
        << Fixed(c.Stats.Median, 2) << std::setw(18)
        << (Fixed(c.Stats.P25, 2) + " - " + Fixed(c.Stats.P75, 2)) << std::setw(9)
        << Fixed(1000.0 / c.Stats.Median, 1) << std::setw(8) << Fixed(c.Ratio, 2) << std::setw(10)
        << Fixed(c.CpuMedian, 1) << std::setw(10) << Fixed(c.CpuRatio, 2) << "\n";
    const std::string steps = StepTimesText(c);
    if (!steps.empty())
    {
      out << "     GPU ms by step: " << steps << "\n";
    }
  }
}

void IceBench::PrintTargets(std::ostream& out, const std::vector<Target>& targets)
{
  out << "\n== Targets (ratio to plain VTK of the same scene)\n";
  for (const IceBench::Target& t : targets)
  {
    out << "   " << std::left << std::setw(56) << t.Name << std::setw(14) << t.Limit
        << std::setw(14) << TargetValue(t) << TargetVerdict(t) << "\n";
  }
}

std::string IceBench::WriteFiles(const Options& options, const std::vector<Group>& groups,
  const std::vector<Target>& targets, const Machine& machine, int frames)
{
  if (!options.Csv.empty())
  {
    const std::string problem = IceOutputFile::Write(options.Csv, Csv(groups, machine));
    if (!problem.empty())
    {
      return problem;
    }
    std::cout << "ice-bench: wrote " << options.Csv << "\n";
  }
  if (!options.Markdown.empty())
  {
    const std::string problem =
      IceOutputFile::Write(options.Markdown, Markdown(groups, targets, machine, frames));
    if (!problem.empty())
    {
      return problem;
    }
    std::cout << "ice-bench: wrote " << options.Markdown << "\n";
  }
  if (!options.Plot.empty())
  {
    const std::string plotError = WritePlot(groups, options.Plot,
      machine.Renderer + ", " + machine.CPU + ", " + std::to_string(machine.Threads) +
        " threads, multisampling " + std::to_string(machine.MultiSamples));
    if (!plotError.empty())
    {
      return plotError;
    }
    std::cout << "ice-bench: wrote " << options.Plot << "\n";
  }
  return std::string();
}
