// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The scene the viewer's tests drive: a model as ice in the procedural sky, without the landscape
// or a dynamic cube map, and the look table's target on it (with a small cube-map pass of its own
// for the key that switches the dynamic cube map on).
#ifndef IceViewerTestScene_h
#define IceViewerTestScene_h

#include "IceScene.h"
#include "vtkIceLookTable.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <string>

struct IceViewerTestScene
{
  explicit IceViewerTestScene(const char* modelName)
  {
    std::string error;
    this->Model = IceScene::LoadModel(modelName, error);
    vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment("sky", error);
    IceScene::Options options;
    options.Landscape = false;
    options.DynamicEnvironment = false;
    this->Ice = IceScene::Populate(this->Renderer, this->Model, environment, options);
    this->CubeMaps->SetFaceSize(64);
    this->Target = { vtkIceMapper::SafeDownCast(this->Ice->GetMapper()),
      vtkIcePass::SafeDownCast(this->Renderer->GetPass()), this->CubeMaps,
      this->Renderer->GetActiveCamera() };
  }

  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIceCubeMapPass> CubeMaps;
  vtkSmartPointer<vtkPolyData> Model;
  vtkActor* Ice = nullptr;
  vtkIceLookTable::Target Target;
};

#endif
