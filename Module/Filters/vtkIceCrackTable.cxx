// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCrackTable.h"

#include "vtkIceCrackGeometry.h"
#include "vtkIceCrackSource.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkIceCrackTable);

namespace
{
// A record's frame applied to the ray: its origin and direction in the crack's frame.
void ToCrack(const float* record, const double o[3], const double d[3], double p[3], double v[3])
{
  for (int row = 0; row < 3; ++row)
  {
    const float* m = record + 4 * row;
    p[row] = m[0] * o[0] + m[1] * o[1] + m[2] * o[2] + m[3];
    v[row] = m[0] * d[0] + m[1] * d[1] + m[2] * d[2];
  }
}
}

//------------------------------------------------------------------------------
void vtkIceCrackTable::Build(int seed, int count, const double bounds[6])
{
  // The three models' outlines and curvatures, as vtkIceCrackGeometry picks them.
  this->Outlines.assign(3 * OutlineSamples, 0.0f);
  vtkIceCrackSource::Shape shapes[3];
  double largest[3];
  for (int m = 0; m < 3; ++m)
  {
    shapes[m] = vtkIceCrackSource::GetShape(vtkIceCrackGeometry::ModelSeed(seed, m));
    for (int a = 0; a < OutlineSamples; ++a)
    {
      this->Outlines[m * OutlineSamples + a] =
        static_cast<float>(shapes[m].OutlineRadius(2.0 * vtkMath::Pi() * a / OutlineSamples));
    }
    const float* outline = &this->Outlines[static_cast<size_t>(m) * OutlineSamples];
    largest[m] = *std::max_element(outline, outline + OutlineSamples);
  }
  this->Records.assign(RecordSize * static_cast<size_t>(std::max(count, 0)), 0.0f);
  this->Sheets.clear();
  for (int i = 0; i < count; ++i)
  {
    vtkNew<vtkTransform> where;
    vtkIceCrackGeometry::Placement(seed, i, bounds, where);
    vtkNew<vtkMatrix4x4> toCrack;
    vtkMatrix4x4::Invert(where->GetMatrix(), toCrack);
    float* record = &this->Records[RecordSize * static_cast<size_t>(i)];
    for (int row = 0; row < 3; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        record[4 * row + column] = static_cast<float>(toCrack->GetElement(row, column));
      }
    }
    const vtkIceCrackSource::Shape& shape = shapes[i % 3];
    record[12] = static_cast<float>(shape.Bowl + shape.Saddle);
    record[13] = static_cast<float>(shape.Bowl - shape.Saddle);
    record[14] = static_cast<float>(i % 3);
    vtkIceCrackGrid::Sheet sheet;
    std::copy(record, record + 12, sheet.ModelToSheet);
    sheet.Bowl[0] = record[12];
    sheet.Bowl[1] = record[13];
    sheet.Radius = largest[i % 3];
    this->Sheets.push_back(sheet);
  }
}

//------------------------------------------------------------------------------
bool vtkIceCrackTable::Nearest(
  const double o[3], const double d[3], double sEnd, double& s, int& record, double& edge) const
{
  s = sEnd;
  record = -1;
  edge = 0.0;
  for (int i = 0; i < this->GetNumberOfCracks(); ++i)
  {
    const float* r = &this->Records[RecordSize * static_cast<size_t>(i)];
    double p[3];
    double v[3];
    ToCrack(r, o, d, p, v);
    const double a = r[12];
    const double b = r[13];
    const double qa = -(a * v[0] * v[0] + b * v[1] * v[1]);
    const double qb = v[2] - 2.0 * (a * p[0] * v[0] + b * p[1] * v[1]);
    const double qc = p[2] - a * p[0] * p[0] - b * p[1] * p[1];
    const double discriminant = qb * qb - 4.0 * qa * qc;
    const double q = -0.5 * (qb + (qb < 0.0 ? -1.0 : 1.0) * std::sqrt(std::max(discriminant, 0.0)));
    const bool quadratic = std::abs(qa) > 1.0e-6 * std::abs(qb);
    const double s0 = quadratic ? q / qa : -qc / qb;
    const double s1 = quadratic ? qc / q : -1.0;
    const bool in0 = s0 > 0.0 && s0 < sEnd;
    const bool in1 = s1 > 0.0 && s1 < sEnd;
    const double along = in0 && (!in1 || s0 < s1) ? s0 : s1;
    if (discriminant < 0.0 || !(in0 || in1) || along >= s)
    {
      continue;
    }
    const double x = p[0] + along * v[0];
    const double y = p[1] + along * v[1];
    // The outline linear between its samples, as the shader's.
    const double turns = std::atan2(y, x) / (2.0 * vtkMath::Pi());
    const double u = (turns - std::floor(turns)) * OutlineSamples;
    const int k = static_cast<int>(u) % OutlineSamples;
    const float* outline = &this->Outlines[static_cast<size_t>(r[14]) * OutlineSamples];
    const double f = u - std::floor(u);
    const double radius = outline[k] * (1.0 - f) + outline[(k + 1) % OutlineSamples] * f;
    const double distance = std::hypot(x, y);
    if (distance > radius)
    {
      continue;
    }
    s = along;
    record = i;
    edge = distance / std::max(radius, 1.0e-6);
  }
  return record >= 0;
}

//------------------------------------------------------------------------------
void vtkIceCrackTable::Normal(
  int record, const double o[3], const double d[3], double s, double n[3]) const
{
  const float* r = &this->Records[RecordSize * static_cast<size_t>(record)];
  double p[3];
  double v[3];
  ToCrack(r, o, d, p, v);
  const double g[3] = { -2.0 * r[12] * (p[0] + s * v[0]), -2.0 * r[13] * (p[1] + s * v[1]), 1.0 };
  for (int c = 0; c < 3; ++c)
  {
    n[c] = g[0] * r[c] + g[1] * r[4 + c] + g[2] * r[8 + c];
  }
}

//------------------------------------------------------------------------------
void vtkIceCrackTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCracks: " << this->GetNumberOfCracks() << "\n";
}
