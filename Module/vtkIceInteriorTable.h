// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The interior of one vtkIceMapper as the screen-space step reads it: its cracks and air planes
// as records in a float texture (placement and shape, the same as the paper passes' geometry), a
// periodic noise-gradient texture for the cracks' bumps, and the shader code that intersects the
// view ray with them (glsl/vtkIceInteriorFS.glsl).
#ifndef vtkIceInteriorTable_h
#define vtkIceInteriorTable_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

class vtkIceInteriorTable
{
public:
  struct Settings
  {
    int Cracks = 0;
    int CrackSeed = 1;
    double CrackIntensity = 1.0;
    double CrackReflection = 0.0;    // the cracks as sheets (vtkIceMapper::CrackReflection)
    double CrackBumpFrequency = 1.0; // noise cells per model unit
    int AirPlanes = 0;
    int AirSeed = 1;
    double Milkiness = 0.5;
    double CoreDensity = 0.0; // 0: no milky core
    double CoreCenter[3] = { 0.0, 0.0, 0.0 };
    double CoreScale[3] = { 1.0, 1.0, 1.0 };             // model to the core's frame
    int Debug = 0;                                       // vtkIceInteriorLook::Debug
    double Bounds[6] = { 0.0, 1.0, 0.0, 1.0, 0.0, 1.0 }; // what cracks and air are placed in
  };

  vtkIceInteriorTable();
  ~vtkIceInteriorTable();

  // Declarations (after VTK's normal declarations) and functions (before main, after VTK's light
  // declarations, for VTK's light loop of this complexity and count).
  static std::string Declarations();
  static std::string Functions(int lightComplexity, int lightCount);

  // Before a draw of `actor`: the records of `ice` (placed again only when it or a setting
  // changed), the planes back to front for the active camera, the textures uploaded and
  // activated. `atlas` is the bubble images (activated here too).
  void Prepare(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* ice, const Settings& settings,
    vtkTexture* atlas);
  // The interior's own uniforms (the screen-space step sets the matrices it reads).
  void SetUniforms(vtkShaderProgram* program);
  // After the draw: the textures deactivated.
  void Finish(vtkRenderer* renderer);
  void ReleaseGraphicsResources(vtkWindow* window);

  // The records in the table's order (cracks, then air planes back to front) since the last
  // Prepare, and the model-space box around record `position`'s sheet or plane (8 corners).
  int GetNumberOfCracks() const { return this->Current.Cracks; }
  // The air planes the shader reads (none without the bubble atlas), between Prepare and Finish.
  int GetNumberOfAirPlanes() const
  {
    return this->ActiveAtlas ? static_cast<int>(this->AirOrder.size()) : 0;
  }
  int GetNumberOfRecords() const
  {
    return this->Current.Cracks + static_cast<int>(this->AirOrder.size());
  }
  void GetCorners(int position, double corners[24]) const;

private:
  void Place(vtkPolyData* ice, const Settings& settings);
  void Order(const double eye[3]);

  Settings Current;
  vtkPolyData* PlacedFor = nullptr;
  vtkMTimeType PlacedTime = 0;
  bool Placed = false;
  std::vector<float> Outlines;      // 3 models x 64 radii
  std::vector<float> CrackRecords;  // 16 floats each
  std::vector<float> AirRecords;    // 16 floats each, in placement order
  std::vector<double> AirCenters;   // 3 each
  std::vector<vtkIdType> AirOrder;  // back to front
  std::vector<double> CrackCorners; // 24 each: the box around the sheet, model coordinates
  std::vector<double> AirCorners;   // 24 each, in placement order
  bool Uploaded = false;
  vtkSmartPointer<vtkTextureObject> Table;
  vtkSmartPointer<vtkTextureObject> Bump;
  vtkTexture* ActiveAtlas = nullptr;

  vtkIceInteriorTable(const vtkIceInteriorTable&) = delete;
  void operator=(const vtkIceInteriorTable&) = delete;
};

#endif
