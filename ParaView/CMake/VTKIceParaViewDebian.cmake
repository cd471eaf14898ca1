# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Workarounds for Debian's ParaView packages, included before find_package(ParaView). They change
# nothing on the system and nothing where the packages are right (Debian 12's ParaView 5.11).

# Debian 13's paraview-dev 5.13.2+dfsg-3 and sid's 6.1.1+dfsg1-3: the exported targets of the
# Python extension modules name paraview/modules/vtkX.so, paraview/incubator/vtkX.so (45 files)
# and, in 5.13, its own VTK's vtkmodules/vtkX.so (135), where the packages ship
# vtkX.cpython-3XY-x86_64-linux-gnu.so. CMake's generated targets file ends by
# checking that every file it names exists, and stops the configure when one does not. The plugin
# links none of these modules: just before that check reads its list of targets, a missing vtkX.so
# with exactly one shipped vtkX.cpython-*.so beside it is replaced by that file, in the list and in
# the target's location.
function (_vtkice_shipped_python_modules variable access targets)
  if (NOT access STREQUAL "READ_ACCESS")
    return ()
  endif ()
  foreach (target IN LISTS targets)
    set(files_variable "_cmake_import_check_files_for_${target}")
    set(files "")
    set(changed FALSE)
    foreach (file IN LISTS "${files_variable}")
      if (NOT EXISTS "${file}" AND file MATCHES "^(.*)\\.so$")
        file(GLOB shipped "${CMAKE_MATCH_1}.cpython-*.so")
        list(LENGTH shipped count)
        if (count EQUAL 1)
          get_target_property(configurations "${target}" IMPORTED_CONFIGURATIONS)
          foreach (configuration IN LISTS configurations)
            get_target_property(location "${target}" "IMPORTED_LOCATION_${configuration}")
            if (location STREQUAL file)
              set_target_properties("${target}" PROPERTIES
                "IMPORTED_LOCATION_${configuration}" "${shipped}")
            endif ()
          endforeach ()
          set(file "${shipped}")
          set(changed TRUE)
        endif ()
      endif ()
      list(APPEND files "${file}")
    endforeach ()
    if (changed)
      set("${files_variable}" "${files}" PARENT_SCOPE)
    endif ()
  endforeach ()
endfunction ()
variable_watch(_cmake_import_check_targets _vtkice_shipped_python_modules)

# Debian 13's paraview-dev 5.13.2+dfsg-3 (ParaView with its own VTK): the link interfaces of that
# VTK's hdf5 and netcdf modules name hdf5::hdf5 and NetCDF::NetCDF, which ParaView's CMake package
# does not define (it asks its VTK for the components of ParaView's modules only), and CMake stops
# when it generates. Called after find_package(ParaView): finding those two components of the same
# VTK defines them. Not with 5.11, which generates without them, nor sid's 6.1 on Debian's VTK.
function (vtkice_paraview_debian_vtk_dependencies)
  if (ParaView_VERSION VERSION_LESS 5.13 OR NOT VTK_DIR STREQUAL "${ParaView_DIR}/vtk")
    return ()
  endif ()
  if ((TARGET VTK::hdf5 AND NOT TARGET hdf5::hdf5) OR
      (TARGET VTK::netcdf AND NOT TARGET NetCDF::NetCDF))
    # The HDF5 ParaView links (libhdf5_openmpi), not the serial one found first.
    set(HDF5_PREFER_PARALLEL ON)
    find_package(VTK REQUIRED COMPONENTS hdf5 netcdf)
  endif ()
endfunction ()
