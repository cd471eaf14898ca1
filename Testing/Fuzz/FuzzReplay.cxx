// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Runs a libFuzzer harness once on each file named (or in each folder named) without libFuzzer:
// the seeds and every input that once crashed (Regressions/) replayed by the ordinary test suite,
// under each build's compiler and, in ./ice.sh sanitize, under ASan and UBSan.
#include <cstdint>
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/stat.h>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
int Replay(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  return 1;
}
}

int main(int argc, char* argv[])
{
  int inputs = 0;
  for (int i = 1; i < argc; ++i)
  {
    struct stat info;
    if (stat(argv[i], &info) != 0)
    {
      continue; // a folder of regressions that has none yet
    }
    if (!S_ISDIR(info.st_mode))
    {
      inputs += Replay(argv[i]);
      continue;
    }
    if (DIR* folder = opendir(argv[i]))
    {
      while (dirent* entry = readdir(folder))
      {
        const std::string name = entry->d_name;
        if (name != "." && name != "..")
        {
          inputs += Replay(std::string(argv[i]) + "/" + name);
        }
      }
      closedir(folder);
    }
  }
  std::printf("%d inputs replayed\n", inputs);
  return inputs > 0 ? 0 : 1;
}
