#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ice-render's --backend: the default command without DISPLAY writes ice.png through EGL with the
# picture of the X path, and so does osmesa; auto picks x, then egl, then osmesa; a forced back
# end that is not available gives one line and exit 1.
# Needs an X display (run under Xvfb); exits 125 (skipped) without one.
# A build without the osmesa back end (OSMESA=0: no GL/osmesa.h, Debian sid) refuses it instead.
# usage: TestIceRenderBackends.sh ICE_RENDER WORK_DIR BASELINE COMPARE_IMAGES_PY OSMESA
set -u
ice_render=$1
work=$2
baseline=$3
compare=$4
osmesa=${5:-1}
if [ -z "${DISPLAY:-}" ]; then echo "DISPLAY is not set: skipped"; exit 125; fi
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
unset VTKICE_BACKEND VTKICE_EGL_DEVICE VTKICE_OSMESA_LIBRARY
failures=0

# expect_ok NAME EXPECTED_STDOUT_TEXT COMMAND...
expect_ok() {
  local name=$1 text=$2; shift 2
  if "$@" >out.txt 2>err.txt && [ ! -s err.txt ] && grep -qF "$text" out.txt; then
    echo "ok   $name: $(cat out.txt)"
  else
    echo "FAIL $name: exit $?, stdout: $(cat out.txt), stderr: $(cat err.txt)"
    failures=$((failures + 1))
  fi
}

# expect_error NAME PATTERN COMMAND...: exit 1, one stderr line "ice-render: ...PATTERN"
expect_error() {
  local name=$1 pattern=$2; shift 2
  "$@" >out.txt 2>err.txt
  local code=$?
  local lines
  lines=$(wc -l <err.txt)
  if [ "$code" -eq 1 ] && [ "$lines" -eq 1 ] && grep -q "^ice-render: $pattern" err.txt; then
    echo "ok   $name: $(cat err.txt)"
  else
    echo "FAIL $name: exit $code, $lines stderr line(s): $(cat err.txt)"
    failures=$((failures + 1))
  fi
}

compare() {
  /usr/bin/python3 "$compare" "$@" || failures=$((failures + 1))
}

# The criterion: no X at all, the default command, the same picture as the X path.
mkdir -p headless && cd headless || exit 1
expect_ok "env -u DISPLAY ice-render" "wrote ice.png (1024x768, model cube, back end egl)" \
  env -u DISPLAY "$ice_render"
cd .. || exit 1
expect_ok "ice-render --backend x" "back end x" "$ice_render" --backend x --out ice-x.png
compare headless/ice.png ice-x.png
if [ "$osmesa" = 1 ]; then
  expect_ok "ice-render --backend osmesa without DISPLAY" "back end osmesa" \
    env -u DISPLAY "$ice_render" --backend osmesa --out ice-osmesa.png
  compare ice-osmesa.png ice-x.png
fi
# The X render is the reviewed picture (the baseline of Cxx.TestIceTeapot is the same scene with
# the library's defaults: the paper preset).
expect_ok "ice-render --backend x at 400x300" "back end x" \
  "$ice_render" --backend x --model teapot --env sky --preset paper --size 400x300 --out x-400x300.png
compare x-400x300.png "$baseline" --alternatives

# auto: x with a display, egl without, osmesa without EGL.
expect_ok "auto with DISPLAY" "back end x" "$ice_render" --size 64x48 --out auto-x.png
expect_ok "auto without DISPLAY" "back end egl" env -u DISPLAY "$ice_render" --size 64x48 --out auto-egl.png
if [ "$osmesa" = 1 ]; then
  expect_ok "auto without DISPLAY and EGL" "back end osmesa" \
    env -u DISPLAY VTKICE_EGL_DEVICE=99 "$ice_render" --size 64x48 --out auto-osmesa.png
  expect_ok "VTKICE_BACKEND=osmesa" "back end osmesa" \
    env VTKICE_BACKEND=osmesa "$ice_render" --size 64x48 --out env-osmesa.png
fi

# Forced back ends that are not available here.
expect_error "x without DISPLAY" "x back end unavailable: DISPLAY is not set" \
  env -u DISPLAY "$ice_render" --backend x
expect_error "x with a display that does not exist" "x back end unavailable: cannot open display" \
  env DISPLAY=:4095 "$ice_render" --backend x
expect_error "egl with a device that does not exist" "egl back end unavailable: EGL device 99" \
  env VTKICE_EGL_DEVICE=99 "$ice_render" --backend egl
if [ "$osmesa" = 1 ]; then
  expect_error "osmesa without its library" "osmesa back end unavailable: .*libOSMesa" \
    env VTKICE_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8 "$ice_render" --backend osmesa
else
  expect_error "osmesa in a build without it" "osmesa back end unavailable: this build has no osmesa" \
    "$ice_render" --backend osmesa
  expect_error "VTKICE_BACKEND=osmesa in a build without it" "osmesa back end unavailable" \
    env VTKICE_BACKEND=osmesa "$ice_render" --size 64x48 --out env-osmesa.png
fi
expect_error "auto with none" "no rendering back end works (x: DISPLAY is not set; egl: .*; osmesa: " \
  env -u DISPLAY VTKICE_EGL_DEVICE=99 VTKICE_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8 "$ice_render"
expect_error "--interactive without X" "--interactive needs the x back end" \
  env -u DISPLAY "$ice_render" --interactive
"$ice_render" --backend vulkan >/dev/null 2>err.txt
code=$?
if [ "$code" -eq 2 ] && grep -q "^ice-render: bad --backend 'vulkan'" err.txt; then
  echo "ok   unknown back end: $(cat err.txt)"
else
  echo "FAIL unknown back end: exit $code, $(cat err.txt)"; failures=$((failures + 1))
fi

if [ "$failures" -eq 0 ]; then echo "ice-render back ends: all checks passed"; fi
exit "$failures"
