// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's scenes: the timed objects, a renderer per configuration and the calibration of the
// camera distance. Private to ice-bench (IceBenchScene.cxx; used by IceBenchMeasure.cxx and main).
#ifndef IceBenchScene_h
#define IceBenchScene_h

#include "IceBench.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkActor;
class vtkIceCubeMapPass;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkTexture;

namespace IceBench
{
// One configuration's renderer and what the frame loop needs of it.
struct Scene
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Ball;
  vtkSmartPointer<vtkIceCubeMapPass> CubeMapPass;
};

// A model IceScene::LoadModel knows, or sphere-1k, -10k, -100k, -1M (a UV sphere of about that
// many triangles). Returns nullptr and sets `error` on failure.
vtkSmartPointer<vtkPolyData> MakeObject(const std::string& object, std::string& error);

Scene BuildScene(const Group& g, Configuration& c, vtkPolyData* object, vtkTexture* environment);

// Moves the ball a step along its circle around the ice.
void MoveBall(vtkActor* ball);

// The camera distance at which `object` covers the `wanted` fraction of the window (1: all of
// it); `achieved` is the fraction it covers there.
double Calibrate(vtkRenderWindow* window, vtkPolyData* object, double wanted, double& achieved);
}

#endif
