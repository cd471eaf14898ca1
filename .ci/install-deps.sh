#!/usr/bin/env bash
# Installs the Debian packages VTK Ice needs to build, test and render headless
# (Xvfb for the X tests; Mesa EGL and OSMesa for rendering without X), to make and check its
# Debian package (dpkg-dev, lintian) and the turntable's video (ffmpeg).
# Skips apt-get entirely when every package is already installed.
#   .ci/install-deps.sh            Debian's VTK 9.1 and everything the main build and tests use
#   .ci/install-deps.sh paraview   Debian's ParaView 5.11 (with its own VTK 9.2) for the plugin
#   .ci/install-deps.sh fuzz       the first list and clang with libFuzzer (./ice.sh fuzz)
#   .ci/install-deps.sh web        the first list and Debian's Chromium with its WebDriver: the web
#                                  viewer's browser tests (./ice.sh wheel, ./ice.sh web)
# The two VTKs cannot be installed together: apt replaces one by the other, so each stage calls
# this first and finds what it needs whatever ran before.
set -euo pipefail
recommends=--no-install-recommends
if [ "${1:-}" = paraview ]; then
  # The GUI test's screenshot uses xwd (x11-apps) and ImageMagick; the MPI test mpiexec. ParaView's recommended
  # packages (Qt's platform and image plugins among them) are what the GUI was tested with.
  packages=(
    paraview paraview-dev python3-paraview python3-dev cmake ninja-build g++ pkg-config
    libglm-dev libopenimageio-dev xvfb xauth libgl1-mesa-dri x11-apps imagemagick openmpi-bin
  )
  recommends=
else
  packages=(
    libvtk9-dev python3-vtk9 cmake ninja-build g++ pkg-config
    libglm-dev libopenimageio-dev
    xvfb xauth libgl1-mesa-dri libegl-dev libegl-mesa0 libosmesa6-dev
    dpkg-dev lintian ffmpeg
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
echo "Installing missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
# A run interrupted during an install (Ctrl-C) leaves dpkg half-configured; finish that first.
$SUDO dpkg --configure -a
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq $recommends "${missing[@]}"
