// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// What one ice mapper's interior is made from, for both interior methods: its crack sheets (the
// pipeline that places them, vtkIceCrackGeometry) and the bubble images of its air (as one
// texture the screen-space interior samples).
#ifndef vtkIceInteriorSources_h
#define vtkIceInteriorSources_h

#include "vtkNew.h"

class vtkIceAirTextureSource;
class vtkIceCrackGeometry;
class vtkPolyData;
class vtkTexture;
class vtkWindow;

class vtkIceInteriorSources
{
public:
  vtkIceInteriorSources();
  ~vtkIceInteriorSources();

  // The crack sheets of `ice`, placed in `bounds` (rebuilt only when it or a parameter changed).
  vtkPolyData* UpdateCracks(
    vtkPolyData* ice, const double bounds[6], int number, int seed, bool clipToSurface);

  // The bubble images of air of `seed`, for the screen-space interior.
  vtkTexture* GetAirAtlas(int seed);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkNew<vtkIceCrackGeometry> Cracks;
  vtkNew<vtkIceAirTextureSource> AirImages;
  vtkNew<vtkTexture> AirAtlas;

  vtkIceInteriorSources(const vtkIceInteriorSources&) = delete;
  void operator=(const vtkIceInteriorSources&) = delete;
};

#endif
