#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh vtk-sdk PREFIX: the SDK of a `vtk` wheel (headers, CMake package, wrapping tools) made
# from VTK's source, for building VTK Ice against the wheel where VTK's own `vtk-sdk` wheel cannot
# be had (PyPI serves it for macOS only). No VTK library is compiled: the SDK's imported targets
# point at the wheel's libraries (PREFIX/vtkmodules and PREFIX/build/... link to its vtkmodules/).
#   VTKICE_PYTHON      the Python whose vtk wheel the SDK is for (default: python3)
#   VTKICE_VTK_SOURCE  VTK's source of the wheel's release: a .tar.xz/.tar.gz archive or a folder
#   VTKICE_SDK_WORK    a folder kept for the next SDK (the source unpacked, VTK's configured
#                      build): another Python's SDK is then a configure and an install
# Then: CMAKE_PREFIX_PATH=PREFIX pip install .   (with that Python's pip)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)

prefix=${1:-}
if [ -z "$prefix" ] || [ $# -ne 1 ]; then
  echo "usage: VTKICE_VTK_SOURCE=vtk-X.Y.Z-source.tar.xz VTKICE_PYTHON=venv/bin/python ./ice.sh vtk-sdk PREFIX" >&2
  exit 2
fi
python=${VTKICE_PYTHON:-python3}
source=${VTKICE_VTK_SOURCE:-}
if [ -z "$source" ] || [ ! -e "$source" ]; then
  echo "vtk-sdk: VTKICE_VTK_SOURCE must name VTK's source (archive or folder) of the wheel's release${source:+, not '$source'}" >&2
  exit 2
fi
if ! wheel=$("$python" -c 'import os, sys, sysconfig, vtkmodules
from vtkmodules.vtkCommonCore import vtkVersion
print(vtkVersion.GetVTKVersion()); print(os.path.realpath(os.path.dirname(vtkmodules.__file__)))
print(sysconfig.get_platform() + "-" + sys.implementation.cache_tag)' 2>&1); then
  echo "vtk-sdk: $python cannot import the vtk wheel (pip install vtk): ${wheel##*$'\n'}" >&2
  exit 2
fi
version=$(sed -n 1p <<<"$wheel")
modules_dir=$(sed -n 2p <<<"$wheel")
platlib=lib.$(sed -n 3p <<<"$wheel")
python_path=$(command -v "$python")
python_path="$(cd "$(dirname "$python_path")" && pwd)/$(basename "$python_path")"
if ! ls "$modules_dir"/libvtkCommonCore*.so >/dev/null 2>&1; then
  echo "vtk-sdk: $python's vtkmodules ($modules_dir) is not a vtk wheel's (no libvtkCommonCore there;" \
    "Debian's python3-vtk9?): use a venv with pip install vtk" >&2
  exit 2
fi
prefix=$(realpath -m "$prefix")
mkdir -p "$(dirname "$prefix")"
if [ -n "${VTKICE_SDK_WORK:-}" ]; then
  work=$(realpath -m "$VTKICE_SDK_WORK")
  mkdir -p "$work"
else
  work=$(mktemp -d "$prefix.work.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
echo "vtk-sdk: VTK $version for $modules_dir, from $source, into $prefix"

# 1. The source, checked to be the wheel's release.
if [ -d "$source" ]; then
  src=$(cd "$source" && pwd)
else
  # Unpacked once per archive (its path, size and time) in a kept work folder.
  stamp="$(realpath "$source") $(stat -c '%s %Y' "$source")"
  if [ "$(cat "$work/source.stamp" 2>/dev/null)" != "$stamp" ]; then
    rm -rf "$work/source" "$work/build" "$work/source.stamp"
    mkdir -p "$work/source"
    tar -xf "$source" -C "$work/source"
    echo "$stamp" >"$work/source.stamp"
  fi
  src=$(find "$work/source" -mindepth 1 -maxdepth 1 -type d | head -n 1)
fi
src_version=$(sed -nE 's/^set\(VTK_(MAJOR|MINOR|BUILD)_VERSION ([0-9]+)\)$/\2/p' "$src/CMake/vtkVersion.cmake" | paste -sd.)
if [ "$src_version" != "$version" ]; then
  echo "vtk-sdk: the source is VTK $src_version but the wheel is $version: a wheel's SDK must be of its release" >&2
  exit 1
fi

# 2. Configure as VTK configures its wheels, with only the modules VTK Ice uses (the SDK has
# headers and wrapping hierarchies of enabled modules only) and the wheels' old libstdc++ ABI.
modules=$(cmake -P "$top/CMake/VTKIceVTK.cmake" 2>&1)
options=()
for module in $modules; do options+=("-DVTK_MODULE_ENABLE_VTK_$module=YES"); done
for group in Imaging MPI Qt Rendering StandAlone Views Web; do
  options+=("-DVTK_GROUP_ENABLE_$group=DONT_WANT")
done
# A kept build is configured afresh (another Python's FindPython results); ninja then redoes only
# what changed.
rm -f "$work/build/CMakeCache.txt"
cmake -G Ninja -S "$src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DVTK_WHEEL_BUILD=ON -DVTK_INSTALL_SDK=ON -DVTK_WRAP_PYTHON=ON -DVTK_WRAP_SERIALIZATION=ON \
  -DVTK_DEBUG_LEAKS=OFF -DVTK_DISPATCH_SOA_ARRAYS=ON -DVTK_SMP_IMPLEMENTATION_TYPE=Sequential \
  -DVTK_BUILD_TESTING=OFF -DVTK_BUILD_ALL_MODULES=OFF -DCMAKE_CXX_FLAGS=-D_GLIBCXX_USE_CXX11_ABI=0 \
  -DPython3_EXECUTABLE="$python_path" "${options[@]}" >"$work/configure.log" 2>&1 || {
  tail -n 30 "$work/configure.log" >&2
  exit 1
}

# 3. Only the wrapping tools (C) and the hierarchy files: never the library chain. Checked first:
# a C++ compile step here would mean VTK's libraries were about to be built.
cd "$work/build"
targets=(WrapHierarchy WrapPython WrapPythonInit WrapSerDes WrapJava WrapJavaScript ParseJava)
targets+=($(ninja -t targets all | sed -nE 's/^([A-Za-z0-9]+-hierarchy): phony$/\1/p'))
if ninja -n "${targets[@]}" | grep -q "Building CXX"; then
  echo "vtk-sdk: building the wrapping tools would compile VTK's C++ libraries; stopping" >&2
  exit 1
fi
ninja "${targets[@]}" >"$work/tools.log" 2>&1 || {
  tail -n 30 "$work/tools.log" >&2
  exit 1
}
# The generated public headers (shader sources, ...): each one `cmake -P` step, run alone. Made
# from the source only: those a kept work folder has stay.
ninja -t targets all | sed -nE 's/^([^/][^:]*\.(h|hxx|txx)): CUSTOM_COMMAND$/\1/p' |
  while read -r header; do
    [ ! -s "$header" ] || continue
    command=$(ninja -t commands -s "$header")
    case "$command" in
      *"cmake "*"-P "*) bash -c "$command" ;;
      *) echo "vtk-sdk: $header is not made by a cmake -P step" >&2; exit 1 ;;
    esac
  done

# 4. Install the development files; the tools beside them; the wheel's libraries by links.
rm -rf "$prefix"
cmake --install . --component development --prefix "$prefix" >"$work/install.log" 2>&1 || {
  grep -A3 "CMake Error" "$work/install.log" >&2
  exit 1
}
mkdir -p "$prefix/bin" "$prefix/build/$platlib"
cp bin/vtkWrap* bin/vtkParse* "$prefix/bin/"
cp "build/$platlib/vtkmodules/libvtkWrappingTools.so" "$prefix/bin/"
# Imported by the SDK's targets, never run by a build against it.
printf '#!/bin/sh\nexit 1\n' >"$prefix/bin/vtkProbeOpenGLVersion"
chmod +x "$prefix/bin/vtkProbeOpenGLVersion"
ln -s "$modules_dir" "$prefix/build/$platlib/vtkmodules"
ln -s "$modules_dir" "$prefix/vtkmodules"
# find_package(VTK) with CMAKE_PREFIX_PATH=PREFIX: lib/cmake/vtk/ leads to the wheel layout.
data="vtk-$version.data"
mkdir -p "$prefix/lib/cmake/vtk"
for file in vtk-config.cmake vtk-config-version.cmake; do
  printf 'include("${CMAKE_CURRENT_LIST_DIR}/../../../%s/headers/cmake/%s")\n' "$data" "$file" \
    >"$prefix/lib/cmake/vtk/$file"
done
echo "vtk-sdk: done ($(du -sh "$prefix" | cut -f1)). Build VTK Ice against the wheel with:"
echo "  CMAKE_PREFIX_PATH=$prefix $(dirname "$python_path")/pip install $top"
