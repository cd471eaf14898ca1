// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceImageFile: the image files vtkIceEnvironmentReader reads, through OpenImageIO (here; VTK's
// readers in vtkIceImageFileVTK.cxx where there is none, VTKICE_IMAGE_READERS), behind an
// interface no C++ library type crosses (plain structs, char buffers). The `vtk` wheels use the
// old libstdc++ ABI and Debian's OpenImageIO the new one: vtkIceImageFile.cxx alone talks to
// OpenImageIO and is compiled with OpenImageIO's ABI, whatever VTK's is (Module/CMakeLists.txt).
#ifndef vtkIceImageFile_h
#define vtkIceImageFile_h

#include <cstddef>

namespace vtkIceImageFile
{
// OpenImageIO's message, on one line, after a failure.
struct Message
{
  char Text[512] = "";
};

struct Header
{
  int Width = 0;
  int Height = 0;
  int Depth = 0;
  int Channels = 0;
  bool EightBit = false; // stored as 8-bit unsigned channels
};

enum class Status
{
  Ok,
  CannotOpen, // the file cannot be opened as an image (message set)
  Changed,    // its size is no longer the one expected
  CannotRead  // the pixels cannot be read (message set)
};

// Opens `path` and reads its header.
Status ReadHeader(const char* path, Header& header, Message& message);

// Reads every pixel, rows top first, as floats or 8-bit values, into `pixels` (room for
// width * height * 3 values): the first three channels of a colour image, the first of a grey one
// (with or without alpha); `channels` says which (3 or 1). The file must still be width x height.
Status ReadPixels(const char* path, int width, int height, bool asFloat, void* pixels,
  int& channels, Message& message);

// Whether OpenImageIO reads files with this extension (without its dot, lower case).
bool ReadsExtension(const char* extension);
}

#endif
