// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Private to the module: connects an algorithm whose six image outputs are cube faces (OpenGL
// order +X, -X, +Y, -Y, +Z, -Z, row 0 first) to a vtkTexture as a cube map. Shared by
// vtkIceCubeMapSource and vtkIceEnvironmentReader so both set textures up the same way.
#ifndef vtkIceCubeMapTexture_h
#define vtkIceCubeMapTexture_h

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTexture.h"

namespace vtkIceCubeMapTexture
{
constexpr int NumberOfFaces = 6;

inline void Configure(vtkTexture* texture, vtkAlgorithm* faces)
{
  if (!texture || !faces)
  {
    return;
  }
  // CubeMapOn first: it gives the texture the six input ports connected below.
  texture->CubeMapOn();
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    texture->SetInputConnection(face, faces->GetOutputPort(face));
  }
  texture->InterpolateOn();
  texture->MipmapOff();
  texture->RepeatOff();
  texture->EdgeClampOn();
  // Upload the scalars as colours, whether 8-bit or float RGB; with the default colour mode
  // float scalars would go through a lookup table and lose HDR values above 1.
  texture->SetColorModeToDirectScalars();
}

// Pipeline information of the six face outputs: size x size RGB images of `scalarType`, spacing
// 1 and origin 0 (image filters such as vtkImageFlip need those). A size of 0 gives empty faces.
inline void SetFaceInformation(vtkInformationVector* outputVector, int size, int scalarType)
{
  const int extent[6] = { 0, size - 1, 0, size - 1, 0, 0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    vtkInformation* info = outputVector->GetInformationObject(face);
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    info->Set(vtkDataObject::SPACING(), spacing, 3);
    info->Set(vtkDataObject::ORIGIN(), origin, 3);
    vtkDataObject::SetPointDataActiveScalarInfo(info, scalarType, 3);
  }
}
// Whether `texture`'s images hold floats (an HDR environment, such as vtkIceEnvironmentReader
// gives for EXR or HDR files: linear light, values above 1). Brings its input up to date.
inline bool HoldsHighDynamicRange(vtkTexture* texture)
{
  if (!texture || texture->GetNumberOfInputConnections(0) == 0)
  {
    return false;
  }
  texture->GetInputAlgorithm(0, 0)->Update();
  vtkImageData* face = vtkImageData::SafeDownCast(texture->GetInputDataObject(0, 0));
  vtkDataArray* texels = face ? face->GetPointData()->GetScalars() : nullptr;
  return texels && (texels->GetDataType() == VTK_FLOAT || texels->GetDataType() == VTK_DOUBLE);
}
}

#endif
