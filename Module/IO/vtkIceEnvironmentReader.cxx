// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceEnvironmentReader.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceCubeMapTexture.h"
#include "vtkIceImageFile.h"

#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkIceEnvironmentReader);

namespace
{
constexpr int NumberOfFaces = vtkIceCubeMapTexture::NumberOfFaces;
const char* const FaceNames[NumberOfFaces] = { "px", "nx", "py", "ny", "pz", "nz" };

// Where each face (OpenGL order) sits in a cross, in units of the face size; a rotated face is
// stored turned by 180 degrees.
struct Cell
{
  int Column;
  int Row;
  bool Rotated;
};
const Cell HorizontalCrossCells[NumberOfFaces] = { { 2, 1, false }, { 0, 1, false },
  { 1, 0, false }, { 1, 2, false }, { 1, 1, false }, { 3, 1, false } };
const Cell VerticalCrossCells[NumberOfFaces] = { { 2, 1, false }, { 0, 1, false }, { 1, 0, false },
  { 1, 2, false }, { 1, 1, false }, { 1, 3, true } };

std::string Size(int width, int height)
{
  return std::to_string(width) + "x" + std::to_string(height);
}

// Limits on what a header may ask for, checked before any pixel is allocated: a hostile or broken
// header otherwise makes the reader allocate gigabytes (and abort). 2^28 pixels is 16384x16384,
// twice the largest common HDR panoramas (16384x8192); faces as large as vtkIceCubeMapSource's.
constexpr long long MaximumPixels = 1LL << 28;
constexpr int MaximumFaceSize = 8192;

struct Failure
{
  std::string Message;
  unsigned long Code = vtkErrorCode::UnknownError;
};

// What the file headers say: the layout, the files, the face size and the scalar type.
struct Plan
{
  bool Valid = false;
  int Layout = vtkIceEnvironmentReader::Unknown;
  std::vector<std::string> Files; // six faces in OpenGL order, or one image
  int Width = 0;                  // of every file
  int Height = 0;
  int FaceSize = 0; // of the outputs
  bool Float = false;
};

// Opens `path` and reads its header; false and `failure` set if OpenImageIO cannot.
bool ReadHeader(const std::string& path, vtkIceImageFile::Header& spec, Failure& failure)
{
  vtkIceImageFile::Message message;
  if (vtkIceImageFile::ReadHeader(path.c_str(), spec, message) != vtkIceImageFile::Status::Ok)
  {
    failure = { "Cannot read environment image '" + path + "': " + message.Text,
      vtkErrorCode::CannotOpenFileError };
    return false;
  }
  if (spec.Width <= 0 || spec.Height <= 0 || spec.Depth != 1 || spec.Channels <= 0)
  {
    failure = { "Environment image '" + path + "' is not a 2D image with pixels",
      vtkErrorCode::FileFormatError };
    return false;
  }
  if (static_cast<long long>(spec.Width) * spec.Height > MaximumPixels)
  {
    failure = { "Environment image '" + path + "' is " + Size(spec.Width, spec.Height) +
        ", more than the " + std::to_string(MaximumPixels) + " pixels the reader accepts",
      vtkErrorCode::FileFormatError };
    return false;
  }
  return true;
}

// Whether OpenImageIO has a reader for files with extension `ext` (with its dot, any case).
bool IsImageExtension(std::string ext)
{
  if (ext.size() < 2 || ext[0] != '.')
  {
    return false;
  }
  ext.erase(0, 1);
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return vtkIceImageFile::ReadsExtension(ext.c_str());
}

// The six face files of a folder: px, nx, ... with an extension OpenImageIO reads, one per face.
bool FindFaces(const std::string& folder, std::vector<std::string>& files, Failure& failure)
{
  std::vector<std::vector<std::string>> found(NumberOfFaces);
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
  {
    std::error_code typeError;
    if (!it->is_regular_file(typeError))
    {
      continue;
    }
    const std::string stem = it->path().stem().string();
    for (int face = 0; face < NumberOfFaces; ++face)
    {
      if (stem == FaceNames[face] && IsImageExtension(it->path().extension().string()))
      {
        found[face].push_back(it->path().string());
      }
    }
  }
  if (ec)
  {
    failure = { "Cannot list the environment folder '" + folder + "': " + ec.message(),
      vtkErrorCode::CannotOpenFileError };
    return false;
  }
  files.clear();
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    if (found[face].empty())
    {
      failure = { "Environment folder '" + folder + "' has no face image '" + FaceNames[face] +
          ".*' (expected px, nx, py, ny, pz and nz, each with an extension OpenImageIO reads, "
          "such as .png, .jpg, .exr, .hdr or .tif)",
        vtkErrorCode::FileNotFoundError };
      return false;
    }
    if (found[face].size() > 1)
    {
      std::sort(found[face].begin(), found[face].end());
      failure = { "Environment folder '" + folder + "' has more than one '" + FaceNames[face] +
          "' image ('" + found[face][0] + "', '" + found[face][1] + "')",
        vtkErrorCode::FileFormatError };
      return false;
    }
    files.push_back(found[face][0]);
  }
  return true;
}

bool MakeFacesPlan(const std::string& folder, Plan& plan, Failure& failure)
{
  if (!FindFaces(folder, plan.Files, failure))
  {
    return false;
  }
  plan.Float = false;
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    const std::string& path = plan.Files[face];
    vtkIceImageFile::Header spec;
    if (!ReadHeader(path, spec, failure))
    {
      return false;
    }
    if (spec.Width != spec.Height)
    {
      failure = { "Cube face '" + path + "' is " + Size(spec.Width, spec.Height) + ", not square",
        vtkErrorCode::FileFormatError };
      return false;
    }
    if (face > 0 && spec.Width != plan.Width)
    {
      failure = { "Cube face '" + path + "' is " + Size(spec.Width, spec.Height) + " but '" +
          plan.Files[0] + "' is " + Size(plan.Width, plan.Height) +
          "; all six faces must be of one size",
        vtkErrorCode::FileFormatError };
      return false;
    }
    if (spec.Width > MaximumFaceSize)
    {
      failure = { "Cube face '" + path + "' is " + Size(spec.Width, spec.Height) +
          ", more than the " + Size(MaximumFaceSize, MaximumFaceSize) + " the reader accepts",
        vtkErrorCode::FileFormatError };
      return false;
    }
    plan.Width = spec.Width;
    plan.Height = spec.Height;
    plan.Float = plan.Float || !spec.EightBit;
  }
  plan.Layout = vtkIceEnvironmentReader::Faces;
  plan.FaceSize = plan.Width;
  return true;
}

bool MakeImagePlan(const std::string& path, int faceSize, Plan& plan, Failure& failure)
{
  vtkIceImageFile::Header spec;
  if (!ReadHeader(path, spec, failure))
  {
    return false;
  }
  const long long w = spec.Width;
  const long long h = spec.Height;
  plan.Files = { path };
  plan.Width = spec.Width;
  plan.Height = spec.Height;
  plan.Float = !spec.EightBit;
  if (3 * w == 4 * h)
  {
    plan.Layout = vtkIceEnvironmentReader::HorizontalCross;
    plan.FaceSize = spec.Width / 4;
  }
  else if (4 * w == 3 * h)
  {
    plan.Layout = vtkIceEnvironmentReader::VerticalCross;
    plan.FaceSize = spec.Width / 3;
  }
  else if (w == 2 * h)
  {
    plan.Layout = vtkIceEnvironmentReader::Equirectangular;
    plan.FaceSize = faceSize > 0 ? faceSize : std::max(1, spec.Width / 4);
  }
  else
  {
    failure = { "Environment image '" + path + "' is " + Size(spec.Width, spec.Height) +
        ", which is no cube map layout: expected a 4:3 horizontal cross, a 3:4 vertical cross or "
        "a 2:1 equirectangular panorama",
      vtkErrorCode::FileFormatError };
    return false;
  }
  if (plan.FaceSize > MaximumFaceSize)
  {
    failure = { "Environment image '" + path + "' would give cube faces of " +
        Size(plan.FaceSize, plan.FaceSize) + ", more than the " +
        Size(MaximumFaceSize, MaximumFaceSize) + " the reader accepts",
      vtkErrorCode::FileFormatError };
    return false;
  }
  return true;
}

bool MakePlan(const char* fileName, int faceSize, Plan& plan, Failure& failure)
{
  plan = Plan();
  if (!fileName || !*fileName)
  {
    failure = { "No FileName set: give a folder of six face images or a cross or panorama image",
      vtkErrorCode::NoFileNameError };
    return false;
  }
  const std::string path = fileName;
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
  {
    failure = { "Environment '" + path + "' does not exist", vtkErrorCode::FileNotFoundError };
    return false;
  }
  if (!std::filesystem::is_directory(status) && !std::filesystem::is_regular_file(status))
  {
    // A device such as /dev/zero, or a pipe, would be read for ever.
    failure = { "Environment '" + path + "' is neither a folder nor a regular file",
      vtkErrorCode::FileFormatError };
    return false;
  }
  const bool ok = std::filesystem::is_directory(status)
    ? MakeFacesPlan(path, plan, failure)
    : MakeImagePlan(path, faceSize, plan, failure);
  plan.Valid = ok;
  return ok;
}

// An image as RGB rows, top row first.
template <typename T>
struct Raster
{
  int Width = 0;
  int Height = 0;
  std::vector<T> RGB;
  const T* At(int x, int y) const
  {
    return &this->RGB[3 * (static_cast<size_t>(y) * this->Width + x)];
  }
};

template <typename T>
bool ReadRGB(const std::string& path, const Plan& plan, Raster<T>& raster, Failure& failure)
{
  const size_t pixels = static_cast<size_t>(plan.Width) * plan.Height;
  std::vector<T> rgb(3 * pixels);
  int channels = 0;
  vtkIceImageFile::Message message;
  switch (vtkIceImageFile::ReadPixels(path.c_str(), plan.Width, plan.Height,
    std::is_same<T, float>::value, rgb.data(), channels, message))
  {
    case vtkIceImageFile::Status::Ok:
      break;
    case vtkIceImageFile::Status::CannotOpen:
      failure = { "Cannot read environment image '" + path + "': " + message.Text,
        vtkErrorCode::CannotOpenFileError };
      return false;
    case vtkIceImageFile::Status::Changed:
      failure = { "Environment image '" + path + "' changed while it was read",
        vtkErrorCode::FileFormatError };
      return false;
    case vtkIceImageFile::Status::CannotRead:
      failure = { "Cannot read the pixels of environment image '" + path + "': " + message.Text,
        vtkErrorCode::PrematureEndOfFileError };
      return false;
  }
  if (channels == 1)
  {
    // Grey: spread each value over three channels, from the last pixel back.
    for (size_t p = pixels; p-- > 0;)
    {
      rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = rgb[p];
    }
  }
  if constexpr (std::is_same<T, float>::value)
  {
    // Light is never negative: HDR files hold small negative values where their camera's noise
    // or compression left them (all eight of blender-data's panoramas, down to -0.004), and NaN
    // where broken. Gamma correction (a skybox's, the ice's) makes both NaN, which a prefiltered
    // lobe spreads over its whole neighbourhood.
    for (float& value : rgb)
    {
      value = value > 0.0f ? value : 0.0f;
    }
  }
  raster.Width = plan.Width;
  raster.Height = plan.Height;
  raster.RGB.swap(rgb);
  return true;
}

// Copies the size x size block at (x0, y0) of `raster`, turned by 180 degrees if `rotated`,
// into `out` (row 0 first).
template <typename T>
void CopyFace(const Raster<T>& raster, int x0, int y0, int size, bool rotated, T* out)
{
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const T* texel =
        rotated ? raster.At(x0 + size - 1 - i, y0 + size - 1 - j) : raster.At(x0 + i, y0 + j);
      *out++ = texel[0];
      *out++ = texel[1];
      *out++ = texel[2];
    }
  }
}

template <typename T>
T Store(double value)
{
  if constexpr (std::is_same<T, float>::value)
  {
    return static_cast<T>(value);
  }
  else
  {
    return static_cast<T>(std::lround(std::min(255.0, std::max(0.0, value))));
  }
}

// Samples the panorama bilinearly in the direction of every texel of `face`.
template <typename T>
void SampleFace(const Raster<T>& panorama, int face, int size, T* out)
{
  const double twoPi = 2.0 * vtkMath::Pi();
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      double d[3];
      vtkIceCubeMapSource::TexelDirection(face, i, j, size, d);
      vtkMath::Normalize(d);
      const double u = 0.5 + std::atan2(d[0], -d[2]) / twoPi;
      const double v = 0.5 - std::asin(std::min(1.0, std::max(-1.0, d[1]))) / vtkMath::Pi();
      // Pixel centres are at half-integer coordinates.
      const double x = u * panorama.Width - 0.5;
      const double y = v * panorama.Height - 0.5;
      const double xFloor = std::floor(x);
      const double yFloor = std::floor(y);
      const double fx = x - xFloor;
      const double fy = y - yFloor;
      auto wrap = [&panorama](long long column) {
        const long long w = panorama.Width;
        return static_cast<int>(((column % w) + w) % w);
      };
      auto clampRow = [&panorama](long long row) {
        return static_cast<int>(std::min<long long>(panorama.Height - 1, std::max(0LL, row)));
      };
      const int x0 = wrap(static_cast<long long>(xFloor));
      const int x1 = wrap(static_cast<long long>(xFloor) + 1);
      const int y0 = clampRow(static_cast<long long>(yFloor));
      const int y1 = clampRow(static_cast<long long>(yFloor) + 1);
      const T* a = panorama.At(x0, y0);
      const T* b = panorama.At(x1, y0);
      const T* c = panorama.At(x0, y1);
      const T* e = panorama.At(x1, y1);
      for (int k = 0; k < 3; ++k)
      {
        const double top = a[k] + fx * (static_cast<double>(b[k]) - a[k]);
        const double bottom = c[k] + fx * (static_cast<double>(e[k]) - c[k]);
        *out++ = Store<T>(top + fy * (bottom - top));
      }
    }
  }
}

// Fills the six outputs from the files of `plan`; false and `failure` set if a file cannot be
// read.
template <typename T>
bool ReadFaces(const Plan& plan, vtkInformationVector* outputVector, Failure& failure)
{
  using ArrayType = typename std::conditional<std::is_same<T, float>::value, vtkFloatArray,
    vtkUnsignedCharArray>::type;
  const int size = plan.FaceSize;
  std::array<vtkSmartPointer<ArrayType>, NumberOfFaces> faces;
  for (auto& face : faces)
  {
    face = vtkSmartPointer<ArrayType>::New();
    face->SetName("CubeFace");
    face->SetNumberOfComponents(3);
    face->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  }

  if (plan.Layout == vtkIceEnvironmentReader::Faces)
  {
    for (int face = 0; face < NumberOfFaces; ++face)
    {
      Raster<T> raster;
      if (!ReadRGB(plan.Files[face], plan, raster, failure))
      {
        return false;
      }
      CopyFace(raster, 0, 0, size, false, faces[face]->GetPointer(0));
    }
  }
  else
  {
    Raster<T> raster;
    if (!ReadRGB(plan.Files[0], plan, raster, failure))
    {
      return false;
    }
    for (int face = 0; face < NumberOfFaces; ++face)
    {
      T* out = faces[face]->GetPointer(0);
      if (plan.Layout == vtkIceEnvironmentReader::Equirectangular)
      {
        SampleFace(raster, face, size, out);
      }
      else
      {
        const Cell& cell = plan.Layout == vtkIceEnvironmentReader::HorizontalCross
          ? HorizontalCrossCells[face]
          : VerticalCrossCells[face];
        CopyFace(raster, cell.Column * size, cell.Row * size, size, cell.Rotated, out);
      }
    }
  }

  for (int face = 0; face < NumberOfFaces; ++face)
  {
    vtkImageData* image = vtkImageData::GetData(outputVector, face);
    image->SetDimensions(size, size, 1);
    image->GetPointData()->SetScalars(faces[face]);
  }
  return true;
}
}

class vtkIceEnvironmentReader::vtkInternals
{
public:
  Plan Current;
};

//------------------------------------------------------------------------------
vtkIceEnvironmentReader::vtkIceEnvironmentReader()
  : FileName(nullptr)
  , FaceSize(0)
  , Layout(Unknown)
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(NumberOfFaces);
}

//------------------------------------------------------------------------------
vtkIceEnvironmentReader::~vtkIceEnvironmentReader()
{
  this->SetFileName(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
const char* vtkIceEnvironmentReader::GetLayoutAsString(int layout)
{
  switch (layout)
  {
    case Faces:
      return "Faces";
    case HorizontalCross:
      return "HorizontalCross";
    case VerticalCross:
      return "VerticalCross";
    case Equirectangular:
      return "Equirectangular";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
const char* vtkIceEnvironmentReader::GetLayoutAsString() const
{
  return GetLayoutAsString(this->Layout);
}

//------------------------------------------------------------------------------
void vtkIceEnvironmentReader::ConfigureTexture(vtkTexture* texture)
{
  vtkIceCubeMapTexture::Configure(texture, this);
}

//------------------------------------------------------------------------------
int vtkIceEnvironmentReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Set directly: the Set macros would modify the reader and make the pipeline run it again.
  this->ErrorCode = vtkErrorCode::NoError;
  Plan& plan = this->Internals->Current;
  Failure failure;
  if (!MakePlan(this->FileName, this->FaceSize, plan, failure))
  {
    plan = Plan();
    this->ErrorCode = failure.Code;
    vtkErrorMacro(<< failure.Message);
  }
  this->Layout = plan.Layout;

  vtkIceCubeMapTexture::SetFaceInformation(
    outputVector, plan.Valid ? plan.FaceSize : 0, plan.Float ? VTK_FLOAT : VTK_UNSIGNED_CHAR);
  return 1;
}

//------------------------------------------------------------------------------
int vtkIceEnvironmentReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int face = 0; face < NumberOfFaces; ++face)
  {
    vtkImageData::GetData(outputVector, face)->Initialize();
  }
  const Plan plan = this->Internals->Current;
  if (!plan.Valid)
  {
    // RequestInformation has reported the error; the outputs stay empty.
    return 1;
  }
  Failure failure;
  bool ok = false;
  try
  {
    ok = plan.Float ? ReadFaces<float>(plan, outputVector, failure)
                    : ReadFaces<unsigned char>(plan, outputVector, failure);
  }
  catch (const std::bad_alloc&)
  {
    failure = { "Not enough memory to read environment '" + plan.Files[0] + "' (" +
        Size(plan.Width, plan.Height) + ", faces of " + Size(plan.FaceSize, plan.FaceSize) + ")",
      vtkErrorCode::UnknownError };
  }
  if (!ok)
  {
    for (int face = 0; face < NumberOfFaces; ++face)
    {
      vtkImageData::GetData(outputVector, face)->Initialize();
    }
    // The empty outputs do not cover the extent announced by RequestInformation, so the pipeline
    // runs RequestData again on the next update: report the error only this once.
    this->Internals->Current = Plan();
    this->Layout = Unknown;
    this->ErrorCode = failure.Code;
    vtkErrorMacro(<< failure.Message);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkIceEnvironmentReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FaceSize: " << this->FaceSize << (this->FaceSize == 0 ? " (automatic)" : "")
     << "\n";
  os << indent << "Layout: " << this->GetLayoutAsString() << "\n";
}
