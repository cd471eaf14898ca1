// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceEnvironmentReader
 * @brief   Reads an environment cube map from image files (OpenImageIO).
 *
 * The reader has six image outputs, the cube faces in OpenGL order +X, -X, +Y, -Y, +Z, -Z, laid
 * out like those of vtkIceCubeMapSource: row j, column i of face f is the texel whose direction
 * is vtkIceCubeMapSource::TexelDirection(f, i, j, size, dir), which is how vtkTexture uploads
 * cube faces (row 0 first, unflipped) and how vtkSkybox and vtkIceMapper look them up. +Y is up.
 * ConfigureTexture() wires the outputs to a vtkTexture.
 *
 * FileName is one of:
 * - A folder holding six face images named px, nx, py, ny, pz, nz (for +X, -X, +Y, -Y, +Z, -Z)
 *   with any extension OpenImageIO reads (png, jpg, exr, hdr, tif, ...), exactly one per face;
 *   other files are ignored. All six square and of one size. Each face is the OpenGL cube face
 *   seen from inside the cube, in the usual image convention: the top row of the file is the
 *   face's t = 0 row, the left column its s = 0.
 * - A single image whose aspect ratio selects the layout:
 *   - 4:3, a horizontal cross of four by three faces:
 *     @verbatim
 *       .  +Y  .   .
 *      -X  +Z  +X  -Z
 *       .  -Y  .   .
 *     @endverbatim
 *     each face as in a folder (top row of the file first); the seams are continuous.
 *   - 3:4, a vertical cross of three by four faces: +Y / -X +Z +X / -Y / -Z, as the horizontal
 *     cross but with -Z below -Y, rotated by 180 degrees so that its seam with -Y is continuous.
 *   - 2:1, an equirectangular (latitude-longitude) panorama. +Y is up: the top row looks
 *     straight up, the bottom row straight down. The centre column looks toward -Z (where VTK's
 *     default camera looks) and longitude increases to the right: a quarter of the width right
 *     of the centre looks toward +X, the left and right edges toward +Z. As seen from inside, the
 *     panorama is not mirrored. A direction (x, y, z) is at u = 0.5 + atan2(x, -z) / (2 pi) and
 *     v = 0.5 - asin(y) / pi (u to the right, v down, both in [0, 1] over the whole image). The
 *     faces (FaceSize, default width / 4) are sampled bilinearly, wrapping around horizontally.
 *   Any other aspect ratio is an error.
 *
 * Output scalars are RGB: unsigned char when every source image has 8 bits per channel, float
 * otherwise (16-bit, half or float images such as EXR and HDR), in which case values above 1 are
 * kept. Alpha channels are dropped; grey images are expanded to RGB.
 *
 * Limits, checked on the headers before any pixel is read: at most 2^28 pixels per image (16384 x
 * 16384) and faces of at most 8192 x 8192; FileName must be a folder or a regular file (not a
 * device or a pipe, which would be read for ever).
 *
 * Bad input (no such file or folder, a missing face file, an unreadable or corrupt image, faces
 * that are not square or not of one size, a single image of another aspect ratio, an image over
 * the limits, not enough memory for the pixels) gives one VTK
 * error naming the file and the problem, sets ErrorCode, and leaves all six outputs empty (no
 * points). A vtkTexture fed by empty outputs reports that it has no scalars and draws nothing.
 *
 * @sa vtkIceCubeMapSource vtkTexture vtkSkybox
 */
#ifndef vtkIceEnvironmentReader_h
#define vtkIceEnvironmentReader_h

#include "IOIceModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class vtkTexture;

class IOICE_EXPORT vtkIceEnvironmentReader : public vtkImageAlgorithm
{
public:
  static vtkIceEnvironmentReader* New();
  vtkTypeMacro(vtkIceEnvironmentReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * A folder with the six face images, or a single cross or panorama image.
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * Width and height of the faces made from an equirectangular panorama; 0 (the default) uses a
   * quarter of the panorama's width. Faces read from a folder or a cross keep their own size.
   * Clamped to [0, 8192].
   */
  vtkSetClampMacro(FaceSize, int, 0, 8192);
  vtkGetMacro(FaceSize, int);
  ///@}

  enum Layouts
  {
    Unknown = 0,
    Faces = 1,
    HorizontalCross = 2,
    VerticalCross = 3,
    Equirectangular = 4
  };

  ///@{
  /**
   * The layout found by the last update: Faces, HorizontalCross, VerticalCross or
   * Equirectangular; Unknown before the first update and after an error.
   */
  vtkGetMacro(Layout, int);
  const char* GetLayoutAsString() const;
  static const char* GetLayoutAsString(int layout);
  ///@}

  /**
   * Makes `texture` a linearly interpolated cube map fed by the six outputs of this reader, set
   * up like vtkIceCubeMapSource::ConfigureTexture (colours uploaded directly, 8-bit or float).
   */
  void ConfigureTexture(vtkTexture* texture);

protected:
  vtkIceEnvironmentReader();
  ~vtkIceEnvironmentReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  int FaceSize;
  int Layout;

private:
  vtkIceEnvironmentReader(const vtkIceEnvironmentReader&) = delete;
  void operator=(const vtkIceEnvironmentReader&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
