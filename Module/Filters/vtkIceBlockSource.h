// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceBlockSource
 * @brief   Irregular, slightly melted ice cube made of triangles.
 *
 * vtkIceBlockSource builds a watertight cube surface from a Resolution x
 * Resolution grid of quads per face (each split into two triangles), rounds
 * its edges and corners toward a sphere by Roundness, and pushes every point
 * along the surface normal with smooth seeded 3D gradient noise (a few
 * octaves). Triangles face outward and smooth point normals are stored in the
 * "Normals" array. The block is centred at the origin; the same Seed always
 * gives the same output.
 */

#ifndef vtkIceBlockSource_h
#define vtkIceBlockSource_h

#include "FiltersIceModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FILTERSICE_EXPORT vtkIceBlockSource : public vtkPolyDataAlgorithm
{
public:
  static vtkIceBlockSource* New();
  vtkTypeMacro(vtkIceBlockSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of quads along each edge of a cube face. Default is 20, which
   * gives 6 x 20 x 20 x 2 = 4800 triangles; clamped to [1, 512].
   */
  vtkSetClampMacro(Resolution, int, 1, 512);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Seed of the displacement noise. Default is 1.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Amplitude of the noise displacement along the normal, relative to half
   * the edge length (the noise lies in about [-1, 1]). Default is 0.08.
   */
  vtkSetClampMacro(Displacement, double, 0.0, 1.0);
  vtkGetMacro(Displacement, double);
  ///@}

  ///@{
  /**
   * Edge length of the (undisplaced) cube. Default is 2, i.e. about [-1, 1]^3.
   */
  vtkSetClampMacro(Size, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Size, double);
  ///@}

  ///@{
  /**
   * How far edges and corners are rounded: the rounding radius as a fraction
   * of half the edge length. 0 is a sharp cube, 1 a sphere. Default is 0.3.
   */
  vtkSetClampMacro(Roundness, double, 0.0, 1.0);
  vtkGetMacro(Roundness, double);
  ///@}

protected:
  vtkIceBlockSource();
  ~vtkIceBlockSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution;
  int Seed;
  double Displacement;
  double Size;
  double Roundness;

private:
  vtkIceBlockSource(const vtkIceBlockSource&) = delete;
  void operator=(const vtkIceBlockSource&) = delete;
};

#endif
