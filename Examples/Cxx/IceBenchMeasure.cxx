// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's measuring: the schedule, every configuration of a group timed in turn (wall clock
// and CPU time, glFinish after every frame) and the statistics and ratios of the times.
#include "IceBench.h"
#include "IceBenchScene.h"
#include "IceScene.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

static_assert(IceBench::Steps == vtkIcePass::NumberOfSteps, "ice-bench times every step");

namespace
{
using IceBench::Configuration;
using IceBench::Group;
using IceBench::MoveBall;
using IceBench::Scene;
using IceBench::Schedule;

IceBench::Statistics Summarize(std::vector<double> times)
{
  IceBench::Statistics s;
  if (times.empty())
  {
    return s;
  }
  std::sort(times.begin(), times.end());
  auto quantile = [&](double q) {
    const double position = q * static_cast<double>(times.size() - 1);
    const size_t below = static_cast<size_t>(std::floor(position));
    const size_t above = std::min(below + 1, times.size() - 1);
    const double t = position - static_cast<double>(below);
    return times[below] * (1.0 - t) + times[above] * t;
  };
  s.Median = quantile(0.5);
  s.P25 = quantile(0.25);
  s.P75 = quantile(0.75);
  s.Min = times.front();
  s.Max = times.back();
  double sum = 0.0;
  for (double t : times)
  {
    sum += t;
  }
  s.Mean = sum / static_cast<double>(times.size());
  return s;
}

// CPU time of the whole process (the main thread and llvmpipe's threads) in milliseconds.
double ProcessCpuMilliseconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// Every configuration takes its turn once a round, so that a drift of the machine (heat, other
// load) falls on all of them alike.
void MeasureGroup(
  Group& g, vtkRenderWindow* window, std::vector<Scene>& scenes, const Schedule& schedule)
{
  const size_t n = scenes.size();
  auto activate = [&](size_t active) {
    for (size_t i = 0; i < n; ++i)
    {
      scenes[i].Renderer->SetDraw(i == active ? 1 : 0);
    }
  };
  auto frame = [&](size_t i) {
    if (g.Configurations[i].Moving && scenes[i].Ball)
    {
      MoveBall(scenes[i].Ball);
    }
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
  };
  // The last warm-up frame of each configuration estimates its frame time.
  std::vector<double> estimate(n, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    activate(i);
    for (int f = 0; f < schedule.WarmUp; ++f)
    {
      estimate[i] = frame(i);
      if (f >= 1 && schedule.TurnBudget > 0.0 && estimate[i] > schedule.SlowFrame)
      {
        break;
      }
    }
  }
  auto framesPerTurn = [&](size_t i) {
    if (schedule.TurnBudget <= 0.0 || estimate[i] <= 0.0)
    {
      return schedule.PerRound;
    }
    const int fit = static_cast<int>(schedule.TurnBudget / estimate[i]);
    return std::max(1, std::min(schedule.PerRound, fit));
  };
  std::vector<long long> faces(n, 0);
  for (int round = 0; round < schedule.Rounds; ++round)
  {
    for (size_t k = 0; k < n; ++k)
    {
      // A different configuration starts each round.
      const size_t i = (k + static_cast<size_t>(round)) % n;
      activate(i);
      if (schedule.TurnBudget <= 0.0 || estimate[i] <= schedule.SlowFrame)
      {
        frame(i); // settles the switch between renderers
      }
      const long long facesBefore =
        scenes[i].CubeMapPass ? scenes[i].CubeMapPass->GetNumberOfFaceRenders() : 0;
      const int frames = framesPerTurn(i);
      for (int f = 0; f < frames; ++f)
      {
        const double cpuStart = ProcessCpuMilliseconds();
        const double milliseconds = frame(i);
        g.Configurations[i].CpuTimes.push_back(ProcessCpuMilliseconds() - cpuStart);
        g.Configurations[i].Times.push_back(milliseconds);
        if (vtkIcePass* pass = vtkIcePass::SafeDownCast(scenes[i].Renderer->GetPass()))
        {
          for (int step = 0; step < IceBench::Steps; ++step)
          {
            const double time = pass->GetStepTime(step);
            if (time >= 0.0)
            {
              g.Configurations[i].StepTimes[step].push_back(time);
            }
          }
        }
      }
      if (scenes[i].CubeMapPass)
      {
        faces[i] += scenes[i].CubeMapPass->GetNumberOfFaceRenders() - facesBefore;
      }
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    Configuration& c = g.Configurations[i];
    c.Stats = Summarize(c.Times);
    c.CpuMedian = Summarize(c.CpuTimes).Median;
    for (int step = 0; step < IceBench::Steps; ++step)
    {
      c.StepMedians[step] = c.StepTimes[step].empty() ? -1.0 : Summarize(c.StepTimes[step]).Median;
    }
    c.CubeFacesPerFrame =
      c.Times.empty() ? 0.0 : static_cast<double>(faces[i]) / static_cast<double>(c.Times.size());
  }
  const double baseline = g.Configurations[0].Stats.Median;
  const double cpuBaseline = g.Configurations[0].CpuMedian;
  for (Configuration& c : g.Configurations)
  {
    c.Ratio = baseline > 0.0 ? c.Stats.Median / baseline : 0.0;
    c.CpuRatio = cpuBaseline > 0.0 ? c.CpuMedian / cpuBaseline : 0.0;
  }
  activate(n); // none
}
}

Schedule IceBench::ChooseSchedule(bool quick, int frames)
{
  Schedule schedule;
  if (quick)
  {
    schedule.WarmUp = 2;
    schedule.Rounds = 2;
    schedule.PerRound = 2;
  }
  else
  {
    schedule.TurnBudget = 800.0;
  }
  if (frames > 0)
  {
    schedule.PerRound = std::min(frames, quick ? 2 : 4);
    schedule.Rounds = (frames + schedule.PerRound - 1) / schedule.PerRound;
  }
  return schedule;
}

void IceBench::RunGroup(Group& g, vtkRenderWindow* window, vtkPolyData* object,
  vtkTexture* environment, const Schedule& schedule)
{
  const auto groupStarted = std::chrono::steady_clock::now();
  std::vector<Scene> scenes;
  for (Configuration& c : g.Configurations)
  {
    Scene scene = BuildScene(g, c, object, environment);
    // Where the time goes: GPU timer queries around each step of the ice's frame.
    if (vtkIcePass* pass = vtkIcePass::SafeDownCast(scene.Renderer->GetPass()))
    {
      pass->MeasureStepTimesOn();
    }
    IceScene::PlaceCamera(scene.Renderer, g.CameraDistance);
    scene.Renderer->SetDraw(0);
    window->AddRenderer(scene.Renderer);
    scenes.push_back(scene);
  }
  MeasureGroup(g, window, scenes, schedule);
  for (Scene& scene : scenes)
  {
    scene.Renderer->ReleaseGraphicsResources(window);
    window->RemoveRenderer(scene.Renderer);
  }
  g.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - groupStarted).count();
}
