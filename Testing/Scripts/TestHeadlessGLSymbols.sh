#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The osmesa back end works only if every GL function that VTK's OpenGL libraries and VTK Ice
# import directly from libGL/libOpenGL is defined by libIceHeadless (IceHeadlessGL.cxx), and if
# programs load libIceHeadless before those libraries. This checks both with nm and readelf, so a
# VTK update that imports a new GL 1.x function fails here rather than rendering black.
# usage: TestHeadlessGLSymbols.sh LIBICEHEADLESS VTK_RENDERING_OPENGL2_LIBRARY RENDERING_ICE_LIBRARY PROGRAM...
set -u
headless=$1
vtk_opengl2=$2
ice=$3
shift 3
failures=0

defined=$(nm -D --defined-only "$headless" | awk '{print $3}' | sort -u)
# VTK's OpenGL libraries beside the one given, each file once (Debian: libvtk*OpenGL2*-9.1.so.1,
# a wheel: libvtk*OpenGL2*.so).
importers=("$ice")
while IFS= read -r library; do
  importers+=("$library")
done < <(for f in "$(dirname "$vtk_opengl2")"/libvtk*OpenGL2*.so*; do readlink -f "$f"; done | sort -u)
imported=$(for library in "${importers[@]}"; do
  nm -D --undefined-only "$library" | awk '{print $2}'
done | grep -E '^gl[A-Z]' | grep -v '^glX' | sort -u)
missing=$(comm -23 <(echo "$imported") <(echo "$defined"))
count=$(echo "$imported" | grep -c .)
if [ -z "$missing" ] && [ "$count" -gt 0 ]; then
  echo "ok   all $count GL functions imported by ${#importers[@]} libraries are routed"
elif [ "$count" -eq 0 ] && [ "${#importers[@]}" -gt 2 ]; then
  # VTK >= 9.4 loads every GL function through glad, from the loader the headless window gives it.
  echo "ok   none of ${#importers[@]} libraries imports a GL function directly (glad): nothing to route"
else
  echo "FAIL not routed by libIceHeadless: $(echo $missing)"; failures=$((failures + 1))
fi
if ! echo "$defined" | grep -qx glXGetProcAddressARB; then
  echo "FAIL libIceHeadless does not define glXGetProcAddressARB"; failures=$((failures + 1))
fi

for program in "$@"; do
  needed=$(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  first=$(echo "$needed" | grep -nE '^(libvtk|libGL|libOpenGL|libRenderingIce)' | head -1 | cut -d: -f1)
  own=$(echo "$needed" | grep -n '^libIceHeadless' | cut -d: -f1)
  if [ -n "$own" ] && [ -n "$first" ] && [ "$own" -lt "$first" ]; then
    echo "ok   $(basename "$program") loads libIceHeadless before VTK and GL"
  else
    echo "FAIL $(basename "$program") does not load libIceHeadless first: $(echo $needed)"
    failures=$((failures + 1))
  fi
done

if [ "$failures" -eq 0 ]; then echo "GL routing: all checks passed"; fi
exit "$failures"
