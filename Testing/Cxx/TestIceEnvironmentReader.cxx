// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkIceEnvironmentReader: writes environments with OpenImageIO into the temporary folder (-T)
// and reads them back. Six 8-bit PNG faces, a horizontal cross and an RGBA vertical cross of
// vtkIceCubeMapSource's DirectionTest faces must come back texel for texel (+-1) at the texel
// directions of vtkIceCubeMapSource::TexelDirection; a float EXR equirectangular panorama of the
// same pattern times 3 must come back as float with values above 1 and a small error; a grey
// 8-bit panorama comes back as RGB. Bad input gives exactly one error and empty outputs, also when
// a texture fed by the reader is rendered. Finally the faces read back, as a texture, must render
// a skybox pixel-equal to vtkIceCubeMapSource's and pass the ice invisibility check, and the float
// faces of an EXR panorama must render a skybox within 1/255 of it.
#include "IceTestImageWriter.h"
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceEnvironmentReader.h"
#include "vtkIceMapper.h"
#include "vtkIceVTKCompat.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

const char* const FaceNames[6] = { "px", "nx", "py", "ny", "pz", "nz" };
constexpr double PanoramaScale = 3.0; // so that the EXR panorama has values above 1

bool Report(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  return ok;
}

bool WriteImage(
  const std::string& path, int width, int height, int channels, bool asFloat, const void* pixels)
{
  return IceTest::WriteImage(path.c_str(), width, height, channels, asFloat, pixels);
}

// The six DirectionTest faces of vtkIceCubeMapSource (RGB, row 0 first).
struct Faces
{
  int Size = 0;
  std::vector<unsigned char> RGB[6];
  const unsigned char* At(int face, int i, int j) const
  {
    return &this->RGB[face][3 * (static_cast<size_t>(j) * this->Size + i)];
  }
};

Faces MakeFaces(int size)
{
  vtkNew<vtkIceCubeMapSource> source;
  source->SetPatternToDirectionTest();
  source->SetFaceSize(size);
  source->Update();
  Faces faces;
  faces.Size = size;
  for (int face = 0; face < 6; ++face)
  {
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(
      vtkImageData::SafeDownCast(source->GetOutputDataObject(face))->GetPointData()->GetScalars());
    faces.RGB[face].assign(scalars->GetPointer(0), scalars->GetPointer(0) + 3 * size * size);
  }
  return faces;
}

// Writes each face as an 8-bit PNG named px.png ... nz.png, row 0 as the top row of the file.
bool WriteFaces(const Faces& faces, const std::string& folder)
{
  fs::create_directories(folder);
  bool ok = true;
  for (int face = 0; face < 6; ++face)
  {
    ok = WriteImage(folder + "/" + FaceNames[face] + ".png", faces.Size, faces.Size, 3, false,
           faces.RGB[face].data()) &&
      ok;
  }
  return ok;
}

// The test's own description of the crosses (column, row in face units; rotated by 180 degrees).
struct Placement
{
  int Column;
  int Row;
  bool Rotated;
};
const Placement HorizontalCross[6] = { { 2, 1, false }, { 0, 1, false }, { 1, 0, false },
  { 1, 2, false }, { 1, 1, false }, { 3, 1, false } };
const Placement VerticalCross[6] = { { 2, 1, false }, { 0, 1, false }, { 1, 0, false },
  { 1, 2, false }, { 1, 1, false }, { 1, 3, true } };

// The face and texel shown at cross pixel (x, y); false where the cross is empty.
bool CrossTexel(const Placement* layout, int size, int x, int y, int& face, int& i, int& j)
{
  for (face = 0; face < 6; ++face)
  {
    const Placement& p = layout[face];
    const int u = x - p.Column * size;
    const int v = y - p.Row * size;
    if (u >= 0 && u < size && v >= 0 && v < size)
    {
      i = p.Rotated ? size - 1 - u : u;
      j = p.Rotated ? size - 1 - v : v;
      return true;
    }
  }
  return false;
}

// The cross image (top row first) with `channels` 3 or 4 (alpha 128) on a black background.
std::vector<unsigned char> MakeCross(
  const Faces& faces, const Placement* layout, int columns, int rows, int channels)
{
  const int width = columns * faces.Size;
  const int height = rows * faces.Size;
  std::vector<unsigned char> image(static_cast<size_t>(width) * height * channels, 0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      int face, i, j;
      if (CrossTexel(layout, faces.Size, x, y, face, i, j))
      {
        unsigned char* out = &image[channels * (static_cast<size_t>(y) * width + x)];
        std::copy(faces.At(face, i, j), faces.At(face, i, j) + 3, out);
        if (channels == 4)
        {
          out[3] = 128;
        }
      }
    }
  }
  return image;
}

// Seams of a cross layout are continuous: across every edge between two faces in the image, the
// directions of the two texels differ by at most about one texel. Returns the number of
// face-to-face pixel pairs checked (5 seams of `size` pairs each) or -1 if a seam is broken.
int CheckSeams(const Placement* layout, int columns, int rows, int size)
{
  const double limit = 1.5 * 2.0 / size; // a texel spans at most 2/size radians
  int pairs = 0;
  for (int y = 0; y < rows * size; ++y)
  {
    for (int x = 0; x < columns * size; ++x)
    {
      int faceA, iA, jA;
      if (!CrossTexel(layout, size, x, y, faceA, iA, jA))
      {
        continue;
      }
      const int neighbours[2][2] = { { x + 1, y }, { x, y + 1 } };
      for (const auto& n : neighbours)
      {
        int faceB, iB, jB;
        if (n[0] >= columns * size || n[1] >= rows * size ||
          !CrossTexel(layout, size, n[0], n[1], faceB, iB, jB) || faceB == faceA)
        {
          continue;
        }
        double a[3], b[3];
        vtkIceCubeMapSource::TexelDirection(faceA, iA, jA, size, a);
        vtkIceCubeMapSource::TexelDirection(faceB, iB, jB, size, b);
        vtkMath::Normalize(a);
        vtkMath::Normalize(b);
        if (std::acos(std::min(1.0, vtkMath::Dot(a, b))) > limit)
        {
          std::cout << "seam broken between faces " << FaceNames[faceA] << " and "
                    << FaceNames[faceB] << " at cross pixel " << x << "," << y << "\n";
          return -1;
        }
        ++pairs;
      }
    }
  }
  return pairs;
}

// The panorama convention of vtkIceEnvironmentReader, written independently: u to the right and
// v down in [0, 1]; the centre column looks toward -Z, u = 0.75 toward +X, the top row up.
void PanoramaDirection(double u, double v, double dir[3])
{
  const double longitude = (u - 0.5) * 2.0 * vtkMath::Pi();
  const double latitude = (0.5 - v) * vtkMath::Pi();
  dir[0] = std::sin(longitude) * std::cos(latitude);
  dir[1] = std::sin(latitude);
  dir[2] = -std::cos(longitude) * std::cos(latitude);
}

bool CheckPanoramaConvention()
{
  auto near = [](double u, double v, double x, double y, double z) {
    double d[3];
    PanoramaDirection(u, v, d);
    return std::abs(d[0] - x) + std::abs(d[1] - y) + std::abs(d[2] - z) < 1e-12;
  };
  return Report(near(0.5, 0.5, 0, 0, -1) && near(0.75, 0.5, 1, 0, 0) && near(0.25, 0.5, -1, 0, 0) &&
      near(0.0, 0.5, 0, 0, 1) && near(0.5, 0.0, 0, 1, 0) && near(0.5, 1.0, 0, -1, 0),
    "panorama convention: centre -Z, right quarter +X, edges +Z, top +Y");
}

// An equirectangular panorama of the DirectionTest pattern times `scale` (RGB float).
std::vector<float> MakePanorama(int width, int height, double scale)
{
  vtkNew<vtkIceCubeMapSource> pattern;
  pattern->SetPatternToDirectionTest();
  std::vector<float> image(3 * static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      double dir[3], rgb[3];
      PanoramaDirection((x + 0.5) / width, (y + 0.5) / height, dir);
      pattern->Evaluate(dir, rgb);
      for (int c = 0; c < 3; ++c)
      {
        image[3 * (static_cast<size_t>(y) * width + x) + c] = static_cast<float>(scale * rgb[c]);
      }
    }
  }
  return image;
}

vtkImageData* Output(vtkIceEnvironmentReader* reader, int face)
{
  return vtkImageData::SafeDownCast(reader->GetOutputDataObject(face));
}

// Reads `path` and checks layout, face size and scalar type.
bool ReadAs(vtkIceEnvironmentReader* reader, const std::string& path, int layout, int size,
  int scalarType, const std::string& name)
{
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  bool ok = recorder->Errors.empty() && recorder->Warnings.empty() &&
    reader->GetLayout() == layout && reader->GetErrorCode() == vtkErrorCode::NoError;
  for (int face = 0; face < 6 && ok; ++face)
  {
    vtkImageData* image = Output(reader, face);
    int dims[3];
    image->GetDimensions(dims);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    ok = dims[0] == size && dims[1] == size && dims[2] == 1 && scalars &&
      scalars->GetNumberOfComponents() == 3 && scalars->GetDataType() == scalarType;
  }
  reader->RemoveAllObservers();
  return Report(ok,
    name + ": layout " + reader->GetLayoutAsString() + ", " + std::to_string(size) + "x" +
      std::to_string(size) + " faces of " + vtkImageScalarTypeNameMacro(scalarType) +
      (recorder->Errors.empty() ? std::string() : ", error: " + recorder->Errors[0]));
}

// Calls `visit(rgb, scalars, t)` for every texel t of every face the reader produced, with the
// DirectionTest colour `rgb` at the texel's direction.
template <typename Visit>
void ForEachTexel(vtkIceEnvironmentReader* reader, Visit visit)
{
  vtkNew<vtkIceCubeMapSource> pattern;
  pattern->SetPatternToDirectionTest();
  for (int face = 0; face < 6; ++face)
  {
    vtkImageData* image = Output(reader, face);
    const int size = image->GetDimensions()[0];
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        double dir[3], rgb[3];
        vtkIceCubeMapSource::TexelDirection(face, i, j, size, dir);
        pattern->Evaluate(dir, rgb);
        visit(rgb, scalars, static_cast<vtkIdType>(j) * size + i);
      }
    }
  }
}

// Every texel of every face against the 8-bit DirectionTest colour at its direction, within 1.
bool CheckExact(vtkIceEnvironmentReader* reader, const std::string& name)
{
  int worst = 0;
  ForEachTexel(reader, [&worst](const double rgb[3], vtkDataArray* scalars, vtkIdType t) {
    for (int c = 0; c < 3; ++c)
    {
      const double expected = std::lround(255.0 * std::min(1.0, std::max(0.0, rgb[c])));
      const double read = scalars->GetComponent(t, c);
      worst = std::max(worst, static_cast<int>(std::abs(read - expected)));
    }
  });
  return Report(worst <= 1,
    name + ": every texel within " + std::to_string(worst) +
      "/255 of the pattern at its direction");
}

// Every texel of every face against `scale` times the DirectionTest colour at its direction:
// mean and largest channel error, the largest value read, and (grey) whether R = G = B.
struct PanoramaError
{
  double Mean = 0.0;
  double Max = 0.0;
  double Largest = 0.0;
  bool Grey = true;
};

PanoramaError MeasurePanorama(vtkIceEnvironmentReader* reader, double scale, bool grey)
{
  PanoramaError error;
  double sum = 0.0;
  size_t count = 0;
  ForEachTexel(reader, [&](const double rgb[3], vtkDataArray* scalars, vtkIdType t) {
    for (int c = 0; c < 3; ++c)
    {
      const double read = scalars->GetComponent(t, c);
      const double expected = scale * rgb[grey ? 0 : c];
      const double e = std::abs(read - expected);
      sum += e;
      ++count;
      error.Max = std::max(error.Max, e);
      error.Largest = std::max(error.Largest, read);
      error.Grey = error.Grey && read == scalars->GetComponent(t, 0);
    }
  });
  error.Mean = sum / count;
  return error;
}

bool OutputsEmpty(vtkIceEnvironmentReader* reader)
{
  for (int face = 0; face < 6; ++face)
  {
    if (Output(reader, face)->GetNumberOfPoints() != 0 ||
      Output(reader, face)->GetPointData()->GetScalars())
    {
      return false;
    }
  }
  return true;
}

// Bad input: exactly one error that contains `expected`, Layout Unknown, an ErrorCode, empty
// outputs. The reader is reused, so stale faces of an earlier good read must be gone too.
bool CheckBad(vtkIceEnvironmentReader* reader, const char* path, const std::string& expected,
  const std::string& name)
{
  vtkNew<IceTest::MessageRecorder> recorder;
  recorder->Watch(reader);
  reader->SetFileName(path);
  reader->Update();
  reader->Update(); // nothing changed: no second error
  const bool ok = recorder->Errors.size() == 1 &&
    recorder->Errors[0].find(expected) != std::string::npos && recorder->Warnings.empty() &&
    reader->GetLayout() == vtkIceEnvironmentReader::Unknown &&
    reader->GetErrorCode() != vtkErrorCode::NoError && OutputsEmpty(reader);
  reader->RemoveAllObservers();
  return Report(ok,
    name + ": " + std::to_string(recorder->Errors.size()) + " error(s)" +
      (recorder->Errors.empty() ? std::string() : ": " + recorder->Errors[0]));
}

// A texture fed by a reader that failed: the skybox and the ice render without crashing and the
// reader reports its one error.
bool RenderFailedTexture(const std::string& path)
{
  vtkNew<vtkIceEnvironmentReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<IceTest::MessageRecorder> readerErrors;
  readerErrors->Watch(reader);
  vtkNew<vtkTexture> texture;
  reader->ConfigureTexture(texture);
  vtkNew<IceTest::MessageRecorder> textureErrors; // vtkTexture: "No scalar values found ..."
  textureErrors->Watch(texture);

  vtkNew<vtkRenderer> renderer;
  renderer->SetEnvironmentTexture(texture);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(texture);
  if (vtkIceVTKCompat::SkyboxDrawsUnloadedTextureCleanly)
  {
    renderer->AddActor(skybox); // else VTK's own skybox raises a GL error (vtkIceVTKCompat.h)
  }
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkIceMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<IceTest::MessageRecorder> mapperMessages;
  mapperMessages->Watch(mapper);
  vtkNew<vtkActor> ice;
  ice->SetMapper(mapper);
  renderer->AddActor(ice);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();
  window->Render();
  IceTest::Capture(window);
  return Report(readerErrors->Errors.size() == 1,
    "texture of a failed reader renders twice without crashing (reader: " +
      std::to_string(readerErrors->Errors.size()) + " error; texture: " +
      std::to_string(textureErrors->Errors.size()) + " error(s) about missing scalars)");
}
}

int TestIceEnvironmentReader(int argc, char* argv[])
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string temp = std::string(testing->GetTempDirectory()) + "/environment-reader";
  fs::remove_all(temp);
  fs::create_directories(temp);
  bool ok = true;

  // (a) Six 8-bit PNG faces.
  const int size = 64;
  const Faces faces = MakeFaces(size);
  ok = WriteFaces(faces, temp + "/faces") && ok;
  std::ofstream(temp + "/faces/px.txt") << "notes are not a second px image\n";
  vtkNew<vtkIceEnvironmentReader> reader;
  if (ReadAs(reader, temp + "/faces", vtkIceEnvironmentReader::Faces, size, VTK_UNSIGNED_CHAR,
        "six PNG faces"))
  {
    ok = CheckExact(reader, "six PNG faces") && ok;
  }
  else
  {
    ok = false;
  }

  // (b) A horizontal cross (RGB) and (c) a vertical cross (RGBA; alpha is dropped).
  const int horizontalPairs = CheckSeams(HorizontalCross, 4, 3, size);
  const int verticalPairs = CheckSeams(VerticalCross, 3, 4, size);
  ok = Report(horizontalPairs == 5 * size && verticalPairs == 5 * size,
         "cross layouts have continuous seams (" + std::to_string(horizontalPairs) + " and " +
           std::to_string(verticalPairs) + " face-to-face pixel pairs within 1.5 texels)") &&
    ok;
  const std::vector<unsigned char> horizontal = MakeCross(faces, HorizontalCross, 4, 3, 3);
  ok = WriteImage(temp + "/hcross.png", 4 * size, 3 * size, 3, false, horizontal.data()) && ok;
  if (ReadAs(reader, temp + "/hcross.png", vtkIceEnvironmentReader::HorizontalCross, size,
        VTK_UNSIGNED_CHAR, "horizontal cross PNG"))
  {
    ok = CheckExact(reader, "horizontal cross PNG") && ok;
  }
  else
  {
    ok = false;
  }
  const std::vector<unsigned char> vertical = MakeCross(faces, VerticalCross, 3, 4, 4);
  ok = WriteImage(temp + "/vcross.png", 3 * size, 4 * size, 4, false, vertical.data()) && ok;
  if (ReadAs(reader, temp + "/vcross.png", vtkIceEnvironmentReader::VerticalCross, size,
        VTK_UNSIGNED_CHAR, "vertical cross RGBA PNG"))
  {
    ok = CheckExact(reader, "vertical cross RGBA PNG") && ok;
  }
  else
  {
    ok = false;
  }

  // (d) A float EXR equirectangular panorama, 3 x the pattern; faces of width / 4 = 128.
  ok = CheckPanoramaConvention() && ok;
  const int panoramaWidth = 512;
  const std::vector<float> panorama = MakePanorama(panoramaWidth, panoramaWidth / 2, PanoramaScale);
  ok = WriteImage(
         temp + "/panorama.exr", panoramaWidth, panoramaWidth / 2, 3, true, panorama.data()) &&
    ok;
  if (ReadAs(reader, temp + "/panorama.exr", vtkIceEnvironmentReader::Equirectangular,
        panoramaWidth / 4, VTK_FLOAT, "EXR panorama"))
  {
    const PanoramaError e = MeasurePanorama(reader, PanoramaScale, false);
    ok = Report(e.Mean <= 0.002 * PanoramaScale && e.Max <= 0.02 * PanoramaScale,
           "EXR panorama: |read - 3 x pattern| mean " + std::to_string(e.Mean) + ", max " +
             std::to_string(e.Max) + " (values up to 3)") &&
      ok;
    ok = Report(e.Largest > 2.5,
           "EXR panorama: HDR kept as float, largest value " + std::to_string(e.Largest)) &&
      ok;
  }
  else
  {
    ok = false;
  }
  reader->SetFaceSize(40);
  ok = ReadAs(reader, temp + "/panorama.exr", vtkIceEnvironmentReader::Equirectangular, 40,
         VTK_FLOAT, "EXR panorama with FaceSize 40") &&
    ok;
  reader->SetFaceSize(0);

  // Light is never negative: an EXR panorama's negative values (its camera's noise; every one of
  // blender-data's has some) and NaN read as 0, or gamma correction makes them NaN.
  std::vector<float> noisy = panorama;
  for (size_t v = 0; v < noisy.size(); v += 5)
  {
    noisy[v] = -0.004f;
  }
  noisy[3 * (panoramaWidth / 2) * (panoramaWidth / 4) + 2] = std::nanf("");
  ok = WriteImage(temp + "/noisy.exr", panoramaWidth, panoramaWidth / 2, 3, true, noisy.data()) &&
    ok;
  if (ReadAs(reader, temp + "/noisy.exr", vtkIceEnvironmentReader::Equirectangular,
        panoramaWidth / 4, VTK_FLOAT, "EXR panorama with negative values and a NaN"))
  {
    size_t below = 0;
    ForEachTexel(reader, [&](const double*, vtkDataArray* scalars, vtkIdType t) {
      for (int c = 0; c < 3; ++c)
      {
        const double read = scalars->GetComponent(t, c);
        below += !(read >= 0.0);
      }
    });
    ok = Report(below == 0,
           "EXR panorama with negative values and a NaN: " + std::to_string(below) +
             " values read below 0 or NaN") &&
      ok;
  }
  else
  {
    ok = false;
  }

  // A grey 8-bit panorama (the red channel of the pattern) comes back as RGB.
  std::vector<unsigned char> grey(panorama.size() / 3);
  for (size_t p = 0; p < grey.size(); ++p)
  {
    grey[p] = static_cast<unsigned char>(std::lround(255.0 * panorama[3 * p] / PanoramaScale));
  }
  ok =
    WriteImage(temp + "/grey.png", panoramaWidth, panoramaWidth / 2, 1, false, grey.data()) && ok;
  if (ReadAs(reader, temp + "/grey.png", vtkIceEnvironmentReader::Equirectangular,
        panoramaWidth / 4, VTK_UNSIGNED_CHAR, "grey PNG panorama"))
  {
    const PanoramaError e = MeasurePanorama(reader, 255.0, true);
    ok = Report(e.Grey && e.Mean <= 2.0 && e.Max <= 8.0,
           "grey PNG panorama: R = G = B, |read - pattern| mean " + std::to_string(e.Mean) +
             "/255, max " + std::to_string(e.Max) + "/255") &&
      ok;
  }
  else
  {
    ok = false;
  }

  // Bad input. The reader keeps its last good faces until then; each case must clear them.
  const std::string bad = temp + "/bad";
  fs::create_directories(bad);
  std::ofstream(bad + "/garbage.png") << "this is not a PNG file\n";
  {
    // A PNG whose header is intact but whose pixel data is cut short.
    const std::string whole = temp + "/hcross.png";
    std::vector<char> bytes(fs::file_size(whole));
    std::ifstream(whole, std::ios::binary).read(bytes.data(), bytes.size());
    std::ofstream(bad + "/truncated.png", std::ios::binary).write(bytes.data(), bytes.size() / 3);
  }
  fs::create_directories(bad + "/missing-face");
  for (int face = 0; face < 5; ++face)
  {
    fs::copy_file(temp + "/faces/" + FaceNames[face] + ".png",
      bad + "/missing-face/" + FaceNames[face] + ".png");
  }
  std::ofstream(bad + "/missing-face/nz.txt") << "not an image\n";
  fs::copy(temp + "/faces", bad + "/two-px");
  fs::copy_file(temp + "/faces/px.png", bad + "/two-px/px.jpg");
  fs::copy(temp + "/faces", bad + "/not-square");
  const std::vector<unsigned char> wide(3 * 64 * 48, 128);
  ok = WriteImage(bad + "/not-square/py.png", 64, 48, 3, false, wide.data()) && ok;
  fs::copy(temp + "/faces", bad + "/sizes");
  ok = WriteImage(bad + "/sizes/nz.png", 32, 32, 3, false, wide.data()) && ok;
  ok = WriteImage(bad + "/square.png", 48, 48, 3, false, wide.data()) && ok;

  ReadAs(reader, temp + "/faces", vtkIceEnvironmentReader::Faces, size, VTK_UNSIGNED_CHAR,
    "six PNG faces again before the bad input");
  ok = CheckBad(reader, (temp + "/no-such-thing").c_str(), "does not exist", "missing path") && ok;
  ok = CheckBad(reader, (bad + "/garbage.png").c_str(), "Cannot read", "corrupt file") && ok;
  ok = CheckBad(reader, (bad + "/truncated.png").c_str(), "Cannot read", "truncated PNG") && ok;
  ok = CheckBad(reader, (bad + "/missing-face").c_str(), "no face image 'nz", "missing face") && ok;
  ok = CheckBad(reader, (bad + "/two-px").c_str(), "more than one 'px'", "two px images") && ok;
  ok = CheckBad(reader, (bad + "/not-square").c_str(), "not square", "non-square face") && ok;
  ok = CheckBad(reader, (bad + "/sizes").c_str(), "one size", "faces of different sizes") && ok;
  ok = CheckBad(reader, (bad + "/square.png").c_str(), "no cube map layout", "1:1 image") && ok;
  ok = CheckBad(reader, nullptr, "No FileName", "no file name") && ok;
  ok = RenderFailedTexture(bad + "/garbage.png") && ok;

  // The faces read back follow vtkSkybox's convention: the skybox of the reader's texture is
  // pixel-equal to that of vtkIceCubeMapSource's, and the ice is invisible at eta 1 against it.
  const int renderSize = 128;
  const Faces renderFaces = MakeFaces(renderSize);
  ok = WriteFaces(renderFaces, temp + "/render-faces") && ok;
  vtkNew<vtkIceEnvironmentReader> renderReader;
  renderReader->SetFileName((temp + "/render-faces").c_str());
  vtkNew<vtkTexture> readTexture;
  renderReader->ConfigureTexture(readTexture);
  const IceTest::Invisibility read = IceTest::MeasureInvisibility(readTexture);
  ok = IceTest::ReportInvisibility("reader's faces", read) && ok;
  const IceTest::Invisibility reference = IceTest::MeasureInvisibility(
    IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, renderSize));
  int worst = 0;
  for (size_t p = 0; p < read.Background.RGB.size() / 3; ++p)
  {
    worst = std::max(worst,
      IceTest::PixelDifference(&read.Background.RGB[3 * p], &reference.Background.RGB[3 * p]));
  }
  ok = Report(worst <= 1 && read.Background.Width == reference.Background.Width,
         "skybox of the reader's faces vs vtkIceCubeMapSource's: largest difference " +
           std::to_string(worst) + "/255") &&
    ok;

  // Float faces are uploaded as colours too: the skybox of an EXR panorama of the pattern (scale
  // 1) matches vtkIceCubeMapSource's within the panorama's resampling error.
  const std::vector<float> unitPanorama = MakePanorama(1024, 512, 1.0);
  ok = WriteImage(temp + "/unit-panorama.exr", 1024, 512, 3, true, unitPanorama.data()) && ok;
  vtkNew<vtkIceEnvironmentReader> floatReader;
  floatReader->SetFileName((temp + "/unit-panorama.exr").c_str());
  floatReader->SetFaceSize(renderSize);
  vtkNew<vtkTexture> floatTexture;
  floatReader->ConfigureTexture(floatTexture);
  const IceTest::Invisibility floatRender = IceTest::MeasureInvisibility(floatTexture);
  ok = IceTest::ReportInvisibility("float faces of a panorama", floatRender) && ok;
  std::vector<double> differences;
  for (size_t p = 0; p < floatRender.Background.RGB.size() / 3; ++p)
  {
    differences.push_back(IceTest::PixelDifference(
      &floatRender.Background.RGB[3 * p], &reference.Background.RGB[3 * p]));
  }
  const IceTest::Stats floatStats = IceTest::Summarize(differences);
  ok =
    Report(floatStats.Mean <= 1.0 && floatStats.Max <= 4.0,
      "skybox of float panorama faces vs vtkIceCubeMapSource's: mean " +
        std::to_string(floatStats.Mean) + "/255, max " + std::to_string(floatStats.Max) + "/255") &&
    ok;

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
