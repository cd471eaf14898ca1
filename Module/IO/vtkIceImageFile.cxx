// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// OpenImageIO, and nothing of VTK: see vtkIceImageFile.h for why.
#include "vtkIceImageFile.h"

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>
#include <set>
#include <string>

namespace vtkIceImageFile
{
namespace
{
// OpenImageIO's messages may span lines; VTK errors read best on one.
void Set(Message& message, std::string text)
{
  text.erase(text.find_last_not_of(" \n") + 1);
  std::string::size_type newline;
  while ((newline = text.find('\n')) != std::string::npos)
  {
    text.replace(newline, 1, "; ");
  }
  if (text.empty())
  {
    text = "unknown error";
  }
  std::strncpy(message.Text, text.c_str(), sizeof(message.Text) - 1);
  message.Text[sizeof(message.Text) - 1] = '\0';
}

// OpenImageIO premultiplies colour by unassociated alpha (PNG, TIFF) by default; the reader
// drops alpha, so it asks for the colour as stored.
std::unique_ptr<OIIO::ImageInput> Open(const char* path, Message& message)
{
  OIIO::geterror(); // drop any stale message of this thread
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    Set(message, OIIO::geterror());
  }
  return input;
}
}

Status ReadHeader(const char* path, Header& header, Message& message)
{
  auto input = Open(path, message);
  if (!input)
  {
    return Status::CannotOpen;
  }
  const OIIO::ImageSpec& spec = input->spec();
  header.Width = spec.width;
  header.Height = spec.height;
  header.Depth = spec.depth;
  header.Channels = spec.nchannels;
  header.EightBit = spec.format.basetype == OIIO::TypeDesc::UINT8;
  input->close();
  return Status::Ok;
}

Status ReadPixels(const char* path, int width, int height, bool asFloat, void* pixels,
  int& channels, Message& message)
{
  auto input = Open(path, message);
  if (!input)
  {
    return Status::CannotOpen;
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != width || spec.height != height || spec.depth != 1)
  {
    return Status::Changed;
  }
  channels = spec.nchannels >= 3 ? 3 : 1;
  const OIIO::TypeDesc type = asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  if (!input->read_image(0, 0, 0, channels, type, pixels))
  {
    Set(message, input->geterror());
    return Status::CannotRead;
  }
  input->close();
  return Status::Ok;
}

bool ReadsExtension(const char* extension)
{
  static const std::set<std::string> known = [] {
    std::set<std::string> extensions;
    for (const auto& format : OIIO::get_extension_map())
    {
      extensions.insert(format.second.begin(), format.second.end());
    }
    return extensions;
  }();
  return known.count(extension) > 0;
}
}
