// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceTestImageWriter.h"

#include <OpenImageIO/imageio.h>

#include <iostream>

namespace IceTest
{
bool WriteImage(
  const char* path, int width, int height, int channels, bool asFloat, const void* pixels)
{
  const OIIO::TypeDesc type = asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  const bool ok = out && out->open(path, spec) && out->write_image(type, pixels) && out->close();
  if (!ok)
  {
    std::cerr << "cannot write " << path << ": " << (out ? out->geterror() : OIIO::geterror())
              << "\n";
  }
  return ok;
}
}
