// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceCrackMapper
 * @brief   Draws crack surfaces inside ice (private to the module): a bump-mapped specular
 *          highlight, nothing else.
 *
 * Used by vtkIceOpenGLPaperInterior for the cracks of an ice mapper (paper section 3.3). The
 * fragment shader tilts the normal by a noise field fixed to the crack (bump mapping), keeps only
 * the specular term of VTK's lighting, and, with ClipToInterval on, discards fragments whose view
 * depth is outside the ice's [front, back] depth interval, the sampler iceDepthInterval that
 * vtkIcePass hands to the shaders of the ice and its cracks. Fragments are tested against the scene
 * at the ice's front depth, so what hides the ice hides its cracks. DebugColor draws solid red
 * instead of the highlight.
 */
#ifndef vtkIceCrackMapper_h
#define vtkIceCrackMapper_h

#include "vtkIceInteriorLook.h" // for CrackBumpStrength
#include "vtkIceWorldSpaceMapper.h"

class vtkIceCrackMapper : public vtkIceWorldSpaceMapper
{
public:
  static vtkIceCrackMapper* New();
  vtkTypeMacro(vtkIceCrackMapper, vtkIceWorldSpaceMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Discard fragments outside the depth interval. Default on.
   */
  vtkSetMacro(ClipToInterval, bool);
  vtkGetMacro(ClipToInterval, bool);
  ///@}

  ///@{
  /**
   * Solid red instead of the highlight. Default off.
   */
  vtkSetMacro(DebugColor, bool);
  vtkGetMacro(DebugColor, bool);
  ///@}

  ///@{
  /**
   * Highlight brightness. Default 1.
   */
  vtkSetClampMacro(Intensity, double, 0.0, 100.0);
  vtkGetMacro(Intensity, double);
  ///@}

  ///@{
  /**
   * Bump mapping: how far normals tilt (0 = flat) and the noise frequency in model units.
   */
  vtkSetClampMacro(BumpStrength, double, 0.0, 10.0);
  vtkGetMacro(BumpStrength, double);
  vtkSetClampMacro(BumpFrequency, double, 0.0, 1.0e6);
  vtkGetMacro(BumpFrequency, double);
  ///@}

protected:
  vtkIceCrackMapper();
  ~vtkIceCrackMapper() override;

  void AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act) override;
  void SetIceShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act) override;

  bool ClipToInterval = true;
  bool DebugColor = false;
  double Intensity = 1.0;
  double BumpStrength = vtkIceInteriorLook::CrackBumpStrength;
  double BumpFrequency = 4.0;

private:
  vtkIceCrackMapper(const vtkIceCrackMapper&) = delete;
  void operator=(const vtkIceCrackMapper&) = delete;
};

#endif
