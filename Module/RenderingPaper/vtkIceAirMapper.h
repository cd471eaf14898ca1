// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceAirMapper
 * @brief   Draws the air-bubble planes inside ice, clipped to its depth interval (private to
 *          the module).
 *
 * Used by vtkIceOpenGLPaperInterior for the air of an ice mapper (the milky look of ice). The input
 * is a set of planes with texture coordinates in the point array "vtkIceAirUV"; the fragment shader
 * samples the bubble atlas (AirTexture, e.g. from vtkIceAirTextureSource), whitens and thickens it
 * by Milkiness, discards fragments outside the ice's [front, back] depth interval
 * (iceDepthInterval, handed over by vtkIcePass) and is tested against the scene at the ice's front
 * depth. Drawn with alpha blending, planes sorted back to front. DebugColor draws solid green where
 * a bubble covers.
 */
#ifndef vtkIceAirMapper_h
#define vtkIceAirMapper_h

#include "vtkIceWorldSpaceMapper.h"

class vtkTexture;

class vtkIceAirMapper : public vtkIceWorldSpaceMapper
{
public:
  static vtkIceAirMapper* New();
  vtkTypeMacro(vtkIceAirMapper, vtkIceWorldSpaceMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The bubble images, sampled with the "vtkIceAirUV" coordinates.
   */
  void SetAirTexture(vtkTexture* texture);
  vtkTexture* GetAirTexture();
  ///@}

  ///@{
  /**
   * 0: sparse, clear bubbles; 1: white and cloudy. Default 0.5.
   */
  vtkSetClampMacro(Milkiness, double, 0.0, 1.0);
  vtkGetMacro(Milkiness, double);
  ///@}

  ///@{
  /**
   * Solid green where a bubble covers, for tests. Default off.
   */
  vtkSetMacro(DebugColor, bool);
  vtkGetMacro(DebugColor, bool);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkIceAirMapper();
  ~vtkIceAirMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act) override;
  void SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act) override;

  vtkSmartPointer<vtkTexture> AirTexture;
  double Milkiness = 0.5;
  bool DebugColor = false;

private:
  vtkIceAirMapper(const vtkIceAirMapper&) = delete;
  void operator=(const vtkIceAirMapper&) = delete;
};

#endif
