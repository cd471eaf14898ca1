#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ice-render's command line: renders on good input; on bad input prints one line starting with
# "ice-render:" and exits non-zero, never crashing.
# usage: TestIceRenderCli.sh ICE_RENDER WORK_DIR
set -u
ice_render=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

expect_ok() {
  local name=$1; shift
  if "$ice_render" "$@" >out.txt 2>err.txt && [ ! -s err.txt ]; then
    echo "ok   $name"
  else
    echo "FAIL $name: exit $?, stderr: $(cat err.txt)"; failures=$((failures + 1))
  fi
}

expect_error() {
  local name=$1 pattern=$2; shift 2
  "$ice_render" "$@" >out.txt 2>err.txt
  local code=$?
  local lines
  lines=$(wc -l <err.txt)
  if [ "$code" -ne 0 ] && [ "$code" -lt 128 ] && [ "$lines" -eq 1 ] &&
     grep -q "^ice-render: .*$pattern" err.txt; then
    echo "ok   $name: $(cat err.txt)"
  else
    echo "FAIL $name: exit $code, $lines stderr line(s): $(cat err.txt)"; failures=$((failures + 1))
  fi
}

expect_ok "sphere to a named file" --model sphere --size 64x48 --out sphere.png
[ -s sphere.png ] || { echo "FAIL sphere.png was not written"; failures=$((failures + 1)); }
expect_ok "block, test pattern, one-sided" --model block --env test --one-sided --size 64x48 --out block.png
/usr/bin/python3 - <<'PY'
import vtk
s = vtk.vtkSphereSource()
w = vtk.vtkSTLWriter(); w.SetInputConnection(s.GetOutputPort()); w.SetFileName("ball.stl"); w.Write()
w = vtk.vtkXMLPolyDataWriter(); w.SetInputConnection(s.GetOutputPort()); w.SetFileName("ball.vtp"); w.Write()
PY
expect_ok "STL file, static environment" --model ball.stl --static --size 64x48 --out stl.png
expect_ok "VTP file" --model ball.vtp --size 64x48 --out vtp.png
mkdir -p faces && for f in px nx py ny pz nz; do cp sphere.png faces/$f.png; done
expect_error "non-square faces" "square" --env faces --size 64x48 --out x.png
mkdir -p cube && for f in px nx py ny pz nz; do "$ice_render" --model sphere --size 32x32 --out cube/$f.png >/dev/null; done
expect_ok "six face images" --env cube --size 64x48 --out cube.png
mkdir -p incomplete && cp cube/px.png cube/nx.png cube/py.png cube/ny.png cube/pz.png incomplete/
expect_error "missing face image" "no face image 'nz" --env incomplete --size 64x48 --out x.png
# Single images: the aspect ratio picks the layout (renders of the right sizes serve as images).
"$ice_render" --size 128x96 --out hcross.png >/dev/null
expect_ok "horizontal cross image" --env hcross.png --size 64x48 --out hcross-env.png
"$ice_render" --size 96x128 --out vcross.png >/dev/null
expect_ok "vertical cross image" --env vcross.png --size 64x48 --out vcross-env.png
"$ice_render" --size 128x64 --out panorama.png >/dev/null
expect_ok "panorama PNG" --env panorama.png --size 64x48 --out panorama-env.png
# A Radiance HDR panorama with values above 1 (flat RGBE scanlines, no run-length coding).
/usr/bin/python3 - <<'PY'
import math
width, height = 64, 32
with open("panorama.hdr", "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
    for y in range(height):
        for x in range(width):
            value = 0.2 + 3.0 * (1.0 - y / height)  # brighter toward the top, up to 3.2
            mantissa, exponent = math.frexp(value)
            m = int(mantissa * 256)
            f.write(bytes([m, m, m // 2, exponent + 128]))
PY
expect_ok "HDR panorama" --env panorama.hdr --size 64x48 --out hdr-env.png
"$ice_render" --size 50x40 --out odd.png >/dev/null
expect_error "image of no cube map layout" "no cube map layout" --env odd.png --size 64x48 --out x.png
printf 'not an image\n' >garbage.png
expect_error "corrupt environment image" "Cannot read environment image" --env garbage.png --size 64x48 --out x.png

expect_error "unknown option" "unknown argument '--frobnicate' (see --help)" --frobnicate
expect_error "a misspelled option names the nearest" "'--milkines' (did you mean --milkiness?)" \
  --milkines 0.5
expect_error "a misspelled switch names the nearest" "(did you mean --no-glistening?)" --no-glisten
expect_error "NAME=VALUE says the value follows a space" "(the value follows a space: --eta 0.8)" \
  --eta=0.8
expect_error "SWITCH=VALUE says the switch takes none" "(--static takes no value)" --static=1
# --help: every look and camera option shows its default beside its range or choices: the default
# preset's (ice-cube) where it names the setting, else the library's.
"$ice_render" --help >help.txt 2>&1
settings=$(awk '/^Look and camera/ {on = 1; next} on && /^  --/' help.txt)
without=$(printf '%s\n' "$settings" | grep -v ", default" || true)
if [ "$(printf '%s\n' "$settings" | wc -l)" -ge 30 ] && [ -z "$without" ] &&
   grep -q '^  --milkiness \[0, 1\], default 0.4$' help.txt &&
   grep -q '^  --fresnel-power \[0, 1000000\], default 3$' help.txt &&
   grep -q 'default ice-cube' help.txt &&
   grep -q '^  --cube-map, --no-cube-map, default on (off with --static)$' help.txt &&
   grep -q '^  --view-angle \[1, 179\], default: framing the model$' help.txt; then
  echo "ok   --help shows each setting's default beside its range"
else
  echo "FAIL --help: settings without a default: $without"; failures=$((failures + 1))
fi
expect_error "missing value" "needs a value" --model
expect_error "bad size" "bad --size" --size 10by10
expect_error "missing model file" "cannot open" --model does-not-exist.stl
expect_error "unknown model type" "unknown model" --model notes.txt
printf 'this is not an STL file\n' >garbage.stl
expect_error "corrupt STL" "model" --model garbage.stl
printf '<VTKFile broken' >garbage.vtp
expect_error "corrupt VTP" "model" --model garbage.vtp
expect_error "missing environment" "environment" --env no-such-folder
expect_error "unwritable output" "cannot write" --out /no/such/dir/ice.png

if [ "$failures" -eq 0 ]; then echo "ice-render CLI: all checks passed"; fi
exit "$failures"
