// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Proof that OpenImageIO leaks by itself when it reads a truncated PNG
// (Testing/Sanitizers/lsan-environment-reader.supp). OpenImageIO 2.4's PNG reader reports a
// short read from libpng's read callback with png_error(..., geterror().c_str()): png_error
// longjmps out, and the temporary std::string from geterror() is never destroyed. LeakSanitizer
// reports 31 bytes allocated in basic_string::_M_assign from ImageInput::geterror from
// PNGInput::PngReadCallback, the leak of Cxx.TestIceEnvironmentReader's truncated-PNG case.
//   g++ -std=c++17 -fsanitize=address Testing/Sanitizers/openimageio-png-leak.cxx \
//     $(pkg-config --cflags --libs OpenImageIO) -o /tmp/oiio-leak
//   cd /tmp && ASAN_OPTIONS=fast_unwind_on_malloc=0 ./oiio-leak
#include <OpenImageIO/imageio.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

int main()
{
  const int size = 64;
  std::vector<unsigned char> pixels(size * size * 3);
  for (size_t i = 0; i < pixels.size(); ++i)
  {
    pixels[i] = static_cast<unsigned char>(i * 7);
  }
  auto output = OIIO::ImageOutput::create("full.png");
  output->open("full.png", OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8));
  output->write_image(OIIO::TypeDesc::UINT8, pixels.data());
  output->close();
  output.reset();

  std::ifstream full("full.png", std::ios::binary);
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(full)), std::istreambuf_iterator<char>());
  std::ofstream("truncated.png", std::ios::binary).write(bytes.data(), bytes.size() / 3);

  auto input = OIIO::ImageInput::open("truncated.png");
  std::vector<unsigned char> read(pixels.size());
  const bool ok = input && input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, read.data());
  std::cout << "read_image of a truncated PNG " << (ok ? "succeeded" : "failed, as it should")
            << "\n";
  return 0;
}
