#!/usr/bin/env bash
# `cmake --install` to a prefix, then use that prefix as users would: import vtkice with
# Debian's Python, and build and run a project that calls find_package(VTKIce).
# usage: TestInstall.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -eu
build=$1
source=$2
work=$3
rm -rf "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
  "import vtk, vtkice; m = vtkice.vtkIceMapper(); print('python:', m.GetClassName(), vtkice.__file__)"
cmake -S "$source/Testing/Install" -B "$work/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/ice-consumer"
echo "install: all checks passed"
