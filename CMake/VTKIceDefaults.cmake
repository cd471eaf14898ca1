# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Settings every VTK Ice project shares (the main build and ParaView/): C++17, a Release build
# unless told otherwise, shared libraries (VTK's Python and ClientServer wrapping need them).
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()
set(BUILD_SHARED_LIBS ON)

# Sources that pass C++ library types to Debian's libraries (OpenImageIO) keep the system's
# libstdc++ ABI when VTK's is the old one (VTKICE_VTK_OLD_CXX_ABI, set by VTKIceVTK.cmake for the
# `vtk` wheels; never set in the ParaView plugin's build, whose VTK is Debian's).
function (vtkice_use_system_cxx_abi)
  if (VTKICE_VTK_OLD_CXX_ABI)
    set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_OPTIONS
      -U_GLIBCXX_USE_CXX11_ABI -D_GLIBCXX_USE_CXX11_ABI=1)
  endif ()
endfunction ()
