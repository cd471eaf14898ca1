#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install` to a prefix, then use that prefix as users would: import vtkice with
# Debian's Python, build and run a project that calls find_package(VTKIce) (with
# VTKIce::Headless), and run the installed ice-render without X.
# usage: TestInstall.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -eu
build=$1
source=$2
work=$3
rm -rf "$work"
prefix="$work/prefix"
# In a VTKICE_SANITIZE build the libraries are instrumented: programs built without the
# sanitizers (Python, the consumer project) need ASan's runtime preloaded.
preload=()
[ -n "${VTKICE_ASAN_RUNTIME:-}" ] && preload=(env "LD_PRELOAD=$VTKICE_ASAN_RUNTIME")
cmake --install "$build" --prefix "$prefix" >/dev/null
PYTHONPATH="$prefix/lib/python3/dist-packages" "${preload[@]}" /usr/bin/python3 -c \
  "import vtk, vtkice; m = vtkice.vtkIceMapper(); print('python:', m.GetClassName(), vtkice.__file__)"
cmake -S "$source/Testing/Install" -B "$work/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
"${preload[@]}" "$work/consumer/ice-consumer"
env -u DISPLAY "${preload[@]}" "$work/consumer/ice-consumer-headless"
# The installed ice-render finds libIceHeadless and renders without X.
env -u DISPLAY "$prefix/bin/ice-render" --size 64x48 --out "$work/installed.png"
echo "install: all checks passed"
