# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# A Debian package of this build (`cpack -G DEB` in the build folder, Documentation/building.md):
# the library, headers, CMake package, Python module, ice-render, ice-bench, presets and
# documentation under /usr, depending on the Debian packages its files link to.
set(VTKICE_PACKAGE_CONTACT "VTK Ice developers <vtkice@example.org>" CACHE STRING
  "Maintainer of the Debian package")
set(doc "${CMAKE_INSTALL_DATADIR}/doc/vtkice")
install(FILES "${PROJECT_SOURCE_DIR}/README.md" "${CMAKE_CURRENT_LIST_DIR}/debian/copyright"
  DESTINATION "${doc}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/Documentation/" DESTINATION "${doc}/Documentation"
  FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
# Debian wants the changelog compressed, reproducibly (no name or time stamp in the gzip header).
configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/changelog" "${PROJECT_BINARY_DIR}/debian/changelog"
  @ONLY)
execute_process(COMMAND gzip -9nf "${PROJECT_BINARY_DIR}/debian/changelog")
install(FILES "${PROJECT_BINARY_DIR}/debian/changelog.gz" DESTINATION "${doc}")

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "vtkice")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "${VTKICE_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "real-time ice rendering for VTK")
set(CPACK_PACKAGE_DESCRIPTION "VTK Ice renders polygonal data as ice in VTK scenes
(Seipel and Nivfors): refraction, reflection and Fresnel mixing of an
environment cube map, two-sided refraction, cracks, air bubbles, bumps,
glistening and a dynamic cube map. With the ice-render and ice-bench
tools and the vtkice Python module for Debian's VTK.")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
# dpkg-shlibdeps names the packages of every library the binaries link to (libvtk9.1, ...).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-vtk9, libvtk9-dev")
# The package's libraries: a shlibs file, and ldconfig by trigger.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${CMAKE_CURRENT_LIST_DIR}/debian/triggers")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "ffmpeg")
# The package's own libraries are found through the rpath of its programs.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${PROJECT_BINARY_DIR}/lib")
set(CPACK_STRIP_FILES ON)
include(CPack)
