// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceStepTimers.h"

//------------------------------------------------------------------------------
void vtkIceStepTimers::BeginFrame()
{
  for (Step& step : this->Steps)
  {
    if (step.InFlight && step.Timer.Ready())
    {
      step.Milliseconds = step.Timer.GetElapsedMilliseconds();
      step.Timer.Reset();
      step.InFlight = false;
    }
    else if (!step.InFlight && !step.RanInFrame)
    {
      step.Milliseconds = -1.0;
    }
    step.RanInFrame = false;
  }
}

//------------------------------------------------------------------------------
void vtkIceStepTimers::Start(int step)
{
  Step& s = this->Steps[step];
  s.RanInFrame = true;
  if (!s.InFlight)
  {
    s.Timer.Start();
  }
}

//------------------------------------------------------------------------------
void vtkIceStepTimers::Stop(int step)
{
  Step& s = this->Steps[step];
  if (!s.InFlight && s.Timer.Started())
  {
    s.Timer.Stop();
    s.InFlight = true;
  }
}

//------------------------------------------------------------------------------
void vtkIceStepTimers::ReleaseGraphicsResources()
{
  for (Step& step : this->Steps)
  {
    step.Timer.ReleaseGraphicsResources();
    step.InFlight = false;
    step.RanInFrame = false;
    step.Milliseconds = -1.0;
  }
}
