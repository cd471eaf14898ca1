// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render: renders a model as ice in front of an environment: to an image, a turntable of
// images (and a video), or in an interactive window.
#include "IceHeadless.h"
#include "vtkIceLookTable.h"
#include "vtkIceModelFileChecks.h"
#include "IceOutputFile.h"
#include "IceRenderOptions.h"
#include "IceScene.h"
#include "IceTurntable.h"
#include "IceViewer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkToneMappingPass.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>
#include <string>

using IceRenderOptions::Fail;

int main(int argc, char* argv[])
{
  IceOutputFile::RemoveTemporaryOnSignals();
  IceRenderOptions::Options options;
  const int parsed = IceRenderOptions::Parse(argc, argv, options);
  if (parsed >= 0)
  {
    return parsed;
  }

  if (options.Environment.empty())
  {
    options.Environment = IceRenderOptions::DefaultEnvironment();
  }
  // A photographed environment is brighter than white: tone mapped unless the look says how
  // (--print-preset prints the curve, so the printed look renders the same).
  if (IceRenderOptions::WantsToneMapping(options.Environment, options.Look))
  {
    options.Look.insert(options.Look.begin(), { "tone-mapping", "filmic" });
  }
  if (options.PrintPreset)
  {
    // The library's defaults with the preset and the options applied (checked already).
    vtkNew<vtkIceMapper> mapper;
    vtkNew<vtkIcePass> pass;
    vtkNew<vtkIceCubeMapPass> cubeMaps;
    vtkNew<vtkCamera> camera;
    vtkNew<vtkToneMappingPass> toneMapping;
    vtkIceLookTable::ResetToneMapping(toneMapping);
    if (!options.Static)
    {
      pass->SetCubeMapPass(cubeMaps);
    }
    const vtkIceLookTable::Target target{ mapper, pass, cubeMaps, camera, toneMapping };
    vtkIceLookTable::ApplyAll(target, options.Look);
    std::cout << vtkIceLookTable::WritePreset(target, options.CameraGiven);
    return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
  }

  std::string error;
  std::string warning;
  vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel(options.Model, error, &warning);
  if (!model)
  {
    return Fail(error, 1);
  }
  if (!warning.empty())
  {
    std::cerr << "ice-render: model '" << vtkIceModelFileChecks::Printable(options.Model)
              << "': " << warning << "\n";
  }
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment(options.Environment, error);
  if (!environment)
  {
    return Fail(error, 1);
  }
  // Checked now, before minutes of rendering; nothing is written until an image is complete.
  const std::string firstOutput =
    options.Turntable > 0 ? IceTurntable::FrameName(options.Output, 1) : options.Output;
  const std::string outputProblem =
    options.Interactive ? std::string() : IceOutputFile::CheckWritable(firstOutput);
  if (!outputProblem.empty())
  {
    return Fail(outputProblem, 1);
  }

  // Every vtkRenderWindow from here on renders through the chosen back end.
  const std::string backendError = IceHeadless::Install(options.Backend);
  if (!backendError.empty())
  {
    return Fail(backendError, 1);
  }
  const char* backend = IceHeadless::BackendName(IceHeadless::Installed());
  if (options.Interactive && IceHeadless::Installed() != IceHeadless::Backend::X)
  {
    return Fail(
      std::string("--interactive needs the x back end (an X display), not ") + backend, 1);
  }

  vtkNew<vtkRenderer> renderer;
  IceScene::Options sceneOptions;
  // The small landscape belongs to the built-in sky; any other environment gets the ground.
  const bool sky = options.Environment == "sky";
  sceneOptions.Landscape = !options.Static && sky;
  sceneOptions.Ground = !options.Static && !sky && options.Environment != "test";
  sceneOptions.DynamicEnvironment = !options.Static;
  vtkActor* ice = IceScene::Populate(renderer, model, environment, sceneOptions);
  vtkIcePass* pass = vtkIcePass::SafeDownCast(renderer->GetPass());
  vtkNew<vtkIceCubeMapPass> spareCubeMaps; // for a static scene that asks for the cube map
  vtkIceCubeMapPass* cubeMaps = pass->GetCubeMapPass() ? pass->GetCubeMapPass() : spareCubeMaps;
  vtkNew<vtkToneMappingPass> toneMapping;
  vtkIceLookTable::ResetToneMapping(toneMapping);
  const vtkIceLookTable::Target target{ vtkIceMapper::SafeDownCast(ice->GetMapper()), pass,
    cubeMaps, renderer->GetActiveCamera(), toneMapping };
  if (options.Fit)
  {
    renderer->ResetCamera(ice->GetBounds());
  }
  vtkIceLookTable::ApplyAll(target, options.Look);
  // Standing in its melt pool, the ice shows in it, with the same look.
  vtkActor* image = sceneOptions.Ground ? IceScene::AddMirrorImage(renderer, model) : nullptr;
  vtkIceLookTable::Target mirror = target;
  mirror.Mapper = image ? vtkIceMapper::SafeDownCast(image->GetMapper()) : nullptr;
  if (mirror.Mapper)
  {
    vtkIceLookTable::ApplyAll(mirror, options.Look);
    IceScene::ShowMirrorImage(image, vtkIceLookTable::Value(target, "debug-view"));
  }
  // The HDR scene (a photographed environment is brighter than white) tone mapped: VTK's pass
  // around the ice pass, only where the look asks for a curve.
  if (vtkIceLookTable::AsksForToneMapping(toneMapping))
  {
    toneMapping->SetDelegatePass(pass);
    renderer->SetPass(toneMapping);
  }
  const std::string curve = vtkIceLookTable::Value(target, "tone-mapping");
  if (vtkIceLookTable::Value(target, "exposure") != "0" && (curve == "none" || curve == "reinhard"))
  {
    std::cerr << "ice-render: exposure has no effect with tone-mapping " << curve
              << " (VTK applies it in the exponential, filmic and aces curves)\n";
  }
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(options.Width, options.Height);
  window->AddRenderer(renderer);
  window->SetWindowName("VTK Ice");

  if (options.Interactive)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<IceViewer> viewer;
    viewer->Setup(target, renderer);
    if (mirror.Mapper)
    {
      viewer->Follow(image);
    }
    interactor->SetInteractorStyle(viewer);
    interactor->SetRenderWindow(window);
    window->Render();
    interactor->Start();
    return 0;
  }

  window->SetOffScreenRendering(1);
  if (options.Turntable > 0)
  {
    bool video = false;
    const std::string problem = IceTurntable::Render(
      window, renderer, options.Turntable, options.Output, options.TurntableRate, video);
    if (!problem.empty())
    {
      return Fail(problem, 1);
    }
    std::cout << "ice-render: wrote " << options.Turntable << " frames "
              << IceTurntable::FrameName(options.Output, 1) << " .. "
              << IceTurntable::FrameName(options.Output, options.Turntable)
              << (video ? " and " + IceTurntable::VideoName(options.Output)
                        : std::string(" (no video: ffmpeg is not installed)"))
              << " (" << options.Width << "x" << options.Height << ", model " << options.Model
              << ", back end " << backend << ")\n";
    return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
  }

  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  const std::string writeProblem = IceOutputFile::WriteImage(options.Output, grab->GetOutput());
  if (!writeProblem.empty())
  {
    return Fail(writeProblem, 1);
  }
  std::cout << "ice-render: wrote " << options.Output << " (" << options.Width << "x"
            << options.Height << ", model " << options.Model << ", back end " << backend << ")\n";
  // Standard output is a file too (ice-render > log on a full disk).
  return std::cout.flush() ? 0 : Fail("cannot write to standard output", 1);
}
