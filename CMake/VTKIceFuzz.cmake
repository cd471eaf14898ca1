# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# VTKICE_FUZZ: the libFuzzer harnesses of Testing/Fuzz, with every file of VTK Ice compiled for
# coverage-guided fuzzing and AddressSanitizer. Needs clang (Debian: clang-14 and
# libclang-rt-14-dev, which has libFuzzer); ./ice.sh fuzz configures a folder of its own.
option(VTKICE_FUZZ "Build the libFuzzer harnesses (clang)" OFF)
if (VTKICE_FUZZ)
  if (NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "VTKICE_FUZZ needs clang (CXX=clang++-14), not ${CMAKE_CXX_COMPILER_ID}")
  endif ()
  # -O1 and line tables only: quicker to build than -O2 -g, and a crash's stack still names files
  # and lines.
  add_compile_options(-fsanitize=fuzzer-no-link,address -fno-omit-frame-pointer -O1
    -gline-tables-only)
  add_link_options(-fsanitize=address)
endif ()
