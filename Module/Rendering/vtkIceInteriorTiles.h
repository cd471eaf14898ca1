// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Which of an ice prop's air planes each screen tile's rays can meet, for the screen-space
// interior (vtkIceScreenInterior): the box around each plane is projected with the camera, and
// each tile of 16 x 16 pixels lists the planes whose projection reaches it, back to front (the
// table's order). A pixel's ray then intersects only its tile's planes: a plane no ray of a tile
// can reach costs that tile nothing. (The cracks, about the ice's size, reach nearly every tile:
// a grid in the ice's own space culls them, vtkIceCrackGrid.) Built on the CPU for every draw (the camera and the ice move), uploaded as one
// float texture. Inside the module.
#ifndef vtkIceInteriorTiles_h
#define vtkIceInteriorTiles_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkActor;
class vtkIceInteriorTable;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkIceInteriorTiles
{
public:
  static const int TileSize = 16;    // pixels; even, so no 2 x 2 pixel quad straddles two tiles
  static const int RowTexels = 4096; // as iceTileRowTexels

  // The lists for `interior`'s records (prepared for `actor`) in a viewport of `width` x
  // `height` pixels, inside `rect` (the prop's covered pixels, { x0, y0, x1, y1 }); uploaded and
  // activated until Finish.
  void Update(vtkRenderer* renderer, vtkActor* actor, const vtkIceInteriorTable& interior,
    int width, int height, const int rect[4]);
  void SetUniforms(vtkShaderProgram* program);
  void Finish();
  void ReleaseGraphicsResources(vtkWindow* window);

  // Of the last Update: records listed over all tiles, and tiles.
  long long GetNumberOfEntries() const { return this->Entries; }
  int GetNumberOfTiles() const { return this->TilesAcross * this->TilesUp; }

private:
  vtkSmartPointer<vtkTextureObject> Lists;
  int Origin[2] = { 0, 0 }; // pixel of tile (0, 0)'s lower left corner
  int TilesAcross = 0;
  int TilesUp = 0;
  int Stride = 0; // texels per tile: the two counts, then the records
  long long Entries = 0;
  std::vector<float> Texels;
};

#endif
