#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The long soak: TestIceSoak for 10 000 frames (or $1), reporting every figure even after a
# failure. Needs a build (./ice.sh test-vtk builds one). Runs on the display, or under Xvfb when there
# is none; VTKICE_BACKEND=egl (or osmesa) renders without X instead.
#   Testing/Scripts/soak.sh [FRAMES] [SEED] [WxH]   (./ice.sh soak [FRAMES] [SEED] [WxH])
# WxH: the largest window (the first cycle's; default 320x240), the other sizes scaled with it.
# About 15 minutes for 10 000 frames on 2 cores with llvmpipe. Exit status 0 when no OpenGL error,
# no VTK message, no growth of OpenGL objects and flat memory (TestIceSoak.cxx).
set -euo pipefail
cd "$(dirname "$0")/../.."
build_dir=${VTKICE_BUILD_DIR:-build}
frames=${1:-10000}
seed=${2:-12345}
driver="$build_dir/bin/IceCxxTests"
if [ ! -x "$driver" ]; then
  echo "soak: $driver not found: build first (./ice.sh test-vtk, or cmake --build $build_dir)" >&2
  exit 2
fi
# The memory figures are read with llvmpipe's rasterizer threads off (see TestIceSoak.cxx).
export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
command=("$driver" TestIceSoak --frames "$frames" --seed "$seed" --keep-going)
if [ -n "${3:-}" ]; then
  if [[ ! "$3" =~ ^([0-9]+)x([0-9]+)$ ]]; then
    echo "soak: window size '$3' is not WIDTHxHEIGHT (for example 1280x1024)" >&2
    exit 2
  fi
  command+=(--window "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}")
fi
if [ -n "${VTKICE_BACKEND:-}" ] || { [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; }; then
  "${command[@]}"
else
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "${command[@]}"
fi
