// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceInteriorTable.h"

#include "vtkIceAirGeometry.h"
#include "vtkIceBackToFront.h"
#include "vtkIceCrackGrid.h"
#include "vtkIceCrackTable.h"
#include "vtkIceCracksFS.h"
#include "vtkIceInteriorFS.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceInteriorLookFS.h"
#include "vtkIceNoise.h"
#include "vtkIceProperty.h"
#include "vtkIceShaderSections.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLTexture.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
const int OutlineSamples = vtkIceCrackTable::OutlineSamples;
const int RecordsPerRow = 16;  // as iceRecordsPerRow: 4 texels each, 64 texels a row
const int BumpSize = 32;       // texels per repeat of the bump texture
const int BumpCells = 8;       // noise cells per repeat
const int GridRowTexels = 4096; // as iceCrackGridRowTexels

// The rows of the inverse of `placement` (model to the record's own frame) into `record`.
void StoreInverse(vtkTransform* placement, float* record)
{
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(placement->GetMatrix(), inverse);
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      record[4 * row + column] = static_cast<float>(inverse->GetElement(row, column));
    }
  }
}

// The corners of an air plane's quad, [-1, 1]^2 at z = 0 of its own frame, placed in the model.
void StoreQuad(vtkTransform* placement, double* corners)
{
  for (int corner = 0; corner < 4; ++corner)
  {
    const double local[3] = { corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, 0.0 };
    placement->TransformPoint(local, corners + 3 * corner);
  }
}

// Periodic value noise: lattice values of `cells` per repeat, smoothly interpolated.
double PeriodicValueNoise(const double p[3], int cells, std::uint32_t seed)
{
  int i0[3];
  double f[3];
  for (int c = 0; c < 3; ++c)
  {
    const double floor = std::floor(p[c]);
    i0[c] = static_cast<int>(floor);
    const double t = p[c] - floor;
    f[c] = t * t * (3.0 - 2.0 * t);
  }
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    double weight = 1.0;
    std::uint32_t index = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int bit = (corner >> c) & 1;
      weight *= bit ? f[c] : 1.0 - f[c];
      const int lattice = ((i0[c] + bit) % cells + cells) % cells;
      index = index * static_cast<std::uint32_t>(cells) + static_cast<std::uint32_t>(lattice);
    }
    value += weight * vtkIceNoise::Uniform(seed, index);
  }
  return value;
}

// The gradient (in noise cells) of two octaves of periodic value noise, BumpCells cells per
// repeat: what the crack shader of the paper's passes computes per fragment, looked up instead.
std::vector<float> BumpGradients()
{
  const int n = BumpSize;
  std::vector<double> value(static_cast<size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double cell = static_cast<double>(BumpCells) / n;
        const double p[3] = { i * cell, j * cell, k * cell };
        const double q[3] = { 2.0 * p[0], 2.0 * p[1], 2.0 * p[2] };
        value[(static_cast<size_t>(k) * n + j) * n + i] =
          PeriodicValueNoise(p, BumpCells, 11U) + 0.5 * PeriodicValueNoise(q, 2 * BumpCells, 23U);
      }
    }
  }
  std::vector<float> gradients(3 * value.size());
  auto at = [&](int i, int j, int k) {
    return value[(static_cast<size_t>((k + n) % n) * n + (j + n) % n) * n + (i + n) % n];
  };
  const double perCell = static_cast<double>(n) / BumpCells / 2.0; // central difference
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        float* g = &gradients[3 * ((static_cast<size_t>(k) * n + j) * n + i)];
        g[0] = static_cast<float>((at(i + 1, j, k) - at(i - 1, j, k)) * perCell);
        g[1] = static_cast<float>((at(i, j + 1, k) - at(i, j - 1, k)) * perCell);
        g[2] = static_cast<float>((at(i, j, k + 1) - at(i, j, k - 1)) * perCell);
      }
    }
  }
  return gradients;
}

}

//------------------------------------------------------------------------------
vtkIceInteriorTable::vtkIceInteriorTable()
  : CrackTable(vtkSmartPointer<vtkIceCrackTable>::New())
  , Grid(vtkSmartPointer<vtkIceCrackGrid>::New())
{
}

//------------------------------------------------------------------------------
vtkIceInteriorTable::~vtkIceInteriorTable() = default;

//------------------------------------------------------------------------------
std::string vtkIceInteriorTable::Declarations()
{
  return vtkIceInteriorLook::Defines() + vtkIceShaderSections::Get(vtkIceInteriorLookFS, "Dec") +
    vtkIceShaderSections::Get(vtkIceCracksFS, "Dec") +
    vtkIceShaderSections::Get(vtkIceInteriorFS, "Dec") +
    vtkIceShaderSections::Get(vtkIceInteriorFS, "Bubbles");
}

//------------------------------------------------------------------------------
std::string vtkIceInteriorTable::Functions(int lightComplexity, int lightCount)
{
  // VTK's light loop (vtkOpenGLPolyDataMapper): the headlight's specular is n.z in view space;
  // scene lights reflect about the normal. Positional lights shine from their position, without
  // VTK's attenuation and cone.
  std::ostringstream lights;
  if (lightComplexity == 1 && lightCount > 0)
  {
    lights << "  light += pow(max(0.0, dot(n, -iceViewDirectionWC)), ICE_CRACK_SPECULAR_POWER) * "
              "lightColor0;\n";
  }
  for (int i = 0; lightComplexity >= 2 && i < lightCount; ++i)
  {
    const std::string travel =
      "normalize(mat3(iceVCWCMatrix) * lightDirectionVC" + std::to_string(i) + ")";
    std::string direction = travel;
    if (lightComplexity == 3)
    {
      direction = "(lightPositional" + std::to_string(i) +
        " == 1 ? normalize(positionWC - (iceVCWCMatrix * vec4(lightPositionVC" + std::to_string(i) +
        ", 1.0)).xyz) : " + travel + ")";
    }
    lights << "  light += iceCrackSpecular(n, toEye, " << direction << ") * lightColor" << i
           << ";\n";
  }
  std::string code = vtkIceShaderSections::Get(vtkIceInteriorFS, "Functions");
  vtkShaderProgram::Substitute(code, "//ICEHOOK::InteriorLights", lights.str());
  return code;
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::Place(vtkPolyData* ice, vtkIceProperty* look, const Placement& placement)
{
  // The debug views show the cracks alone or the air alone.
  const int cracks = placement.Flat || placement.Debug == vtkIceInteriorLook::DebugAir
    ? 0
    : look->GetNumberOfCracks();
  const int airPlanes =
    placement.Debug == vtkIceInteriorLook::DebugCracks ? 0 : look->GetNumberOfAirPlanes();
  const bool same = this->Placed && ice == this->PlacedFor && ice->GetMTime() == this->PlacedTime &&
    cracks == this->Cracks && look->GetCrackSeed() == this->CrackSeed &&
    airPlanes == this->AirPlanes && look->GetAirSeed() == this->AirSeed &&
    std::equal(placement.Bounds, placement.Bounds + 6, this->Where.Bounds);
  this->Where = placement;
  if (same)
  {
    return;
  }
  this->Cracks = cracks;
  this->CrackSeed = look->GetCrackSeed();
  this->AirPlanes = airPlanes;
  this->AirSeed = look->GetAirSeed();
  this->Placed = true;
  this->PlacedFor = ice;
  this->PlacedTime = ice->GetMTime();
  this->Uploaded = false;
  const double* bounds = placement.Bounds;

  this->CrackTable->Build(this->CrackSeed, this->Cracks, bounds);
  this->Grid->Build(this->CrackTable->GetSheets(), bounds);
  this->AirCorners.assign(12 * static_cast<size_t>(this->AirPlanes), 0.0);
  this->AirRecords.assign(16 * static_cast<size_t>(this->AirPlanes), 0.0f);
  this->AirCenters.assign(3 * static_cast<size_t>(this->AirPlanes), 0.0);
  for (int i = 0; i < this->AirPlanes; ++i)
  {
    vtkNew<vtkTransform> where;
    vtkIceAirGeometry::Placement(this->AirSeed, i, bounds, where);
    float* record = &this->AirRecords[16 * static_cast<size_t>(i)];
    StoreInverse(where, record);
    double tile[2];
    vtkIceAirGeometry::Tile(i, tile);
    record[12] = static_cast<float>(tile[0]);
    record[13] = static_cast<float>(tile[1]);
    where->GetPosition(&this->AirCenters[3 * static_cast<size_t>(i)]);
    StoreQuad(where, &this->AirCorners[12 * static_cast<size_t>(i)]);
  }
  this->AirOrder.clear();
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::Order(const double eye[3])
{
  // Back to front by the planes' centres, as vtkIceBackToFront orders the paper passes' planes.
  const std::vector<vtkIdType> order = vtkIceBackToFront::Order(this->AirCenters, eye);
  if (order != this->AirOrder)
  {
    this->AirOrder = order;
    this->Uploaded = false;
  }
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::Upload(vtkOpenGLRenderWindow* window)
{
  if (!this->Table || this->Table->GetContext() != window)
  {
    this->Table = vtkSmartPointer<vtkTextureObject>::New();
    this->Table->SetContext(window);
    this->Table->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Table->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->GridLists = vtkSmartPointer<vtkTextureObject>::New();
    this->GridLists->SetContext(window);
    this->GridLists->SetMinificationFilter(vtkTextureObject::Nearest);
    this->GridLists->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Uploaded = false;
  }
  if (!this->Uploaded)
  {
    // Rows 0-2: the outlines, each sample (R) with the next round the turn (G): one lookup
    // between the two. Then the records, cracks first, planes back to front.
    const int records = this->Cracks + this->AirPlanes;
    const int rows = 3 + std::max(1, (records + RecordsPerRow - 1) / RecordsPerRow);
    std::vector<float> texels(static_cast<size_t>(4 * OutlineSamples) * rows, 0.0f);
    const std::vector<float>& outlines = this->CrackTable->GetOutlines();
    for (size_t i = 0; i < outlines.size(); ++i)
    {
      const size_t turn = i - i % OutlineSamples;
      texels[4 * i] = outlines[i];
      texels[4 * i + 1] = outlines[turn + (i + 1) % OutlineSamples];
    }
    float* first = &texels[static_cast<size_t>(4 * OutlineSamples) * 3];
    const std::vector<float>& cracks = this->CrackTable->GetRecords();
    std::copy(cracks.begin(), cracks.end(), first);
    float* planes = first + cracks.size();
    for (size_t k = 0; k < this->AirOrder.size(); ++k)
    {
      const float* record = &this->AirRecords[16 * static_cast<size_t>(this->AirOrder[k])];
      std::copy(record, record + 16, planes + 16 * k);
    }
    this->Table->Create2DFromRaw(OutlineSamples, rows, 4, VTK_FLOAT, texels.data());
    // The grid's offsets and lists in rows of GridRowTexels (within every GPU's width limit).
    std::vector<float> lists = this->Grid->GetTexels();
    const int gridRows =
      std::max(1, static_cast<int>((lists.size() + GridRowTexels - 1) / GridRowTexels));
    lists.resize(static_cast<size_t>(gridRows) * GridRowTexels, 0.0f);
    this->GridLists->Create2DFromRaw(GridRowTexels, gridRows, 1, VTK_FLOAT, lists.data());
    this->Uploaded = true;
  }
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::PrepareCracks(vtkRenderer* renderer, vtkPolyData* ice,
  vtkIceProperty* look, const Placement& placement, vtkShaderProgram* program,
  vtkTextureObject* active[2])
{
  this->Place(ice, look, placement);
  this->Upload(static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()));
  this->Table->Activate();
  this->GridLists->Activate();
  active[0] = this->Table;
  active[1] = this->GridLists;
  this->SetCrackUniforms(program);
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::SetCrackUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("iceInteriorTable", this->Table->GetTextureUnit());
  program->SetUniformi("iceCrackCount", this->Cracks);
  program->SetUniformi("iceCrackGrid", this->GridLists->GetTextureUnit());
  // VTK's programs have no ivec3 setter: the cell counts as floats.
  const int* dimensions = this->Grid->GetDimensions();
  const float size[3] = { static_cast<float>(dimensions[0]), static_cast<float>(dimensions[1]),
    static_cast<float>(dimensions[2]) };
  program->SetUniform3f("iceCrackGridSize", size);
  float origin[3];
  std::copy(this->Grid->GetOrigin(), this->Grid->GetOrigin() + 3, origin);
  program->SetUniform3f("iceCrackGridOrigin", origin);
  program->SetUniformf("iceCrackGridCell", static_cast<float>(this->Grid->GetCellSize()));
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::Prepare(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* ice,
  vtkIceProperty* look, const Placement& placement, vtkTexture* atlas)
{
  this->Place(ice, look, placement);
  this->Look = look;
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  renderer->GetActiveCamera()->GetPosition(eye);
  vtkNew<vtkMatrix4x4> worldToModel;
  vtkMatrix4x4::Invert(actor->GetMatrix(), worldToModel);
  worldToModel->MultiplyPoint(eye, eye);
  this->Order(eye);

  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  this->Upload(window);
  this->MakeBump(window);
  this->Table->Activate();
  this->GridLists->Activate();
  this->Bump->Activate();
  this->ActiveAtlas = this->AirPlanes > 0 ? atlas : nullptr;
  if (this->ActiveAtlas)
  {
    this->ActiveAtlas->Render(renderer);
  }
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::MakeBump(vtkOpenGLRenderWindow* window)
{
  if (this->Bump && this->Bump->GetContext() == window)
  {
    return;
  }
  this->Bump = vtkSmartPointer<vtkTextureObject>::New();
  this->Bump->SetContext(window);
  this->Bump->SetWrapS(vtkTextureObject::Repeat);
  this->Bump->SetWrapT(vtkTextureObject::Repeat);
  this->Bump->SetWrapR(vtkTextureObject::Repeat);
  this->Bump->SetMinificationFilter(vtkTextureObject::Linear);
  this->Bump->SetMagnificationFilter(vtkTextureObject::Linear);
  std::vector<float> gradients = BumpGradients();
  this->Bump->Create3DFromRaw(BumpSize, BumpSize, BumpSize, 3, VTK_FLOAT, gradients.data());
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::PrepareTraceAir(vtkRenderer* renderer, vtkPolyData* ice,
  vtkIceProperty* look, const Placement& placement, vtkShaderProgram* program,
  vtkTextureObject* active[4], vtkTexture* atlas)
{
  this->PrepareCracks(renderer, ice, look, placement, program, active);
  this->MakeBump(static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow()));
  this->Bump->Activate();
  active[2] = this->Bump;
  // Without air planes the atlas sampler sits on a 2D texture's unit (see SetUniforms).
  vtkTextureObject* images = nullptr;
  if (atlas && this->AirPlanes > 0)
  {
    atlas->Render(renderer);
    images = static_cast<vtkOpenGLTexture*>(atlas)->GetTextureObject();
  }
  active[3] = images;
  program->SetUniformi(
    "iceAirAtlas", images ? images->GetTextureUnit() : this->Table->GetTextureUnit());
  program->SetUniformi("iceAirCount", images ? this->AirPlanes : 0);
  program->SetUniformf("iceMilkiness", static_cast<float>(look->GetMilkiness()));
  program->SetUniformi("iceInteriorDebug", 0);
  this->SetBubbleUniforms(program, look);
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::SetUniforms(vtkShaderProgram* program)
{
  if (!this->Table || !this->Look)
  {
    return;
  }
  this->SetCrackUniforms(program);
  // Without air the atlas sampler still needs a 2D texture's unit: samplers of different types
  // on one unit (unit 0 by default) make the draw fail.
  program->SetUniformi("iceAirAtlas",
    this->ActiveAtlas
      ? static_cast<vtkOpenGLTexture*>(this->ActiveAtlas)->GetTextureObject()->GetTextureUnit()
      : this->Table->GetTextureUnit());
  program->SetUniformi("iceAirCount", this->ActiveAtlas ? this->AirPlanes : 0);
  program->SetUniformf("iceCrackIntensity", static_cast<float>(this->Look->GetCrackIntensity()));
  program->SetUniformf("iceCrackReflection", static_cast<float>(this->Look->GetCrackReflection()));
  program->SetUniformf(
    "iceCrackBumpStrength", static_cast<float>(vtkIceInteriorLook::CrackBumpStrength));
  program->SetUniformf("iceCrackBumpFrequency",
    static_cast<float>(vtkIceInteriorLook::CrackBumpFrequency(this->Where.Extent)));
  program->SetUniformf("iceMilkiness", static_cast<float>(this->Look->GetMilkiness()));
  program->SetUniformi("iceInteriorDebug", this->Where.Debug);
  this->SetBubbleUniforms(program, this->Look);
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::SetBubbleUniforms(vtkShaderProgram* program, vtkIceProperty* look)
{
  program->SetUniformi("iceInteriorBump", this->Bump->GetTextureUnit());
  // The milky core: its frame in the placement box, its density from the milkiness.
  float coreCenter[3] = { 0.0f, 0.0f, 0.0f };
  float coreScale[3] = { 1.0f, 1.0f, 1.0f };
  double density = 0.0;
  if (look->HasMilkyCore())
  {
    density = vtkIceInteriorLook::CoreDensity(look->GetMilkiness());
  }
  // The bubbles gather in the core's frame, or in a core of their own.
  if (look->HasMilkyCore() || look->GetBubbleDensity() > 0.0)
  {
    vtkIceInteriorLook::CoreFrame(this->Where.Bounds,
      look->GetMilkyCoreRadius() > 0.0 ? look->GetMilkyCoreRadius()
                                             : vtkIceInteriorLook::BubbleCoreRadius,
      coreCenter, coreScale);
  }
  program->SetUniformf("iceBubbleDensity", static_cast<float>(look->GetBubbleDensity()));
  program->SetUniformf("iceBubbleCell",
    static_cast<float>(this->Where.Extent / vtkIceInteriorLook::BubbleCells));
  program->SetUniformf("iceBubbleFade",
    static_cast<float>(vtkIceInteriorLook::BubbleDepthFade / this->Where.Extent));
  program->SetUniform3f("iceCoreCenter", coreCenter);
  program->SetUniform3f("iceCoreScale", coreScale);
  program->SetUniformf("iceCoreDensity", static_cast<float>(density));
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::Finish(vtkRenderer* renderer)
{
  this->Look = nullptr;
  if (this->ActiveAtlas)
  {
    this->ActiveAtlas->PostRender(renderer);
    this->ActiveAtlas = nullptr;
  }
  if (this->Table)
  {
    this->Table->Deactivate();
    this->GridLists->Deactivate();
    this->Bump->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Table)
  {
    this->Table->ReleaseGraphicsResources(window);
    this->Table = nullptr;
    this->GridLists->ReleaseGraphicsResources(window);
    this->GridLists = nullptr;
  }
  if (this->Bump)
  {
    this->Bump->ReleaseGraphicsResources(window);
    this->Bump = nullptr;
  }
  this->Uploaded = false;
}

//------------------------------------------------------------------------------
void vtkIceInteriorTable::GetAirQuad(int k, double corners[12], double atlas[8]) const
{
  const size_t plane = static_cast<size_t>(this->AirOrder[static_cast<size_t>(k)]);
  std::copy(&this->AirCorners[12 * plane], &this->AirCorners[12 * plane] + 12, corners);
  const float* record = &this->AirRecords[16 * plane];
  for (int corner = 0; corner < 4; ++corner)
  {
    atlas[2 * corner] = record[12] + vtkIceAirGeometry::TileInset +
      vtkIceAirGeometry::TileScale * (corner & 1 ? 2.0 : 0.0);
    atlas[2 * corner + 1] = record[13] + vtkIceAirGeometry::TileInset +
      vtkIceAirGeometry::TileScale * (corner & 2 ? 2.0 : 0.0);
  }
}
