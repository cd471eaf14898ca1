// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench: the paper's performance study, side by side with plain VTK. Every configuration is
// timed in the same run as a plain VTK rendering (vtkPolyDataMapper, Phong) of the same scene and
// object, interleaved with it round by round, and reported as a ratio to it. The parts are listed
// in IceBench.h.
#include "IceBench.h"
#include "IceBenchScene.h"
#include "IceHeadless.h"
#include "IceOutputFile.h"
#include "IceScene.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"

#include <chrono>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

using IceBench::Fail;
using IceBench::Group;

int main(int argc, char* argv[])
{
  IceBench::Options options;
  const int parsed = IceBench::Parse(argc, argv, options);
  if (parsed >= 0)
  {
    return parsed;
  }
  IceOutputFile::RemoveTemporaryOnSignals();
  // Checked before the run, without creating anything: the files are written only at the end,
  // each whole or not at all (IceOutputFile.h).
  for (const std::string& path : { options.Csv, options.Plot, options.Markdown })
  {
    const std::string problem = path.empty() ? path : IceOutputFile::CheckWritable(path);
    if (!problem.empty())
    {
      return Fail(problem, 1);
    }
  }

  const IceBench::Schedule schedule = IceBench::ChooseSchedule(options.Quick, options.Frames);
  const int frames = schedule.Rounds * schedule.PerRound;

  // `--only tree`: the trace's tree alone (no window); a full run measures it at its end.
  if (options.Only == "tree")
  {
    IceBench::MeasureTrees(std::cout);
    return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
  }
  std::vector<Group> groups = IceBench::SelectGroups(options.Quick, options.Only);
  if (groups.empty())
  {
    return Fail("no group matches --only '" + options.Only + "'", 2);
  }

  const std::string backendError = IceHeadless::Install(options.Backend);
  if (!backendError.empty())
  {
    return Fail(backendError, 1);
  }

  std::string error;
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
  if (!environment)
  {
    return Fail(error, 1);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(IceBench::Width, IceBench::Height);
  window->SetOffScreenRendering(1);
  window->SetWindowName("ice-bench");
  if (options.MultiSamples >= 0)
  {
    window->SetMultiSamples(options.MultiSamples);
  }

  IceBench::Machine machine = IceBench::DescribeMachine();

  const auto started = std::chrono::steady_clock::now();
  std::map<std::string, vtkSmartPointer<vtkPolyData>> objects;
  std::map<std::pair<std::string, double>, std::pair<double, double>> calibrated;
  for (Group& g : groups)
  {
    vtkSmartPointer<vtkPolyData>& object = objects[g.Object];
    if (!object)
    {
      object = IceBench::MakeObject(g.Object, error);
      if (!object)
      {
        return Fail(error, 1);
      }
    }
    g.Triangles = object->GetNumberOfPolys() + object->GetNumberOfStrips();
    auto key = std::make_pair(g.Object, g.Coverage);
    if (!calibrated.count(key))
    {
      double achieved = 0.0;
      const double distance = IceBench::Calibrate(window, object, g.Coverage, achieved);
      calibrated[key] = std::make_pair(distance, achieved);
    }
    g.CameraDistance = calibrated[key].first;
    g.MeasuredCoverage = calibrated[key].second;
    // The GL strings need a context: the calibration's renderings made one.
    if (machine.Renderer.empty())
    {
      IceBench::DescribeContext(window, machine);
      IceBench::PrintRun(std::cout, machine, schedule);
    }

    IceBench::RunGroup(g, window, object, environment, schedule);
    IceBench::PrintGroup(std::cout, g);
    std::cout.flush();
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const std::vector<IceBench::Target> targets = IceBench::EvaluateTargets(groups);
  IceBench::PrintTargets(std::cout, targets);
  if (!options.Quick && options.Only.empty())
  {
    IceBench::MeasureTrees(std::cout);
  }
  std::cout << "\nice-bench: " << groups.size() << " groups in " << IceBench::Fixed(seconds, 1)
            << " s\n";

  const std::string problem = IceBench::WriteFiles(options, groups, targets, machine, frames);
  if (!problem.empty())
  {
    return Fail(problem, 1);
  }
  // The tables went to standard output, a file too (ice-bench > run.txt on a full disk).
  return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
}
