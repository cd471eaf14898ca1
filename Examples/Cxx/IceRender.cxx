// ice-render: renders a model as ice in front of an environment, to a PNG or in a window.
#include "IceHeadless.h"
#include "IceModelFile.h"
#include "IceOutputFile.h"
#include "IceScene.h"

#include "vtkActor.h"
#include "vtkIceMapper.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace
{
const char* const Usage =
  "usage: ice-render [--model teapot|block|sphere|FILE] [--env sky|test|PATH] [--size WxH]\n"
  "                  [--out FILE] [--one-sided] [--static] [--interactive]\n"
  "                  [--backend auto|x|egl|osmesa]\n"
  "Renders a model as ice (default: the teapot in a small landscape) to ice.png.\n"
  "  --model  teapot, block, sphere or a .vtp/.vtk/.stl/.obj/.ply file\n"
  "  --env    sky, test, a folder with cube faces px nx py ny pz nz (any image type), a\n"
  "           cross image (4:3 or 3:4) or an equirectangular panorama (2:1; .hdr/.exr too)\n"
  "  --size   image size, default 1024x768\n"
  "  --out    output image, .png or .jpg (default ice.png); replaced only once the new image\n"
  "           is complete: a failed or interrupted run leaves the old file as it was\n"
  "  --one-sided  refract at the front face only (the default blends in the back face)\n"
  "  --static     no landscape and no dynamic cube map: the ice sees the environment map only\n"
  "  --interactive  open a window with a trackball camera instead of writing a file\n"
  "  --backend  x (X display), egl or osmesa (no X needed); default $VTKICE_BACKEND or auto:\n"
  "             x when DISPLAY works, else egl, else osmesa\n";

struct Options
{
  std::string Model = "teapot";
  std::string Environment = "sky";
  std::string Output = "ice.png";
  std::string Backend; // empty: $VTKICE_BACKEND, else auto
  int Width = 1024;
  int Height = 768;
  bool Interactive = false;
  bool OneSided = false;
  bool Static = false;
};

int Fail(const std::string& message, int code)
{
  // Arguments and file names are echoed: terminal escapes in them are not passed on.
  std::cerr << "ice-render: " << IceModelFile::Printable(message, 2000) << "\n";
  return code;
}

bool ParseSize(const std::string& text, int& width, int& height)
{
  char x = 0;
  char extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) == 3 && x == 'x' &&
    width >= 16 && height >= 16 && width <= 8192 && height <= 8192;
}

// Returns -1 when the arguments are fine, otherwise the exit code.
int Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string text;
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      return 0;
    }
    else if (arg == "--interactive")
    {
      options.Interactive = true;
    }
    else if (arg == "--one-sided")
    {
      options.OneSided = true;
    }
    else if (arg == "--static")
    {
      options.Static = true;
    }
    else if (arg == "--model" || arg == "--env" || arg == "--out" || arg == "--size" ||
      arg == "--backend")
    {
      if (!value(text))
      {
        return Fail("option " + arg + " needs a value (see --help)", 2);
      }
      if (arg == "--model")
      {
        options.Model = text;
      }
      else if (arg == "--env")
      {
        options.Environment = text;
      }
      else if (arg == "--out")
      {
        if (IceOutputFile::ImageFormat(text).empty())
        {
          return Fail("bad --out '" + text + "' (the name must end in .png, .jpg or .jpeg)", 2);
        }
        options.Output = text;
      }
      else if (arg == "--backend")
      {
        IceHeadless::Backend backend;
        if (!IceHeadless::ParseBackend(text, backend))
        {
          return Fail("bad --backend '" + text + "' (expected auto, x, egl or osmesa)", 2);
        }
        options.Backend = text;
      }
      else if (!ParseSize(text, options.Width, options.Height))
      {
        return Fail("bad --size '" + text + "' (expected WxH, each 16..8192)", 2);
      }
    }
    else
    {
      return Fail("unknown argument '" + arg + "' (see --help)", 2);
    }
  }
  return -1;
}
}

int main(int argc, char* argv[])
{
  IceOutputFile::RemoveTemporaryOnSignals();
  Options options;
  const int parsed = Parse(argc, argv, options);
  if (parsed >= 0)
  {
    return parsed;
  }

  std::string error;
  vtkSmartPointer<vtkPolyData> model = IceScene::LoadModel(options.Model, error);
  if (!model)
  {
    return Fail(error, 1);
  }
  vtkSmartPointer<vtkTexture> environment = IceScene::LoadEnvironment(options.Environment, error);
  if (!environment)
  {
    return Fail(error, 1);
  }
  // Checked now, before minutes of rendering; nothing is written until the image is complete.
  const std::string outputProblem =
    options.Interactive ? std::string() : IceOutputFile::CheckWritable(options.Output);
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
  sceneOptions.Landscape = !options.Static;
  sceneOptions.DynamicEnvironment = !options.Static;
  vtkActor* ice = IceScene::Populate(renderer, model, environment, sceneOptions);
  vtkIceMapper::SafeDownCast(ice->GetMapper())->SetTwoSidedRefraction(!options.OneSided);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(options.Width, options.Height);
  window->AddRenderer(renderer);
  window->SetWindowName("VTK Ice");

  if (options.Interactive)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(window);
    window->Render();
    interactor->Start();
    return 0;
  }

  window->SetOffScreenRendering(1);
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
