// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: vtkIceWorldSpaceMapper::CheckInput on arbitrary polydata, and what the mapper
// does with input it accepts (the smooth normals of vtkIceSmoothNormals). The bytes give the
// points (any float, NaN and infinities included), the cells of each kind (any point id, any
// size) and point arrays of any length; accepted input must go through the normals filter
// without a fault (CheckInput promises that to applications that call it before any filter).
#include "vtkIceSmoothNormals.h"
#include "vtkIceWorldSpaceMapper.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstring>

namespace
{
// Reads the bytes in order; zeros once they run out.
struct Bytes
{
  const uint8_t* Data;
  size_t Size;
  size_t At = 0;
  uint8_t Byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  float Float()
  {
    uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
    {
      bits = (bits << 8) | this->Byte();
    }
    float value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }
  bool Empty() const { return this->At >= this->Size; }
};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Bytes bytes{ data, size };
  vtkNew<vtkPolyData> input;
  vtkNew<vtkPoints> points;
  const int pointCount = bytes.Byte() % 33;
  // Small coordinates most of the time (a usable mesh), raw floats otherwise.
  const bool raw = bytes.Byte() % 4 == 0;
  for (int i = 0; i < pointCount; ++i)
  {
    double p[3];
    for (double& c : p)
    {
      c = raw ? bytes.Float() : (bytes.Byte() % 16) / 4.0;
    }
    points->InsertNextPoint(p);
  }
  input->SetPoints(points);

  vtkNew<vtkCellArray> cells[4];
  const int cellCount = bytes.Byte() % 17;
  for (int c = 0; c < cellCount && !bytes.Empty(); ++c)
  {
    const int kind = bytes.Byte() % 4;
    const int n = bytes.Byte() % 6;
    cells[kind]->InsertNextCell(n);
    for (int i = 0; i < n; ++i)
    {
      // Mostly valid ids, sometimes any (negative, past the end).
      const uint8_t b = bytes.Byte();
      cells[kind]->InsertCellPoint(b < 224 ? b % (pointCount + 1) : static_cast<int8_t>(b) * 7);
    }
  }
  input->SetVerts(cells[0]);
  input->SetLines(cells[1]);
  input->SetPolys(cells[2]);
  input->SetStrips(cells[3]);

  // Point arrays: normals, texture coordinates, scalars, of any length.
  const int arrays = bytes.Byte() % 4;
  for (int a = 0; a < arrays; ++a)
  {
    vtkNew<vtkFloatArray> array;
    const int components = 1 + bytes.Byte() % 3;
    array->SetNumberOfComponents(components);
    const int tuples = bytes.Byte() % (pointCount + 3);
    for (int t = 0; t < tuples * components; ++t)
    {
      array->InsertNextValue(bytes.Float());
    }
    if (a == 0 && components == 3)
    {
      input->GetPointData()->SetNormals(array);
    }
    else if (a == 1 && components == 2)
    {
      input->GetPointData()->SetTCoords(array);
    }
    else
    {
      array->SetName(a == 0 ? "first" : a == 1 ? "second" : "third");
      input->GetPointData()->AddArray(array);
    }
  }

  if (vtkIceWorldSpaceMapper::CheckInput(input).empty())
  {
    vtkIceSmoothNormals(input);
  }
  return 0;
}
