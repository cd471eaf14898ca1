// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The interior of one vtkIceMapper as the screen-space step reads it: its cracks and air planes
// as records in a float texture (placement and shape, the same as the paper passes' geometry), the
// cracks' grid (vtkIceCrackGrid) in another, a periodic noise-gradient texture for the cracks'
// bumps, and the shader code that intersects the view ray with them (glsl/vtkIceInteriorFS.glsl).
#ifndef vtkIceInteriorTable_h
#define vtkIceInteriorTable_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkActor;
class vtkIceCrackGrid;
class vtkIceCrackTable;
class vtkIceProperty;
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
  // What the drawing decides beside the look (the vtkIceProperty the table reads): the box the
  // cracks and air are placed in, the model's largest extent (the cracks' bump scale), the debug
  // view (vtkIceInteriorLook::Debug: the cracks alone, or the air alone) and whether the input is
  // flat (no inside: no cracks).
  struct Placement
  {
    double Bounds[6] = { 0.0, 1.0, 0.0, 1.0, 0.0, 1.0 };
    double Extent = 1.0;
    int Debug = 0;
    bool Flat = false;
  };

  vtkIceInteriorTable();
  ~vtkIceInteriorTable();

  // Declarations (after VTK's normal declarations) and functions (before main, after VTK's light
  // declarations, for VTK's light loop of this complexity and count).
  static std::string Declarations();
  static std::string Functions(int lightComplexity, int lightCount);

  // Before a draw of `actor`: the records of `ice` with the cracks and air of `look` (placed
  // again only when the input, a count, a seed or the placement changed), the planes back to front
  // for the active camera, the textures uploaded and activated. `atlas` is the bubble images
  // (activated here too). `look` is read until Finish.
  void Prepare(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* ice, vtkIceProperty* look,
    const Placement& placement, vtkTexture* atlas);
  // For the trace in the surface's program: the cracks of `look` placed as for the interior, the
  // crack table and grid uploaded and activated (`active`: the caller deactivates them after the
  // draw), their uniforms set on `program`.
  void PrepareCracks(vtkRenderer* renderer, vtkPolyData* ice, vtkIceProperty* look,
    const Placement& placement, vtkShaderProgram* program, vtkTextureObject* active[2]);
  // The same with the bubbles and the core they gather in (uniforms and the bump texture they
  // read, `active[2]`), for the trace's bubbles on the segments after a reflection inside; with
  // `atlas` (the air planes' bubble images) also the air planes (`active[3]`: the atlas's
  // texture), none without it.
  void PrepareTraceAir(vtkRenderer* renderer, vtkPolyData* ice, vtkIceProperty* look,
    const Placement& placement, vtkShaderProgram* program, vtkTextureObject* active[4],
    vtkTexture* atlas);
  // The interior's own uniforms (the screen-space step sets the matrices it reads).
  void SetUniforms(vtkShaderProgram* program);
  // After the draw: the textures deactivated.
  void Finish(vtkRenderer* renderer);
  void ReleaseGraphicsResources(vtkWindow* window);

  // The records in the table's order (cracks, then air planes back to front) since the last
  // Prepare.
  int GetNumberOfCracks() const { return this->Cracks; }
  // The air planes the shader reads (none without the bubble atlas), between Prepare and Finish.
  int GetNumberOfAirPlanes() const
  {
    return this->ActiveAtlas ? static_cast<int>(this->AirOrder.size()) : 0;
  }
  int GetNumberOfRecords() const { return this->Cracks + static_cast<int>(this->AirOrder.size()); }
  // Air plane `k` back to front (0 the farthest): its quad's corners in model coordinates
  // (x, y = -1 or 1 in its frame: (-1, -1), (1, -1), (-1, 1), (1, 1)) and their coordinates in
  // the bubble atlas (its tile's, as vtkIceAirGeometry gives them).
  void GetAirQuad(int k, double corners[12], double atlas[8]) const;

private:
  void Place(vtkPolyData* ice, vtkIceProperty* look, const Placement& placement);
  void Order(const double eye[3]);
  // The crack table and grid textures made for `window` and uploaded where anything changed.
  void Upload(vtkOpenGLRenderWindow* window);
  // The bubbles' feathers and the cracks' tilt read this noise gradient (made once a context).
  void MakeBump(vtkOpenGLRenderWindow* window);
  // The bubbles' and the core's uniforms for `look` (its frame in the placement's box).
  void SetBubbleUniforms(vtkShaderProgram* program, vtkIceProperty* look);
  void SetCrackUniforms(vtkShaderProgram* program);

  Placement Where;
  vtkIceProperty* Look = nullptr; // between Prepare and Finish
  int Cracks = 0;                 // placed
  int CrackSeed = 1;
  int AirPlanes = 0;
  int AirSeed = 1;
  vtkPolyData* PlacedFor = nullptr;
  vtkMTimeType PlacedTime = 0;
  bool Placed = false;
  std::vector<float> AirRecords;   // 16 floats each, in placement order
  std::vector<double> AirCenters;  // 3 each
  std::vector<vtkIdType> AirOrder; // back to front
  std::vector<double> AirCorners;  // 12 each, in placement order
  bool Uploaded = false;
  vtkSmartPointer<vtkTextureObject> Table;
  vtkSmartPointer<vtkTextureObject> Bump;
  vtkSmartPointer<vtkIceCrackTable> CrackTable;
  vtkSmartPointer<vtkIceCrackGrid> Grid;
  vtkSmartPointer<vtkTextureObject> GridLists;
  vtkTexture* ActiveAtlas = nullptr;

  vtkIceInteriorTable(const vtkIceInteriorTable&) = delete;
  void operator=(const vtkIceInteriorTable&) = delete;
};

#endif
