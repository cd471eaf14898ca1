// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// GPU times of the steps of a vtkIcePass frame, by OpenGL timestamp queries
// (vtkOpenGLRenderTimer), read without waiting for the GPU: a step's time is collected at the
// start of a later frame, once the GPU has finished it. Inside the module only.
#ifndef vtkIceStepTimers_h
#define vtkIceStepTimers_h

#include "vtkOpenGLRenderTimer.h"

#include <array>

class vtkIceStepTimers
{
public:
  static constexpr int NumberOfSteps = 5;

  // Collects the times the GPU has ready; a step that did not run in the frame it was last
  // started for reads -1 from then on.
  void BeginFrame();
  // Brackets a step; a step whose queries are still in flight is not measured this frame.
  void Start(int step);
  void Stop(int step);
  // The latest measured time of `step` in milliseconds, -1 when it did not run.
  double Get(int step) const { return this->Steps[step].Milliseconds; }
  // Frees the queries (the context must be current) and forgets the times.
  void ReleaseGraphicsResources();

private:
  struct Step
  {
    vtkOpenGLRenderTimer Timer;
    bool InFlight = false;   // started and stopped, result not collected yet
    bool RanInFrame = false; // started in the current frame
    double Milliseconds = -1.0;
  };
  std::array<Step, NumberOfSteps> Steps;
};

#endif
