// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render --turntable: images all around the model, and a video of them when ffmpeg is there.
#ifndef IceTurntable_h
#define IceTurntable_h

#include <string>

class vtkRenderWindow;
class vtkRenderer;

namespace IceTurntable
{
// The name of frame `index` (from 1) of a turntable written as `output`: NAME-0001.png for
// NAME.png.
std::string FrameName(const std::string& output, int index);

// The video's name: NAME.mp4 for NAME.png.
std::string VideoName(const std::string& output);

// Renders `frames` images, the camera turned about the focal point by 360 / frames degrees each
// time (around the view-up axis: a whole turn), written as
// FrameName(output, i). A progress line on standard error when it is a terminal. Then, if
// ffmpeg is on the PATH, VideoName(output) at `rate` frames per second. Returns "" or the
// problem; `video` says whether a video was written.
std::string Render(vtkRenderWindow* window, vtkRenderer* renderer, int frames,
  const std::string& output, double rate, bool& video);
}

#endif
