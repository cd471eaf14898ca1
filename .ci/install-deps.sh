#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian packages VTK Ice needs to build, test and render headless
# (Xvfb for the X tests; Mesa EGL and OSMesa for rendering without X), to make and check its
# Debian package (dpkg-dev, lintian), the turntable's video (ffmpeg) and ccache (./ice.sh's builds).
# Skips apt-get entirely when every package is already installed.
#   .ci/install-deps.sh            Debian's VTK 9.1 and everything the main build and tests use
#   .ci/install-deps.sh paraview   Debian's ParaView 5.11 (with its own VTK 9.2) for the plugin
#   .ci/install-deps.sh fuzz       the first list and clang with libFuzzer (./ice.sh fuzz)
#   .ci/install-deps.sh web        the first list and Debian's Chromium with its WebDriver: the web
#                                  viewer's browser tests (./ice.sh wheel, ./ice.sh web)
# The two VTKs cannot be installed together: apt replaces one by the other, so each stage calls
# this first and finds what it needs whatever ran before.
set -euo pipefail
recommends=
if [ "${1:-}" = paraview ]; then
  # The GUI test's screenshot uses xwd (x11-apps) and ImageMagick; the MPI test mpiexec. ParaView's recommended
  # packages (Qt's platform and image plugins among them) are what the GUI was tested with.
  packages=(
    paraview paraview-dev python3-paraview python3-dev cmake ninja-build g++ pkg-config ccache
    libglm-dev libopenimageio-dev xvfb xauth libgl1-mesa-dri x11-apps imagemagick openmpi-bin
  )
  recommends=yes
else
  packages=(
    libvtk9-dev python3-vtk9 python3-numpy cmake ninja-build g++ pkg-config ccache
    libglm-dev libopenimageio-dev
    xvfb xauth libgl1-mesa-dri libegl-dev libegl-mesa0 libosmesa6-dev
    dpkg-dev lintian ffmpeg
    # The photographed HDR panoramas ice-render --env finds by name (CC0, blender's data).
    blender-data
  )
  if [ "${1:-}" = fuzz ]; then
    packages+=(clang-14 libclang-rt-14-dev)
  fi
  if [ "${1:-}" = web ]; then
    packages+=(chromium chromium-driver)
  fi
fi
# VTKICE_SKIP_PACKAGES: packages a Debian suite does not have (sid: libosmesa6-dev).
missing=()
for p in "${packages[@]}"; do
  case " ${VTKICE_SKIP_PACKAGES:-} " in *" $p "*) continue ;; esac
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
case "${1:-}" in
  paraview) step="the ParaView stage's packages" ;;
  fuzz) step="the fuzzing stage's packages" ;;
  web) step="the wheel stage's packages (with the browser)" ;;
  *) step="the VTK stage's packages" ;;
esac
# Waits for another program's hold on the package lock, and names the step if it fails.
bash "$(dirname "$0")/apt-install.sh" "$step" ${recommends:+--recommends} "${missing[@]}"
