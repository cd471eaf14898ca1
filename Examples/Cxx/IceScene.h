// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The default ice scene shared by ice-render, ice-bench and the image tests: a model turned to
// ice in front of an environment cube map that is also drawn as the skybox.
#ifndef IceScene_h
#define IceScene_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkTexture;

namespace IceScene
{
// "cube" (an ice cube: vtkIceBlockSource nearly flat, edges slightly rounded), "teapot", "block",
// "sphere" or a .vtp/.vtk/.stl/.obj/.ply file. The model is centred at the
// origin and scaled so its largest extent is 2. Returns nullptr and sets `error` on failure;
// `warning` (when given) says what of a file was left out (IceReading::ReadPolyDataIsolated).
vtkSmartPointer<vtkPolyData> LoadModel(
  const std::string& model, std::string& error, std::string* warning = nullptr);

// "sky" (procedural landscape), "test" (smooth direction pattern), or a path for
// vtkIceEnvironmentReader: a folder holding six face images px, nx, py, ny, pz, nz (any image
// extension; all square, all the same size), a horizontal (4:3) or vertical (3:4) cross image, or
// an equirectangular (2:1) panorama, 8-bit or HDR; or the name of one of Debian's blender-data
// panoramas (Panoramas()). Returns nullptr and sets `error` on failure.
vtkSmartPointer<vtkTexture> LoadEnvironment(const std::string& environment, std::string& error);

// The photographed HDR panoramas (CC0, 1024 x 512 EXR) that Debian's blender-data package puts in
// PanoramaFolder(): city, courtyard, forest, interior, night, studio, sunrise, sunset.
const std::vector<std::string>& Panoramas();
bool IsPanorama(const std::string& name);
std::string PanoramaFolder();

// Adds the landscape of the default scene: a checkered ground at `groundHeight`, five rocks and
// six pine trees within 8 units of the origin, the sky's sun and a soft headlight.
void AddLandscape(vtkRenderer* renderer, double groundHeight);

// Sets `environment` as the renderer's environment texture and draws it as the skybox.
void AddEnvironment(vtkRenderer* renderer, vtkTexture* environment);

// Points the camera at the origin from `distance` along the default scene's view direction
// (2.1, 0.9, 3.9), 32° view angle; the default scene's distance is that vector's length.
void PlaceCamera(vtkRenderer* renderer, double distance);
double DefaultCameraDistance();

struct Options
{
  // A ground with rocks and trees around the ice, lit by the sky's sun.
  bool Landscape = true;
  // A grey ground under the ice with its soft contact shadow, fading into the environment
  // (IceGround): the ice stands in a photographed panorama instead of floating.
  bool Ground = false;
  // The ice reflects and refracts a cube map of the scene around it (vtkIceCubeMapPass) instead
  // of the environment texture alone.
  bool DynamicEnvironment = true;
};

// Sets a vtkIcePass on the renderer (two-sided refraction), adds the skybox, the environment, the
// landscape or the ground if asked and an ice actor for `model`, and frames the camera.
// Returns the ice actor (its mapper is a vtkIceMapper).
vtkActor* Populate(
  vtkRenderer* renderer, vtkPolyData* model, vtkTexture* environment, const Options& options = {});

// The ice's mirror image in the melt pool around its foot (Options::Ground; IceGround's pool
// lets what lies below the ground show through by water's share of reflection): the model
// reflected about its lowest y, as ice of its own (a vtkIceMapper), added to the renderer and
// returned for the caller to give it the ice's look (ShowMirrorImage). Its cracks and bubbles are
// the look's own in the reflected shape (placed in it as in any ice), not the mirror images of
// the ice's.
vtkActor* AddMirrorImage(vtkRenderer* renderer, vtkPolyData* model);

// Shows the mirror image only while the ice shows its look: a debug view (the paper's Figure 5)
// is of the ice alone.
void ShowMirrorImage(vtkActor* image, const std::string& debugView);
}

#endif
