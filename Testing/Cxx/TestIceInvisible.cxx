// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// With RefractionRatio 1 and a huge FresnelPower the ice passes every view ray straight through,
// so it must be invisible against a skybox of the same cube map: this pins the mapper's cube-map
// lookup to vtkSkybox's convention. Default ice must, by contrast, be clearly visible.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"

#include "vtkTexture.h"

#include <cstdlib>

int TestIceInvisible(int, char*[])
{
  vtkSmartPointer<vtkTexture> environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::Sky, 256);
  const IceTest::Invisibility result = IceTest::MeasureInvisibility(environment);
  return IceTest::ReportInvisibility("sky", result) ? EXIT_SUCCESS : EXIT_FAILURE;
}
