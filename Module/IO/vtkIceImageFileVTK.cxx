// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceImageFile through VTK's own image readers (VTKICE_IMAGE_READERS=VTK): what a build with no
// OpenImageIO reads, such as the manylinux wheels (./ice.sh wheels). The `vtk` wheel carries
// these readers; it has none for OpenEXR, so EXR files are refused with a message naming them.
#include "vtkIceImageFile.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkHDRReader.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkJPEGReader.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTIFFReader.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace vtkIceImageFile
{
namespace
{
void Set(Message& message, const std::string& text)
{
  std::string line = text;
  line.erase(line.find_last_not_of(" \n") + 1);
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::strncpy(message.Text, line.empty() ? "unknown error" : line.c_str(), sizeof(message.Text) - 1);
  message.Text[sizeof(message.Text) - 1] = '\0';
}

std::string LowerExtension(const char* path)
{
  const std::string name = path;
  const std::string::size_type dot = name.find_last_of('.');
  const std::string::size_type slash = name.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  std::string extension = name.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

vtkSmartPointer<vtkImageReader2> ReaderFor(const std::string& extension)
{
  if (extension == "hdr" || extension == "pic")
  {
    return vtkSmartPointer<vtkHDRReader>::New();
  }
  if (extension == "png")
  {
    return vtkSmartPointer<vtkPNGReader>::New();
  }
  if (extension == "jpg" || extension == "jpeg")
  {
    return vtkSmartPointer<vtkJPEGReader>::New();
  }
  if (extension == "tif" || extension == "tiff")
  {
    return vtkSmartPointer<vtkTIFFReader>::New();
  }
  return nullptr;
}

// A reader of `path` with its header read, its errors kept in `message` rather than printed;
// null when there is none for the format or the file is not one.
struct OpenReader
{
  vtkSmartPointer<vtkImageReader2> Reader;
  vtkNew<vtkCallbackCommand> Errors;
  std::string Text;

  OpenReader(const char* path, Message& message)
  {
    const std::string extension = LowerExtension(path);
    this->Reader = ReaderFor(extension);
    if (!this->Reader)
    {
      std::string format = extension.empty() ? std::string("files without an extension")
                                             : "'." + extension + "' files";
      if (extension == "exr")
      {
        format = "OpenEXR ('.exr')";
      }
      Set(message,
        "this build of VTK Ice reads environment images with VTK's readers (Radiance HDR, PNG, "
        "JPEG, TIFF), none of which reads " +
          format);
      return;
    }
    this->Errors->SetClientData(this);
    this->Errors->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
      auto* open = static_cast<OpenReader*>(self);
      if (open->Text.empty() && text)
      {
        open->Text = static_cast<const char*>(text);
      }
    });
    this->Reader->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    if (!this->Reader->CanReadFile(path))
    {
      Set(message, "not a file VTK's " + std::string(this->Reader->GetDescriptiveName()) +
          " reader can read");
      this->Reader = nullptr;
      return;
    }
    this->Reader->SetFileName(path);
    this->Reader->UpdateInformation();
    if (!this->Text.empty())
    {
      Set(message, this->Text);
      this->Reader = nullptr;
    }
  }
};

// One channel of a pixel as a float of [0, 1] for integer formats, as OpenImageIO converts.
double Normalized(vtkDataArray* scalars, vtkIdType tuple, int component)
{
  const double value = scalars->GetComponent(tuple, component);
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      return value / 255.0;
    case VTK_UNSIGNED_SHORT:
      return value / 65535.0;
    default:
      return value;
  }
}
}

Status ReadHeader(const char* path, Header& header, Message& message)
{
  OpenReader open(path, message);
  if (!open.Reader)
  {
    return Status::CannotOpen;
  }
  int extent[6];
  open.Reader->GetDataExtent(extent);
  header.Width = extent[1] - extent[0] + 1;
  header.Height = extent[3] - extent[2] + 1;
  header.Depth = extent[5] - extent[4] + 1;
  header.Channels = open.Reader->GetNumberOfScalarComponents();
  header.EightBit = open.Reader->GetDataScalarType() == VTK_UNSIGNED_CHAR;
  return Status::Ok;
}

Status ReadPixels(const char* path, int width, int height, bool asFloat, void* pixels,
  int& channels, Message& message)
{
  OpenReader open(path, message);
  if (!open.Reader)
  {
    return Status::CannotOpen;
  }
  open.Reader->Update();
  vtkImageData* image = open.Reader->GetOutput();
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!open.Text.empty() || !scalars)
  {
    Set(message, open.Text.empty() ? std::string("no pixels") : open.Text);
    return Status::CannotRead;
  }
  int dimensions[3];
  image->GetDimensions(dimensions);
  if (dimensions[0] != width || dimensions[1] != height || dimensions[2] != 1)
  {
    return Status::Changed;
  }
  const int components = scalars->GetNumberOfComponents();
  channels = components >= 3 ? 3 : 1;
  // VTK's rows go bottom first; the interface's top first.
  for (int y = 0; y < height; ++y)
  {
    const vtkIdType row = static_cast<vtkIdType>(height - 1 - y) * width;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        const size_t out = (static_cast<size_t>(y) * width + x) * channels + c;
        const double value = Normalized(scalars, row + x, c);
        if (asFloat)
        {
          static_cast<float*>(pixels)[out] = static_cast<float>(value);
        }
        else
        {
          static_cast<unsigned char*>(pixels)[out] =
            static_cast<unsigned char>(std::min(255.0, std::max(0.0, value * 255.0 + 0.5)));
        }
      }
    }
  }
  return Status::Ok;
}

bool ReadsExtension(const char* extension)
{
  return ReaderFor(extension) != nullptr;
}
}
