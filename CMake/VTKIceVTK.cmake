# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The VTK that VTK Ice builds against and what differs between the versions it supports (9.1 to
# 9.7): the one CMake file that knows (Module/vtkIceVTKCompat.h is the C++ one).
#   - VTKICE_VTK_MODULES: the VTK modules the project uses. `cmake -P CMake/VTKIceVTK.cmake`
#     prints them (the wheel SDK script enables exactly these).
#   - VTK::opengl (GLEW) exists before VTK 9.4 only; from 9.4 glad comes with RenderingOpenGL2.
#     VTKICE_VTK_GL names what to link for GL calls.
#   - VTK::mpi: Debian's VTK wants it found (its targets name MPI::MPI_C); the wheels have none.
#   - The `vtk` wheels (PyPI, VTK >= 9.4) are built with the old libstdc++ ABI and keep their
#     libraries in site-packages/vtkmodules/: VTKICE_VTK_WHEEL, the ABI and the RPATH follow.
set(VTKICE_VTK_MODULES
  CommonColor CommonComputationalGeometry CommonCore CommonDataModel CommonExecutionModel
  CommonMath CommonSystem CommonTransforms
  FiltersCore FiltersGeneral FiltersGeometry FiltersModeling FiltersSources
  IOGeometry IOImage IOLegacy IOPLY IOXML ImagingCore InteractionStyle
  ChartsCore RenderingContext2D RenderingContextOpenGL2 RenderingCore RenderingFreeType
  RenderingOpenGL2 RenderingUI RenderingVolume RenderingVolumeOpenGL2 TestingRendering)
if (CMAKE_SCRIPT_MODE_FILE)
  string(REPLACE ";" " " modules "${VTKICE_VTK_MODULES};Python;WrappingPythonCore")
  message("${modules}")
  return ()
endif ()

set(components ${VTKICE_VTK_MODULES})
if (VTKICE_WRAP_PYTHON)
  list(APPEND components Python WrappingPythonCore)
endif ()
find_package(VTK 9.1 REQUIRED COMPONENTS ${components} OPTIONAL_COMPONENTS opengl mpi)
message(STATUS "VTK Ice builds against VTK ${VTK_VERSION} (${VTK_DIR})")

set(VTKICE_VTK_GL)
if (TARGET VTK::opengl)
  set(VTKICE_VTK_GL VTK::opengl)
endif ()

# A wheel's libraries live in its vtkmodules/ folder.
get_target_property(vtkice_vtk_core VTK::CommonCore IMPORTED_LOCATION_RELEASE)
if (NOT vtkice_vtk_core)
  get_target_property(vtkice_vtk_core VTK::CommonCore LOCATION)
endif ()
if (vtkice_vtk_core MATCHES "/vtkmodules/[^/]+$")
  set(VTKICE_VTK_WHEEL ON)
else ()
  set(VTKICE_VTK_WHEEL OFF)
endif ()

# The libstdc++ ABI of VTK's C++ API: whether libvtksys takes a std::__cxx11 string (the wheels'
# libvtksys holds other __cxx11 names of the libstdc++ parts it carries). Everything that
# passes a std::string to VTK must use VTK's; what passes one to Debian's libraries (OpenImageIO),
# the system's (vtkice_use_system_cxx_abi, VTKIceDefaults.cmake).
get_target_property(vtkice_vtksys VTK::vtksys IMPORTED_LOCATION_RELEASE)
if (NOT vtkice_vtksys)
  get_target_property(vtkice_vtksys VTK::vtksys LOCATION)
endif ()
set(VTKICE_VTK_OLD_CXX_ABI OFF)
if (vtkice_vtksys AND EXISTS "${vtkice_vtksys}")
  file(STRINGS "${vtkice_vtksys}" vtkice_cxx11 LIMIT_COUNT 1
    REGEX "vtksys11SystemTools15GetFilenameNameERKNSt7__cxx11")
  if (NOT vtkice_cxx11)
    set(VTKICE_VTK_OLD_CXX_ABI ON)
  endif ()
endif ()
if (VTKICE_VTK_OLD_CXX_ABI)
  message(STATUS "VTK's libraries use the old libstdc++ ABI: building with _GLIBCXX_USE_CXX11_ABI=0")
  add_compile_definitions(_GLIBCXX_USE_CXX11_ABI=0)
endif ()
