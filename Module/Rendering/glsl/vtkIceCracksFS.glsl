// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The nearest crack along a ray in the ice: the sheets of vtkIceInteriorTable's table, found
// through the cells of its grid (vtkIceCrackGrid) front to back. The screen-space interior looks
// along the eye ray, the trace along the segments after each reflection inside. Mirrored on the
// CPU by vtkIceCrackTable::Nearest and ::Normal (every sheet tested, no grid): change them
// together.
uniform sampler2D iceInteriorTable; // R: crack outlines (rows 0-2); then 4 texels per record
uniform int iceCrackCount;          // records 0 .. iceCrackCount - 1
uniform sampler2D iceCrackGrid;     // R: each cell's list's start, then the lists
uniform vec3 iceCrackGridSize;      // cells along x, y, z
uniform vec3 iceCrackGridOrigin;    // model coordinates of cell (0, 0, 0)'s lower corner
uniform float iceCrackGridCell;     // the cells' side, model units

const int iceOutlineSamples = 64; // per crack model, over the full turn
const int iceRecordsPerRow = 16;
const int iceCrackGridRowTexels = 4096;

int iceCrackGridEntry(int at)
{
  return int(texelFetch(iceCrackGrid, ivec2(at % iceCrackGridRowTexels,
    at / iceCrackGridRowTexels), 0).r);
}

vec4 iceInteriorTexel(int record, int texel)
{
  return texelFetch(iceInteriorTable,
    ivec2(4 * (record % iceRecordsPerRow) + texel, 3 + record / iceRecordsPerRow), 0);
}

// A record's model-to-local transform (three rows) applied to the ray o + s d.
struct IceLocalRay
{
  vec3 origin;
  vec3 direction;
  vec4 row0;
  vec4 row1;
  vec4 row2;
  vec4 shape;
};

IceLocalRay iceLocalRay(int record, vec3 o, vec3 d)
{
  IceLocalRay ray;
  ray.row0 = iceInteriorTexel(record, 0);
  ray.row1 = iceInteriorTexel(record, 1);
  ray.row2 = iceInteriorTexel(record, 2);
  ray.shape = iceInteriorTexel(record, 3);
  ray.origin = vec3(dot(ray.row0.xyz, o) + ray.row0.w, dot(ray.row1.xyz, o) + ray.row1.w,
    dot(ray.row2.xyz, o) + ray.row2.w);
  ray.direction = vec3(dot(ray.row0.xyz, d), dot(ray.row1.xyz, d), dot(ray.row2.xyz, d));
  return ray;
}

// Outline radius of crack model `model` at `angle` (radians), linear between the samples.
float iceCrackOutline(int model, float angle)
{
  float x = fract(angle / 6.2831853) * float(iceOutlineSamples);
  vec2 r = texelFetch(iceInteriorTable, ivec2(int(x) % iceOutlineSamples, model), 0).rg;
  return mix(r.x, r.y, fract(x));
}

// A walk through the cells of a grid along the ray p + s v (grid units: cells of side 1), front
// to back: `cell` is the current cell, `next` the s at which the ray leaves it across x, y and z.
struct IceGridWalk
{
  vec3 cell;
  vec3 direction;
  vec3 delta;
  vec3 next;
};

IceGridWalk iceGridWalk(vec3 p, vec3 v, vec3 cell)
{
  IceGridWalk walk;
  walk.cell = cell;
  walk.direction = sign(v);
  walk.delta = 1.0 / max(abs(v), vec3(1.0e-9));
  // A selection (mix by a bvec3): mix by a float would compute 1e30 + (x - 1e30) * 1 = 0.
  walk.next = mix(vec3(1.0e30),
    (walk.direction * (cell - p) + max(walk.direction, 0.0)) * walk.delta,
    notEqual(walk.direction, vec3(0.0)));
  return walk;
}

// Into the next cell; returns the s at which the ray entered it.
float iceGridStep(inout IceGridWalk walk)
{
  float s = min(walk.next.x, min(walk.next.y, walk.next.z));
  vec3 crossed = vec3(lessThanEqual(walk.next, vec3(s)));
  walk.cell += crossed * walk.direction;
  walk.next += crossed * walk.delta;
  return s;
}

// The nearest crack the ray o + s d (model coordinates) crosses inside its outline with
// 0 < s < sEnd: true with s, its record, the ray in its frame (`nearestRay`, for iceCrackNormal) and
// where on it (`edge`: the distance from its centre over the outline's, 1 at the outline). The
// grid's cells are walked until a crack nearer than a cell's far side is found (any nearer one
// crosses a cell visited already, which lists it). A crack missed (no crossing in range, or
// outside its outline) or met behind the nearest so far is skipped before its outline is read.
// Both loops test at their end: llvmpipe runs the body of a loop that tests first once more, with
// every lane masked off, before it leaves.
bool iceNearestCrack(vec3 o, vec3 d, float sEnd, out float nearest, out int record,
  out float edge, out IceLocalRay nearestRay)
{
  nearest = sEnd;
  record = -1;
  edge = 0.0;
  nearestRay = IceLocalRay(vec3(0.0), vec3(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
  if (iceCrackCount <= 0)
  {
    return false;
  }
  vec3 gridP = (o - iceCrackGridOrigin) / iceCrackGridCell;
  ivec3 gridSize = ivec3(iceCrackGridSize + 0.5);
  IceGridWalk walk = iceGridWalk(gridP, d / iceCrackGridCell,
    clamp(floor(gridP), vec3(0.0), vec3(gridSize - 1)));
  int cells = gridSize.x + gridSize.y + gridSize.z;
  int i = 0;
  bool inGrid = true;
  float sCell = 0.0;
  do
  {
    ivec3 c = ivec3(walk.cell);
    int cell = (c.z * gridSize.y + c.y) * gridSize.x + c.x;
    int k = iceCrackGridEntry(cell);
    int last = iceCrackGridEntry(cell + 1);
    do
    {
      int entry = k++;
      // The sheet z = a x^2 + b y^2 in the crack's frame: a quadratic in s. A ray crosses such a
      // shallow sheet at most once inside the outline in practice: the nearer root in range.
      int candidate = iceCrackGridEntry(min(entry, last - 1));
      if (entry >= last || candidate == record)
      {
        continue; // an empty cell, or met in an earlier cell
      }
      IceLocalRay ray = iceLocalRay(candidate, o, d);
      float a = ray.shape.x;
      float b = ray.shape.y;
      vec3 p = ray.origin;
      vec3 v = ray.direction;
      float qa = -(a * v.x * v.x + b * v.y * v.y);
      float qb = v.z - 2.0 * (a * p.x * v.x + b * p.y * v.y);
      float qc = p.z - a * p.x * p.x - b * p.y * p.y;
      float discriminant = qb * qb - 4.0 * qa * qc;
      float q = -0.5 * (qb + (qb < 0.0 ? -1.0 : 1.0) * sqrt(max(discriminant, 0.0)));
      bool quadratic = abs(qa) > 1.0e-6 * abs(qb);
      float s0 = quadratic ? q / qa : -qc / qb;
      float s1 = quadratic ? qc / q : -1.0;
      bool in0 = s0 > 0.0 && s0 < sEnd;
      bool in1 = s1 > 0.0 && s1 < sEnd;
      float s = in0 && (!in1 || s0 < s1) ? s0 : s1;
      if (discriminant < 0.0 || !(in0 || in1) || s >= nearest)
      {
        continue;
      }
      vec3 hit = p + s * v;
      float outline = iceCrackOutline(int(ray.shape.z), atan(hit.y, hit.x));
      if (length(hit.xy) > outline)
      {
        continue;
      }
      nearest = s;
      record = candidate;
      edge = length(hit.xy) / max(outline, 1.0e-6);
      nearestRay = ray;
    } while (k < last);
    sCell = iceGridStep(walk);
    ivec3 next = ivec3(walk.cell);
    inGrid = all(greaterThanEqual(next, ivec3(0))) && all(lessThan(next, gridSize));
    ++i;
  } while (inGrid && i < cells && sCell < nearest);
  return record >= 0;
}

// The normal of the crack whose frame holds `ray` (iceNearestCrack's) where the ray meets it at
// s, in model coordinates as a normal (to the world by the normal matrix), unnormalised: the
// gradient of z - a x^2 - b y^2 in the crack's frame taken back.
vec3 iceCrackNormal(IceLocalRay ray, float s)
{
  vec3 hit = ray.origin + s * ray.direction;
  vec3 g = vec3(-2.0 * ray.shape.x * hit.x, -2.0 * ray.shape.y * hit.y, 1.0);
  return g.x * ray.row0.xyz + g.y * ray.row1.xyz + g.z * ray.row2.xyz;
}
