# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# pip install . (SKBUILD): the vtkice package must sit beside the vtk wheel of the Python that
# builds it and use that wheel's VTK. Stops with what to do when CMake found another VTK (Debian's
# in /usr, an SDK of another release) or none.
if (NOT VTKICE_VTK_WHEEL)
  message(FATAL_ERROR
    "pip install: CMake found VTK ${VTK_VERSION} in ${VTK_DIR}, which is not a vtk wheel's SDK. "
    "Install the vtk wheel in this Python (pip install vtk), make its SDK "
    "(VTKICE_PYTHON=${Python3_EXECUTABLE} ./ice.sh vtk-sdk PREFIX) and build with "
    "CMAKE_PREFIX_PATH=PREFIX pip install .")
endif ()
execute_process(
  COMMAND "${Python3_EXECUTABLE}" -c
    "import os, vtkmodules; from vtkmodules.vtkCommonCore import vtkVersion; print(vtkVersion.GetVTKVersion()); print(os.path.realpath(os.path.dirname(vtkmodules.__file__)))"
  OUTPUT_VARIABLE vtkice_wheel
  ERROR_VARIABLE vtkice_wheel_error
  RESULT_VARIABLE vtkice_wheel_result
  OUTPUT_STRIP_TRAILING_WHITESPACE)
if (vtkice_wheel_result)
  message(FATAL_ERROR
    "pip install: ${Python3_EXECUTABLE} cannot import the vtk wheel (pip install vtk==${VTK_VERSION}): "
    "${vtkice_wheel_error}")
endif ()
string(REPLACE "\n" ";" vtkice_wheel "${vtkice_wheel}")
list(GET vtkice_wheel 0 vtkice_wheel_version)
list(GET vtkice_wheel 1 vtkice_wheel_dir)
get_filename_component(vtkice_sdk_modules "${vtkice_vtk_core}" DIRECTORY)
get_filename_component(vtkice_sdk_modules "${vtkice_sdk_modules}" REALPATH)
if (NOT vtkice_wheel_version STREQUAL VTK_VERSION)
  message(FATAL_ERROR
    "pip install: the VTK SDK CMake found is VTK ${VTK_VERSION} (${VTK_DIR}) but this Python's vtk "
    "wheel is ${vtkice_wheel_version}: a wheel's SDK must be of the same release "
    "(./ice.sh vtk-sdk makes the one that matches).")
endif ()
if (NOT vtkice_sdk_modules STREQUAL vtkice_wheel_dir)
  message(FATAL_ERROR
    "pip install: the VTK SDK CMake found (${VTK_DIR}) links against ${vtkice_sdk_modules}, not this "
    "Python's wheel in ${vtkice_wheel_dir}: make the SDK for this Python "
    "(VTKICE_PYTHON=${Python3_EXECUTABLE} ./ice.sh vtk-sdk PREFIX).")
endif ()
message(STATUS "pip install: beside the vtk ${vtkice_wheel_version} wheel in ${vtkice_wheel_dir}")
