// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCrackTable
 * @brief   The crack sheets inside an ice surface as the shaders read them, and the nearest crack
 *          along a ray on the CPU (for the project's modules: not installed).
 *
 * Build() places the cracks of a seed as vtkIceCrackGeometry does and keeps each as a record of
 * 16 floats: the three rows of its model-to-crack transform, then a and b of its sheet
 * z = a x^2 + b y^2 and its model (0-2); and the three models' outlines, OutlineSamples radii over
 * the full turn. vtkIceInteriorTable uploads them (with the grid of vtkIceCrackGrid) for
 * glsl/vtkIceCracksFS.glsl. Nearest() and Normal() are that file's iceNearestCrack and
 * iceCrackNormal on the CPU, testing every sheet: the shaders' reference.
 */
#ifndef vtkIceCrackTable_h
#define vtkIceCrackTable_h

#include "FiltersIceModule.h" // For export macro
#include "vtkIceCrackGrid.h"  // For the sheets
#include "vtkObject.h"

#include <vector> // For the records

class FILTERSICE_EXPORT vtkIceCrackTable : public vtkObject
{
public:
  static vtkIceCrackTable* New();
  vtkTypeMacro(vtkIceCrackTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr int OutlineSamples = 64; // as iceOutlineSamples
  static constexpr int RecordSize = 16;     // floats

  // `count` cracks of `seed` placed in ice of `bounds` (model coordinates).
  void Build(int seed, int count, const double bounds[6]);

  int GetNumberOfCracks() const { return static_cast<int>(this->Records.size() / RecordSize); }
  const std::vector<float>& GetRecords() const { return this->Records; }
  const std::vector<float>& GetOutlines() const { return this->Outlines; }
  // Each sheet's frame, curvatures and largest radius, for vtkIceCrackGrid.
  const std::vector<vtkIceCrackGrid::Sheet>& GetSheets() const { return this->Sheets; }

  /**
   * The nearest crack the ray o + s d (model coordinates) crosses inside its outline with
   * 0 < s < sEnd: true with s, its record and `edge` (its distance from the crack's centre over
   * the outline's).
   */
  bool Nearest(const double o[3], const double d[3], double sEnd, double& s, int& record,
    double& edge) const;
  // The crack's normal where the ray meets it at s, in model coordinates as a normal, unnormalised.
  void Normal(int record, const double o[3], const double d[3], double s, double n[3]) const;

protected:
  vtkIceCrackTable() = default;
  ~vtkIceCrackTable() override = default;

private:
  std::vector<float> Records;
  std::vector<float> Outlines;
  std::vector<vtkIceCrackGrid::Sheet> Sheets;

  vtkIceCrackTable(const vtkIceCrackTable&) = delete;
  void operator=(const vtkIceCrackTable&) = delete;
};

#endif
