// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The inside of one ice mapper's ice: its crack sheets and air planes, the pipelines that build
// them (vtkIceCrackGeometry; vtkIceAirGeometry, ordered by vtkIceBackToFront) and the private
// mappers that draw them.
#ifndef vtkIceInterior_h
#define vtkIceInterior_h

#include "vtkNew.h"

class vtkActor;
class vtkIceAirGeometry;
class vtkIceAirMapper;
class vtkIceAirTextureSource;
class vtkIceBackToFront;
class vtkIceCrackGeometry;
class vtkIceCrackMapper;
class vtkPolyData;
class vtkRenderer;
class vtkTexture;
class vtkWindow;

class vtkIceInterior
{
public:
  vtkIceInterior();
  ~vtkIceInterior();

  // The crack sheets of `ice`, placed in `bounds` (rebuilt only when it or a parameter changed).
  vtkPolyData* UpdateCracks(
    vtkPolyData* ice, const double bounds[6], int number, int seed, bool clipToSurface);

  // How the cracks are drawn.
  struct CrackLook
  {
    bool ClipToInterval;
    bool Debug;     // solid red, opaque
    bool Unclipped; // over everything: no depth test
    double Intensity;
    double BumpFrequency;
  };

  // Draws the sheets of the last UpdateCracks with `ice`'s matrix and render passes: over the
  // rendered scene (`overlay`), or with the current state (into the back-face normals).
  void DrawCracks(vtkRenderer* renderer, vtkActor* ice, const CrackLook& look, bool overlay);

  // Draws the air planes of `ice`, placed in `bounds`, over the rendered scene, back to front for
  // the active camera.
  void DrawAir(vtkRenderer* renderer, vtkActor* ice, vtkPolyData* iceInput, const double bounds[6],
    int number, int seed, double milkiness, bool debug);

  // The bubble images of air of `seed`, for the screen-space interior.
  vtkTexture* GetAirAtlas(int seed);

  // See vtkIceWorldSpaceMapper::ForgetRenderPasses.
  void ForgetRenderPasses();
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkNew<vtkIceCrackGeometry> Cracks;
  vtkNew<vtkIceCrackMapper> CrackMapper;
  vtkNew<vtkActor> CrackActor;
  vtkNew<vtkIceAirGeometry> Air;
  vtkNew<vtkIceBackToFront> AirOrder;
  vtkNew<vtkIceAirTextureSource> AirImages;
  vtkNew<vtkTexture> AirTexture;
  vtkNew<vtkTexture> AirAtlas; // for the screen-space interior
  vtkNew<vtkIceAirMapper> AirMapper;
  vtkNew<vtkActor> AirActor;

  vtkIceInterior(const vtkIceInterior&) = delete;
  void operator=(const vtkIceInterior&) = delete;
};

#endif
