// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCrackSource
 * @brief   A generic crack surface: an irregular, curved, bumpy open sheet.
 *
 * Natural ice shows specular highlights on internal crack surfaces. The paper places a few generic
 * crack models at random inside any ice object. This source makes one such model: a sheet in the
 * XY plane of radius about 1 with a ragged outline (radius varying with the angle), bent into a
 * shallow bowl and saddle, and roughened by noise, with smooth point normals. Seed picks the
 * model; the same seed gives the same sheet.
 */
#ifndef vtkIceCrackSource_h
#define vtkIceCrackSource_h

#include "FiltersIceModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class FILTERSICE_EXPORT vtkIceCrackSource : public vtkPolyDataAlgorithm
{
public:
  static vtkIceCrackSource* New();
  vtkTypeMacro(vtkIceCrackSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Which crack model. Default 1.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Rings and sectors of the sheet's polar grid. Default 12 rings, 48 sectors (1 104 triangles).
   */
  vtkSetClampMacro(Rings, int, 2, 256);
  vtkGetMacro(Rings, int);
  vtkSetClampMacro(Sectors, int, 6, 1024);
  vtkGetMacro(Sectors, int);
  ///@}

  /**
   * The shape of model `seed` (the screen-space interior intersects it analytically): the sheet
   * is z = Bowl (x^2 + y^2) + Saddle (x^2 - y^2), plus Roughness times noise, inside the outline
   * radius OutlineRadius(angle).
   */
  struct Shape
  {
    double Bowl;
    double Saddle;
    double Roughness;
    double Ragged;
    int Seed;
    double OutlineRadius(double angle) const;
  };
  static Shape GetShape(int seed);

protected:
  vtkIceCrackSource();
  ~vtkIceCrackSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Seed = 1;
  int Rings = 12;
  int Sectors = 48;

private:
  vtkIceCrackSource(const vtkIceCrackSource&) = delete;
  void operator=(const vtkIceCrackSource&) = delete;
};

#endif
