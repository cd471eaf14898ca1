#!/usr/bin/env bash
# Installs the Debian packages VTK Ice needs to build, test and render headless
# (Xvfb for the X tests; Mesa EGL and OSMesa for rendering without X), to make and check its
# Debian package (dpkg-dev, lintian) and the turntable's video (ffmpeg).
# Skips apt-get entirely when every package is already installed.
set -euo pipefail
packages=(
  libvtk9-dev python3-vtk9 cmake ninja-build g++ pkg-config
  libglm-dev libopenimageio-dev
  xvfb xauth libgl1-mesa-dri libegl-dev libegl-mesa0 libosmesa6-dev
  dpkg-dev lintian ffmpeg
)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "Installing missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
