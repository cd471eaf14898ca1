// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCubeMapSource
 * @brief   Procedural environment cube maps: a sky with landscape, or a smooth test pattern.
 *
 * The source has six image outputs, the cube faces in OpenGL order +X, -X, +Y, -Y, +Z, -Z, laid
 * out the way vtkTexture uploads them for a cube map (row 0 first, unflipped). Connect them with
 * ConfigureTexture(). +Y is up.
 *
 * Patterns:
 * - Sky: a blue sky with a sun, a ring of mountains and a checkered ground plane (RGB).
 * - DirectionTest: a smooth colour that differs on every face, for pixel tests; Evaluate()
 *   gives the exact colour of any direction so renders can be compared with a CPU reference.
 */
#ifndef vtkIceCubeMapSource_h
#define vtkIceCubeMapSource_h

#include "RenderingIceModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class vtkTexture;

class RENDERINGICE_EXPORT vtkIceCubeMapSource : public vtkImageAlgorithm
{
public:
  static vtkIceCubeMapSource* New();
  vtkTypeMacro(vtkIceCubeMapSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Patterns
  {
    Sky = 0,
    DirectionTest = 1
  };

  ///@{
  /**
   * Pattern drawn on the cube. Default Sky.
   */
  vtkSetClampMacro(Pattern, int, Sky, DirectionTest);
  vtkGetMacro(Pattern, int);
  void SetPatternToSky() { this->SetPattern(Sky); }
  void SetPatternToDirectionTest() { this->SetPattern(DirectionTest); }
  ///@}

  ///@{
  /**
   * Width and height of each face in pixels. Default 256.
   */
  vtkSetClampMacro(FaceSize, int, 1, 8192);
  vtkGetMacro(FaceSize, int);
  ///@}

  /**
   * Colour (components in [0, 1]) of the world direction `dir` (need not be normalised) for
   * the current pattern. The faces are this function sampled at texel centres.
   */
  void Evaluate(const double dir[3], double rgb[3]) const;

  /**
   * The world direction through the centre of texel (i, j) of `face` (0..5, +X -X +Y -Y +Z -Z):
   * the OpenGL cube map convention's direction as VTK's skybox and environment lookups show it,
   * which is that direction in VTK 9.1 and the direction with z negated since VTK 9.2.
   */
  static void TexelDirection(int face, int i, int j, int size, double dir[3]);

  /**
   * Makes `texture` a linearly interpolated cube map fed by the six outputs of this source.
   */
  void ConfigureTexture(vtkTexture* texture);

protected:
  vtkIceCubeMapSource();
  ~vtkIceCubeMapSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Pattern;
  int FaceSize;

private:
  vtkIceCubeMapSource(const vtkIceCubeMapSource&) = delete;
  void operator=(const vtkIceCubeMapSource&) = delete;
};

#endif
