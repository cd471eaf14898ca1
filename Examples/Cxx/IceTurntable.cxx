// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceTurntable.h"

#include "IceOutputFile.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sys/wait.h>
#include <unistd.h>

namespace IceTurntable
{
namespace
{
std::string Stem(const std::string& output)
{
  const auto slash = output.rfind('/');
  const auto dot = output.rfind('.');
  return dot != std::string::npos && (slash == std::string::npos || dot > slash)
    ? output.substr(0, dot)
    : output;
}

std::string Extension(const std::string& output)
{
  return output.substr(Stem(output).size());
}

// Whether `program` is an executable on the PATH.
bool OnPath(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "";
  size_t start = 0;
  while (start <= folders.size())
  {
    const size_t end = folders.find(':', start);
    const std::string folder = folders.substr(start, end == std::string::npos ? end : end - start);
    if (!folder.empty() && access((folder + "/" + program).c_str(), X_OK) == 0)
    {
      return true;
    }
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  return false;
}

// Runs ffmpeg on the frames, reading the video from its standard output, and writes it as every
// output is written (IceOutputFile: whole or not at all, also when interrupted). A fragmented MP4
// needs no seeking, so it can come through a pipe.
std::string EncodeVideo(const std::string& output, int frames, double rate)
{
  const std::string video = VideoName(output);
  const std::string pattern = Stem(output) + "-%04d" + Extension(output);
  const std::string rateText = std::to_string(static_cast<int>(rate));
  const std::string count = std::to_string(frames);
  int pipeEnds[2];
  if (pipe(pipeEnds) != 0)
  {
    return "cannot run ffmpeg for " + video;
  }
  const pid_t child = fork();
  if (child == 0)
  {
    dup2(pipeEnds[1], STDOUT_FILENO);
    close(pipeEnds[0]);
    close(pipeEnds[1]);
    // Even sizes for yuv420p, which every player reads.
    execlp("ffmpeg", "ffmpeg", "-loglevel", "error", "-framerate", rateText.c_str(), "-i",
      pattern.c_str(), "-frames:v", count.c_str(), "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2",
      "-pix_fmt", "yuv420p", "-movflags", "frag_keyframe+empty_moov", "-f", "mp4", "pipe:1",
      static_cast<char*>(nullptr));
    _exit(127);
  }
  close(pipeEnds[1]);
  std::string data;
  char buffer[65536];
  ssize_t got;
  while (child > 0 &&
    ((got = read(pipeEnds[0], buffer, sizeof(buffer))) > 0 || (got < 0 && errno == EINTR)))
  {
    data.append(buffer, static_cast<size_t>(std::max<ssize_t>(got, 0)));
  }
  close(pipeEnds[0]);
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
    WEXITSTATUS(status) != 0 || data.empty())
  {
    return "ffmpeg could not encode " + video;
  }
  return IceOutputFile::Write(video, data);
}
}

//------------------------------------------------------------------------------
std::string FrameName(const std::string& output, int index)
{
  char number[16];
  std::snprintf(number, sizeof(number), "-%04d", index);
  return Stem(output) + number + Extension(output);
}

//------------------------------------------------------------------------------
std::string VideoName(const std::string& output)
{
  return Stem(output) + ".mp4";
}

//------------------------------------------------------------------------------
std::string Render(vtkRenderWindow* window, vtkRenderer* renderer, int frames,
  const std::string& output, double rate, bool& video)
{
  video = false;
  vtkCamera* camera = renderer->GetActiveCamera();
  const bool terminal = isatty(STDERR_FILENO) != 0;
  std::string problem;
  for (int i = 1; i <= frames && problem.empty(); ++i)
  {
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->Update();
    problem = IceOutputFile::WriteImage(FrameName(output, i), grab->GetOutput());
    if (terminal)
    {
      std::cerr << "\rice-render: turntable frame " << i << "/" << frames << std::flush;
    }
    camera->Azimuth(360.0 / frames);
    renderer->ResetCameraClippingRange();
  }
  if (terminal)
  {
    std::cerr << "\n";
  }
  // A whole turn has brought the camera back where it was.
  if (!problem.empty() || frames <= 0)
  {
    return problem;
  }
  if (OnPath("ffmpeg"))
  {
    problem = EncodeVideo(output, frames, rate);
    video = problem.empty();
  }
  return problem;
}
}
