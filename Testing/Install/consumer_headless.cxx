// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Uses the installed VTKIce::Headless: renders a window without X (egl, else osmesa).
#include "IceHeadless.h"

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>

int main()
{
  std::string error = IceHeadless::Install("egl");
  if (!error.empty() && !(error = IceHeadless::Install("osmesa")).empty())
  {
    std::cerr << "ice-consumer-headless: " << error << "\n";
    return 1;
  }
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 1.0, 0.0);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(32, 32);
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 31, 31, 0, pixels);
  const bool green = pixels->GetValue(0) == 0 && pixels->GetValue(1) == 255;
  std::cout << window->GetClassName() << ", " << IceHeadless::InstalledDescription() << ": "
            << (green ? "green" : "wrong colour") << "\n";
  return green ? 0 : 1;
}
