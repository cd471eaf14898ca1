// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVIceMapper
 * @brief   vtkIceMapper that refracts the view's background where the view has no environment.
 *
 * The Ice representation's mapper. Where the renderer has no environment texture (any
 * background but a skybox) the ice samples BackgroundEnvironment (the view's background as a
 * cube map, vtkPVIceBackgroundEnvironment) instead of vtkIceMapper's built-in sky. It is the
 * renderer's environment only while this mapper draws, so nothing else in the view (image-based
 * lighting, dynamic cube maps) sees it.
 */
#ifndef vtkPVIceMapper_h
#define vtkPVIceMapper_h

#include "IceViewsModule.h" // for export macro
#include "vtkIceMapper.h"
#include "vtkSmartPointer.h" // for members

class vtkTexture;

class ICEVIEWS_EXPORT vtkPVIceMapper : public vtkIceMapper
{
public:
  static vtkPVIceMapper* New();
  vtkTypeMacro(vtkPVIceMapper, vtkIceMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The cube map sampled where the renderer has no environment texture (null: the built-in sky).
   */
  void SetBackgroundEnvironment(vtkTexture* texture);
  vtkTexture* GetBackgroundEnvironment();
  ///@}

protected:
  vtkPVIceMapper();
  ~vtkPVIceMapper() override;

  void BindEnvironment(vtkRenderer* ren, vtkActor* act) override;

private:
  vtkPVIceMapper(const vtkPVIceMapper&) = delete;
  void operator=(const vtkPVIceMapper&) = delete;

  vtkSmartPointer<vtkTexture> BackgroundEnvironment;
};

#endif
