// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceTeapotSource.h"

#include "vtkIceSmoothNormals.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkIceTeapotSource);

namespace
{
// The 306 control points of the Newell teapot (public-domain data, z up).
// clang-format off
const double TeapotPoints[306][3] = {
  { 1.4, 0.0, 2.4 }, { 1.4, -0.784, 2.4 }, { 0.784, -1.4, 2.4 },
  { 0.0, -1.4, 2.4 }, { 1.3375, 0.0, 2.53125 }, { 1.3375, -0.749, 2.53125 },
  { 0.749, -1.3375, 2.53125 }, { 0.0, -1.3375, 2.53125 }, { 1.4375, 0.0, 2.53125 },
  { 1.4375, -0.805, 2.53125 }, { 0.805, -1.4375, 2.53125 }, { 0.0, -1.4375, 2.53125 },
  { 1.5, 0.0, 2.4 }, { 1.5, -0.84, 2.4 }, { 0.84, -1.5, 2.4 },
  { 0.0, -1.5, 2.4 }, { -0.784, -1.4, 2.4 }, { -1.4, -0.784, 2.4 },
  { -1.4, 0.0, 2.4 }, { -0.749, -1.3375, 2.53125 }, { -1.3375, -0.749, 2.53125 },
  { -1.3375, 0.0, 2.53125 }, { -0.805, -1.4375, 2.53125 }, { -1.4375, -0.805, 2.53125 },
  { -1.4375, 0.0, 2.53125 }, { -0.84, -1.5, 2.4 }, { -1.5, -0.84, 2.4 },
  { -1.5, 0.0, 2.4 }, { -1.4, 0.784, 2.4 }, { -0.784, 1.4, 2.4 },
  { 0.0, 1.4, 2.4 }, { -1.3375, 0.749, 2.53125 }, { -0.749, 1.3375, 2.53125 },
  { 0.0, 1.3375, 2.53125 }, { -1.4375, 0.805, 2.53125 }, { -0.805, 1.4375, 2.53125 },
  { 0.0, 1.4375, 2.53125 }, { -1.5, 0.84, 2.4 }, { -0.84, 1.5, 2.4 },
  { 0.0, 1.5, 2.4 }, { 0.784, 1.4, 2.4 }, { 1.4, 0.784, 2.4 },
  { 0.749, 1.3375, 2.53125 }, { 1.3375, 0.749, 2.53125 }, { 0.805, 1.4375, 2.53125 },
  { 1.4375, 0.805, 2.53125 }, { 0.84, 1.5, 2.4 }, { 1.5, 0.84, 2.4 },
  { 1.75, 0.0, 1.875 }, { 1.75, -0.98, 1.875 }, { 0.98, -1.75, 1.875 },
  { 0.0, -1.75, 1.875 }, { 2.0, 0.0, 1.35 }, { 2.0, -1.12, 1.35 },
  { 1.12, -2.0, 1.35 }, { 0.0, -2.0, 1.35 }, { 2.0, 0.0, 0.9 },
  { 2.0, -1.12, 0.9 }, { 1.12, -2.0, 0.9 }, { 0.0, -2.0, 0.9 },
  { -0.98, -1.75, 1.875 }, { -1.75, -0.98, 1.875 }, { -1.75, 0.0, 1.875 },
  { -1.12, -2.0, 1.35 }, { -2.0, -1.12, 1.35 }, { -2.0, 0.0, 1.35 },
  { -1.12, -2.0, 0.9 }, { -2.0, -1.12, 0.9 }, { -2.0, 0.0, 0.9 },
  { -1.75, 0.98, 1.875 }, { -0.98, 1.75, 1.875 }, { 0.0, 1.75, 1.875 },
  { -2.0, 1.12, 1.35 }, { -1.12, 2.0, 1.35 }, { 0.0, 2.0, 1.35 },
  { -2.0, 1.12, 0.9 }, { -1.12, 2.0, 0.9 }, { 0.0, 2.0, 0.9 },
  { 0.98, 1.75, 1.875 }, { 1.75, 0.98, 1.875 }, { 1.12, 2.0, 1.35 },
  { 2.0, 1.12, 1.35 }, { 1.12, 2.0, 0.9 }, { 2.0, 1.12, 0.9 },
  { 2.0, 0.0, 0.45 }, { 2.0, -1.12, 0.45 }, { 1.12, -2.0, 0.45 },
  { 0.0, -2.0, 0.45 }, { 1.5, 0.0, 0.225 }, { 1.5, -0.84, 0.225 },
  { 0.84, -1.5, 0.225 }, { 0.0, -1.5, 0.225 }, { 1.5, 0.0, 0.15 },
  { 1.5, -0.84, 0.15 }, { 0.84, -1.5, 0.15 }, { 0.0, -1.5, 0.15 },
  { -1.12, -2.0, 0.45 }, { -2.0, -1.12, 0.45 }, { -2.0, 0.0, 0.45 },
  { -0.84, -1.5, 0.225 }, { -1.5, -0.84, 0.225 }, { -1.5, 0.0, 0.225 },
  { -0.84, -1.5, 0.15 }, { -1.5, -0.84, 0.15 }, { -1.5, 0.0, 0.15 },
  { -2.0, 1.12, 0.45 }, { -1.12, 2.0, 0.45 }, { 0.0, 2.0, 0.45 },
  { -1.5, 0.84, 0.225 }, { -0.84, 1.5, 0.225 }, { 0.0, 1.5, 0.225 },
  { -1.5, 0.84, 0.15 }, { -0.84, 1.5, 0.15 }, { 0.0, 1.5, 0.15 },
  { 1.12, 2.0, 0.45 }, { 2.0, 1.12, 0.45 }, { 0.84, 1.5, 0.225 },
  { 1.5, 0.84, 0.225 }, { 0.84, 1.5, 0.15 }, { 1.5, 0.84, 0.15 },
  { -1.6, 0.0, 2.025 }, { -1.6, -0.3, 2.025 }, { -1.5, -0.3, 2.25 },
  { -1.5, 0.0, 2.25 }, { -2.3, 0.0, 2.025 }, { -2.3, -0.3, 2.025 },
  { -2.5, -0.3, 2.25 }, { -2.5, 0.0, 2.25 }, { -2.7, 0.0, 2.025 },
  { -2.7, -0.3, 2.025 }, { -3.0, -0.3, 2.25 }, { -3.0, 0.0, 2.25 },
  { -2.7, 0.0, 1.8 }, { -2.7, -0.3, 1.8 }, { -3.0, -0.3, 1.8 },
  { -3.0, 0.0, 1.8 }, { -1.5, 0.3, 2.25 }, { -1.6, 0.3, 2.025 },
  { -2.5, 0.3, 2.25 }, { -2.3, 0.3, 2.025 }, { -3.0, 0.3, 2.25 },
  { -2.7, 0.3, 2.025 }, { -3.0, 0.3, 1.8 }, { -2.7, 0.3, 1.8 },
  { -2.7, 0.0, 1.575 }, { -2.7, -0.3, 1.575 }, { -3.0, -0.3, 1.35 },
  { -3.0, 0.0, 1.35 }, { -2.5, 0.0, 1.125 }, { -2.5, -0.3, 1.125 },
  { -2.65, -0.3, 0.9375 }, { -2.65, 0.0, 0.9375 }, { -2.0, -0.3, 0.9 },
  { -1.9, -0.3, 0.6 }, { -1.9, 0.0, 0.6 }, { -3.0, 0.3, 1.35 },
  { -2.7, 0.3, 1.575 }, { -2.65, 0.3, 0.9375 }, { -2.5, 0.3, 1.125 },
  { -1.9, 0.3, 0.6 }, { -2.0, 0.3, 0.9 }, { 1.7, 0.0, 1.425 },
  { 1.7, -0.66, 1.425 }, { 1.7, -0.66, 0.6 }, { 1.7, 0.0, 0.6 },
  { 2.6, 0.0, 1.425 }, { 2.6, -0.66, 1.425 }, { 3.1, -0.66, 0.825 },
  { 3.1, 0.0, 0.825 }, { 2.3, 0.0, 2.1 }, { 2.3, -0.25, 2.1 },
  { 2.4, -0.25, 2.025 }, { 2.4, 0.0, 2.025 }, { 2.7, 0.0, 2.4 },
  { 2.7, -0.25, 2.4 }, { 3.3, -0.25, 2.4 }, { 3.3, 0.0, 2.4 },
  { 1.7, 0.66, 0.6 }, { 1.7, 0.66, 1.425 }, { 3.1, 0.66, 0.825 },
  { 2.6, 0.66, 1.425 }, { 2.4, 0.25, 2.025 }, { 2.3, 0.25, 2.1 },
  { 3.3, 0.25, 2.4 }, { 2.7, 0.25, 2.4 }, { 2.8, 0.0, 2.475 },
  { 2.8, -0.25, 2.475 }, { 3.525, -0.25, 2.49375 }, { 3.525, 0.0, 2.49375 },
  { 2.9, 0.0, 2.475 }, { 2.9, -0.15, 2.475 }, { 3.45, -0.15, 2.5125 },
  { 3.45, 0.0, 2.5125 }, { 2.8, 0.0, 2.4 }, { 2.8, -0.15, 2.4 },
  { 3.2, -0.15, 2.4 }, { 3.2, 0.0, 2.4 }, { 3.525, 0.25, 2.49375 },
  { 2.8, 0.25, 2.475 }, { 3.45, 0.15, 2.5125 }, { 2.9, 0.15, 2.475 },
  { 3.2, 0.15, 2.4 }, { 2.8, 0.15, 2.4 }, { 0.0, 0.0, 3.15 },
  { 0.0, -0.002, 3.15 }, { 0.002, 0.0, 3.15 }, { 0.8, 0.0, 3.15 },
  { 0.8, -0.45, 3.15 }, { 0.45, -0.8, 3.15 }, { 0.0, -0.8, 3.15 },
  { 0.0, 0.0, 2.85 }, { 0.2, 0.0, 2.7 }, { 0.2, -0.112, 2.7 },
  { 0.112, -0.2, 2.7 }, { 0.0, -0.2, 2.7 }, { -0.002, 0.0, 3.15 },
  { -0.45, -0.8, 3.15 }, { -0.8, -0.45, 3.15 }, { -0.8, 0.0, 3.15 },
  { -0.112, -0.2, 2.7 }, { -0.2, -0.112, 2.7 }, { -0.2, 0.0, 2.7 },
  { 0.0, 0.002, 3.15 }, { -0.8, 0.45, 3.15 }, { -0.45, 0.8, 3.15 },
  { 0.0, 0.8, 3.15 }, { -0.2, 0.112, 2.7 }, { -0.112, 0.2, 2.7 },
  { 0.0, 0.2, 2.7 }, { 0.45, 0.8, 3.15 }, { 0.8, 0.45, 3.15 },
  { 0.112, 0.2, 2.7 }, { 0.2, 0.112, 2.7 }, { 0.4, 0.0, 2.55 },
  { 0.4, -0.224, 2.55 }, { 0.224, -0.4, 2.55 }, { 0.0, -0.4, 2.55 },
  { 1.3, 0.0, 2.55 }, { 1.3, -0.728, 2.55 }, { 0.728, -1.3, 2.55 },
  { 0.0, -1.3, 2.55 }, { 1.3, 0.0, 2.4 }, { 1.3, -0.728, 2.4 },
  { 0.728, -1.3, 2.4 }, { 0.0, -1.3, 2.4 }, { -0.224, -0.4, 2.55 },
  { -0.4, -0.224, 2.55 }, { -0.4, 0.0, 2.55 }, { -0.728, -1.3, 2.55 },
  { -1.3, -0.728, 2.55 }, { -1.3, 0.0, 2.55 }, { -0.728, -1.3, 2.4 },
  { -1.3, -0.728, 2.4 }, { -1.3, 0.0, 2.4 }, { -0.4, 0.224, 2.55 },
  { -0.224, 0.4, 2.55 }, { 0.0, 0.4, 2.55 }, { -1.3, 0.728, 2.55 },
  { -0.728, 1.3, 2.55 }, { 0.0, 1.3, 2.55 }, { -1.3, 0.728, 2.4 },
  { -0.728, 1.3, 2.4 }, { 0.0, 1.3, 2.4 }, { 0.224, 0.4, 2.55 },
  { 0.4, 0.224, 2.55 }, { 0.728, 1.3, 2.55 }, { 1.3, 0.728, 2.55 },
  { 0.728, 1.3, 2.4 }, { 1.3, 0.728, 2.4 }, { 0.0, 0.0, 0.0 },
  { 1.5, 0.0, 0.15 }, { 1.5, 0.84, 0.15 }, { 0.84, 1.5, 0.15 },
  { 0.0, 1.5, 0.15 }, { 1.5, 0.0, 0.075 }, { 1.5, 0.84, 0.075 },
  { 0.84, 1.5, 0.075 }, { 0.0, 1.5, 0.075 }, { 1.425, 0.0, 0.0 },
  { 1.425, 0.798, 0.0 }, { 0.798, 1.425, 0.0 }, { 0.0, 1.425, 0.0 },
  { -0.84, 1.5, 0.15 }, { -1.5, 0.84, 0.15 }, { -1.5, 0.0, 0.15 },
  { -0.84, 1.5, 0.075 }, { -1.5, 0.84, 0.075 }, { -1.5, 0.0, 0.075 },
  { -0.798, 1.425, 0.0 }, { -1.425, 0.798, 0.0 }, { -1.425, 0.0, 0.0 },
  { -1.5, -0.84, 0.15 }, { -0.84, -1.5, 0.15 }, { 0.0, -1.5, 0.15 },
  { -1.5, -0.84, 0.075 }, { -0.84, -1.5, 0.075 }, { 0.0, -1.5, 0.075 },
  { -1.425, -0.798, 0.0 }, { -0.798, -1.425, 0.0 }, { 0.0, -1.425, 0.0 },
  { 0.84, -1.5, 0.15 }, { 1.5, -0.84, 0.15 }, { 0.84, -1.5, 0.075 },
  { 1.5, -0.84, 0.075 }, { 0.798, -1.425, 0.0 }, { 1.425, -0.798, 0.0 },
};

// 32 bicubic patches as 4x4 zero-based indices into TeapotPoints, row by row:
// rim 0-3, body 4-11, handle 12-15, spout 16-19, lid 20-27, bottom 28-31.
const int TeapotPatches[32][16] = {
  { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15 },
  { 3, 16, 17, 18, 7, 19, 20, 21, 11, 22, 23, 24, 15, 25, 26, 27 },
  { 18, 28, 29, 30, 21, 31, 32, 33, 24, 34, 35, 36, 27, 37, 38, 39 },
  { 30, 40, 41, 0, 33, 42, 43, 4, 36, 44, 45, 8, 39, 46, 47, 12 },
  { 12, 13, 14, 15, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59 },
  { 15, 25, 26, 27, 51, 60, 61, 62, 55, 63, 64, 65, 59, 66, 67, 68 },
  { 27, 37, 38, 39, 62, 69, 70, 71, 65, 72, 73, 74, 68, 75, 76, 77 },
  { 39, 46, 47, 12, 71, 78, 79, 48, 74, 80, 81, 52, 77, 82, 83, 56 },
  { 56, 57, 58, 59, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 },
  { 59, 66, 67, 68, 87, 96, 97, 98, 91, 99, 100, 101, 95, 102, 103, 104 },
  { 68, 75, 76, 77, 98, 105, 106, 107, 101, 108, 109, 110, 104, 111, 112, 113 },
  { 77, 82, 83, 56, 107, 114, 115, 84, 110, 116, 117, 88, 113, 118, 119, 92 },
  { 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135 },
  { 123, 136, 137, 120, 127, 138, 139, 124, 131, 140, 141, 128, 135, 142, 143, 132 },
  { 132, 133, 134, 135, 144, 145, 146, 147, 148, 149, 150, 151, 68, 152, 153, 154 },
  { 135, 142, 143, 132, 147, 155, 156, 144, 151, 157, 158, 148, 154, 159, 160, 68 },
  { 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176 },
  { 164, 177, 178, 161, 168, 179, 180, 165, 172, 181, 182, 169, 176, 183, 184, 173 },
  { 173, 174, 175, 176, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196 },
  { 176, 183, 184, 173, 188, 197, 198, 185, 192, 199, 200, 189, 196, 201, 202, 193 },
  { 203, 203, 203, 203, 206, 207, 208, 209, 210, 210, 210, 210, 211, 212, 213, 214 },
  { 203, 203, 203, 203, 209, 216, 217, 218, 210, 210, 210, 210, 214, 219, 220, 221 },
  { 203, 203, 203, 203, 218, 223, 224, 225, 210, 210, 210, 210, 221, 226, 227, 228 },
  { 203, 203, 203, 203, 225, 229, 230, 206, 210, 210, 210, 210, 228, 231, 232, 211 },
  { 211, 212, 213, 214, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244 },
  { 214, 219, 220, 221, 236, 245, 246, 247, 240, 248, 249, 250, 244, 251, 252, 253 },
  { 221, 226, 227, 228, 247, 254, 255, 256, 250, 257, 258, 259, 253, 260, 261, 262 },
  { 228, 231, 232, 211, 256, 263, 264, 233, 259, 265, 266, 237, 262, 267, 268, 241 },
  { 269, 269, 269, 269, 278, 279, 280, 281, 274, 275, 276, 277, 270, 271, 272, 273 },
  { 269, 269, 269, 269, 281, 288, 289, 290, 277, 285, 286, 287, 273, 282, 283, 284 },
  { 269, 269, 269, 269, 290, 297, 298, 299, 287, 294, 295, 296, 284, 291, 292, 293 },
  { 269, 269, 269, 269, 299, 304, 305, 278, 296, 302, 303, 274, 293, 300, 301, 270 },
};
// clang-format on

// Cubic Bernstein basis b and its derivative db at t.
void Bernstein(double t, double b[4], double db[4])
{
  const double s = 1.0 - t;
  b[0] = s * s * s;
  b[1] = 3.0 * t * s * s;
  b[2] = 3.0 * t * t * s;
  b[3] = t * t * t;
  db[0] = -3.0 * s * s;
  db[1] = 3.0 * s * (s - 2.0 * t);
  db[2] = 3.0 * t * (2.0 * s - t);
  db[3] = 3.0 * t * t;
}

// Position p and partial derivatives pu, pv of a patch. u runs along a row
// of control points, v from row to row.
void EvaluatePatch(const int patch[16], double u, double v, double p[3], double pu[3], double pv[3])
{
  double bu[4], dbu[4], bv[4], dbv[4];
  Bernstein(u, bu, dbu);
  Bernstein(v, bv, dbv);
  std::fill_n(p, 3, 0.0);
  std::fill_n(pu, 3, 0.0);
  std::fill_n(pv, 3, 0.0);
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      const double* cp = TeapotPoints[patch[4 * i + j]];
      for (int c = 0; c < 3; ++c)
      {
        p[c] += bv[i] * bu[j] * cp[c];
        pu[c] += bv[i] * dbu[j] * cp[c];
        pv[c] += dbv[i] * bu[j] * cp[c];
      }
    }
  }
}

// True when the patch's natural orientation (pu x pv) points out of the
// teapot. Samples n . (p - ref) over the patch, which for the surfaces of
// revolution approximates three times the signed volume of the cone from ref
// to the patch; ref is a point on the axis inside the pot. The handle and
// spout are tubes split lengthwise into halves whose rows are half circles:
// there ref is the midpoint of the row's ends, which lies on the tube axis.
bool IsPatchOutward(int patchIndex)
{
  const int* patch = TeapotPatches[patchIndex];
  const bool tube = patchIndex >= 12 && patchIndex < 20;
  const int samples = 8;
  double score = 0.0;
  for (int a = 1; a < samples; ++a)
  {
    for (int b = 1; b < samples; ++b)
    {
      const double u = static_cast<double>(a) / samples;
      const double v = static_cast<double>(b) / samples;
      double p[3], pu[3], pv[3];
      EvaluatePatch(patch, u, v, p, pu, pv);
      double ref[3] = { 0.0, 0.0, 1.2 };
      if (tube)
      {
        double p0[3], p1[3], d0[3], d1[3];
        EvaluatePatch(patch, 0.0, v, p0, d0, d1);
        EvaluatePatch(patch, 1.0, v, p1, d0, d1);
        for (int c = 0; c < 3; ++c)
        {
          ref[c] = 0.5 * (p0[c] + p1[c]);
        }
      }
      const double n[3] = { pu[1] * pv[2] - pu[2] * pv[1], pu[2] * pv[0] - pu[0] * pv[2],
        pu[0] * pv[1] - pu[1] * pv[0] };
      score += n[0] * (p[0] - ref[0]) + n[1] * (p[1] - ref[1]) + n[2] * (p[2] - ref[2]);
    }
  }
  return score > 0.0;
}
}

namespace
{
// Welds points closer than `tolerance` (the patch seams: one Bezier edge evaluated from both
// sides) in time linear in the points: each point looks for an earlier one in its grid cell of
// 4 * tolerance and the 26 cells around it, which on the sampled surface hold a point or two.
// (vtkStaticCleanPolyData's locator grid fills its buckets along a surface: 40 s at Resolution
// 256, growing faster than the points.) `map` gives each input point's welded id.
vtkSmartPointer<vtkPoints> Weld(vtkPoints* input, double tolerance, std::vector<vtkIdType>& map)
{
  const double cellSize = 4.0 * tolerance;
  const auto cellOf = [cellSize](
                        double x) { return static_cast<std::int64_t>(std::floor(x / cellSize)); };
  // 21 bits a coordinate: the points lie within [-1, 1], 2 / 4e-6 cells across.
  const auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    const std::int64_t mask = (1 << 21) - 1;
    return static_cast<std::uint64_t>(((i & mask) << 42) | ((j & mask) << 21) | (k & mask));
  };
  const vtkIdType n = input->GetNumberOfPoints();
  auto output = vtkSmartPointer<vtkPoints>::New();
  output->SetDataTypeToFloat();
  output->Allocate(n);
  std::unordered_map<std::uint64_t, vtkIdType> first; // a cell's first welded point
  first.reserve(static_cast<size_t>(n));
  std::vector<vtkIdType> next; // the cell's next one, -1 at the end
  std::vector<double> kept;    // welded coordinates, as computed
  next.reserve(static_cast<size_t>(n));
  kept.reserve(3 * static_cast<size_t>(n));
  map.resize(static_cast<size_t>(n));
  const double limit = tolerance * tolerance;
  for (vtkIdType id = 0; id < n; ++id)
  {
    double p[3];
    input->GetPoint(id, p);
    const std::int64_t c[3] = { cellOf(p[0]), cellOf(p[1]), cellOf(p[2]) };
    vtkIdType found = -1;
    for (int d = 0; d < 27 && found < 0; ++d)
    {
      const auto it = first.find(key(c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1));
      for (vtkIdType w = it == first.end() ? -1 : it->second; w >= 0 && found < 0; w = next[w])
      {
        const double* q = &kept[3 * static_cast<size_t>(w)];
        const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
        found = dx * dx + dy * dy + dz * dz <= limit ? w : -1;
      }
    }
    if (found < 0)
    {
      found = output->InsertNextPoint(p);
      kept.insert(kept.end(), p, p + 3);
      auto slot = first.emplace(key(c[0], c[1], c[2]), found);
      next.push_back(slot.second ? -1 : slot.first->second);
      slot.first->second = found;
    }
    map[static_cast<size_t>(id)] = found;
  }
  return output;
}
}

//------------------------------------------------------------------------------
vtkIceTeapotSource::vtkIceTeapotSource()
  : Resolution(15)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkIceTeapotSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int res = this->Resolution;
  const vtkIdType side = res + 1;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(32 * side * side);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(32 * 2 * res * res, 32 * 2 * res * res * 3);

  for (int patchIndex = 0; patchIndex < 32; ++patchIndex)
  {
    const vtkIdType base = patchIndex * side * side;
    for (int i = 0; i <= res; ++i)
    {
      for (int j = 0; j <= res; ++j)
      {
        double p[3], pu[3], pv[3];
        EvaluatePatch(TeapotPatches[patchIndex], static_cast<double>(j) / res,
          static_cast<double>(i) / res, p, pu, pv);
        points->SetPoint(base + i * side + j, p);
      }
    }

    // Copies of the classic data differ in how patches are wound; wind each
    // one outward regardless.
    const bool outward = IsPatchOutward(patchIndex);
    for (int i = 0; i < res; ++i)
    {
      for (int j = 0; j < res; ++j)
      {
        const vtkIdType a = base + i * side + j;
        const vtkIdType b = a + 1;
        const vtkIdType c = b + side;
        const vtkIdType d = a + side;
        const vtkIdType tri1[3] = { a, b, c };
        const vtkIdType tri2[3] = { a, c, d };
        const vtkIdType rev1[3] = { a, c, b };
        const vtkIdType rev2[3] = { a, d, c };
        polys->InsertNextCell(3, outward ? tri1 : rev1);
        polys->InsertNextCell(3, outward ? tri2 : rev2);
      }
    }
  }

  // z up -> y up (a proper rotation, so windings stay outward), then centre
  // the bounding box at the origin and scale its largest extent to 2.
  double bounds[6];
  points->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double scale = 2.0 / extent;
  for (vtkIdType id = 0; id < points->GetNumberOfPoints(); ++id)
  {
    double p[3];
    points->GetPoint(id, p);
    const double q[3] = { scale * (p[0] - center[0]), scale * (p[2] - center[2]),
      -scale * (p[1] - center[1]) };
    points->SetPoint(id, q);
  }

  // Weld the patch seams; triangles that collapse at the lid and bottom poles (two corners welded
  // into one) are dropped, not kept as slivers.
  std::vector<vtkIdType> map;
  vtkSmartPointer<vtkPoints> weldedPoints = Weld(points, 1e-6, map);
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateEstimate(polys->GetNumberOfCells(), 3);
  vtkIdType size;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    const vtkIdType t[3] = { map[ids[0]], map[ids[1]], map[ids[2]] };
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
    {
      triangles->InsertNextCell(3, t);
    }
  }
  vtkNew<vtkPolyData> welded;
  welded->SetPoints(weldedPoints);
  welded->SetPolys(triangles);
  output->ShallowCopy(vtkIceSmoothNormals(welded));
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceTeapotSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
}
