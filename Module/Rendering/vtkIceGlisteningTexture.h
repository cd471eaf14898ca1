// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceGlisteningTexture
 * @brief   The random normal texture of glistening ice and snow: one random crack per texel.
 *
 * A square RGBA8 image of Size x Size texels. RGB holds a unit vector, uniformly distributed over
 * the sphere, encoded as 0.5 + 0.5 n (so 0..255 stands for -1..1); A holds a number uniform in
 * [0, 1]. The same Seed gives the same texels on every platform.
 *
 * vtkIceMapper uses it for its Glistening option: every cell of the crack grid fixed to the
 * surface reads one texel (texelFetch at an integer texel, never a filtered or mip-mapped
 * lookup), so a crack keeps its own normal at any distance. The uploaded texture is set to
 * nearest filtering, repeat wrapping and no mipmaps anyway, so no sampler state can blur it.
 */
#ifndef vtkIceGlisteningTexture_h
#define vtkIceGlisteningTexture_h

#include "RenderingIceModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class RENDERINGICE_EXPORT vtkIceGlisteningTexture : public vtkObject
{
public:
  static vtkIceGlisteningTexture* New();
  vtkTypeMacro(vtkIceGlisteningTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Texels per side, a power of two in [4, 1024] (other values are rounded down to one).
   * Default 256.
   */
  void SetSize(int size);
  vtkGetMacro(Size, int);
  ///@}

  ///@{
  /**
   * Seed of the random numbers. Default 1.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  /**
   * The texels as image data: Size x Size points, 4 unsigned char components.
   */
  vtkImageData* GetImage();

  /**
   * The texture in `window`'s context, created or refreshed when the image changed (nearest
   * filtering, repeat, no mipmaps). The caller activates and deactivates it.
   */
  vtkTextureObject* GetTextureObject(vtkOpenGLRenderWindow* window);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkIceGlisteningTexture();
  ~vtkIceGlisteningTexture() override;

  int Size = 256;
  int Seed = 1;
  vtkSmartPointer<vtkImageData> Image;
  vtkMTimeType ImageTime = 0;
  vtkSmartPointer<vtkTextureObject> TextureObject;
  vtkMTimeType TextureTime = 0;

private:
  vtkIceGlisteningTexture(const vtkIceGlisteningTexture&) = delete;
  void operator=(const vtkIceGlisteningTexture&) = delete;
};

#endif
