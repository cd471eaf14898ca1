// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Writes test images with OpenImageIO, behind an interface without C++ library types: the tests
// built against a `vtk` wheel use its old libstdc++ ABI, OpenImageIO the new one (as
// Module/IO/vtkIceImageFile.h does for reading).
#ifndef IceTestImageWriter_h
#define IceTestImageWriter_h

namespace IceTest
{
// `channels` values per pixel, rows top first, floats or 8-bit; colour as given (not divided by
// alpha). False, with a line on std::cerr, when the file cannot be written.
bool WriteImage(
  const char* path, int width, int height, int channels, bool asFloat, const void* pixels);
}

#endif
