#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The ParaView application with the plugin: a rounded block shown as Ice in an Ice View, with its
# Ice property group; a screenshot of the whole screen (the window) goes to $out/paraview-gui.png.
set -euo pipefail
paraview=$1 plugin_dir=$2 out=$3
result="$out/gui-result.txt"
rm -f "$result" "$out/ice.png" "$out/hidden.png" "$out/forest.png"
# Debian's blender-data forest panorama as the view's skybox where it is installed (ParaView reads
# no EXR: ImageMagick writes it as an sRGB PNG); the view's gradient without it.
forest=/usr/share/blender/datafiles/studiolights/world/forest.exr
panorama=
if [ -f "$forest" ] && convert "$forest" -colorspace sRGB "$out/forest.png"; then
  panorama=$out/forest.png
fi
# The script uses the other tests' helpers (ice_paraview_helpers.py beside it).
PYTHONPATH="$(dirname "$0")/Python${PYTHONPATH:+:$PYTHONPATH}" \
  VTKICE_GUI_RESULT="$result" VTKICE_GUI_PANORAMA="$panorama" PV_PLUGIN_PATH="$plugin_dir" \
  "$paraview" -geometry 1280x1400+0+0 --dr --script="$(dirname "$0")/Python/gui_script.py" \
  > "$out/gui.log" 2>&1 &
pid=$!
for _ in $(seq 120); do [ -s "$result" ] && break; sleep 1; done
sleep 3 # the window finishes drawing
xwd -root -silent > "$out/paraview-gui.xwd"
kill "$pid"
wait "$pid" 2>/dev/null || true
cat "$result" 2>/dev/null || { echo "FAIL the GUI script did not run"; cat "$out/gui.log"; exit 1; }
status=0
grep -q "^representations: .*\bIce\b" "$result" || { echo "FAIL no Ice representation"; status=1; }
grep -q "^representation: 'Ice'" "$result" || { echo "FAIL the display is not Ice"; status=1; }
grep -q "^ice properties: True" "$result" || { echo "FAIL no Ice properties"; status=1; }
# The ice shows: against the same view with the sphere hidden, at least 4 000 pixels differ by
# more than 10 % (98 847 of the view's 1.1 million; an Ice representation that drew nothing
# passed before).
differ=$(compare -metric AE -fuzz 10% "$out/ice.png" "$out/hidden.png" null: 2>&1 || true)
count=$(echo "$differ" | grep -oE '^[0-9]+' || echo 0)
echo "pixels the ice changes: $count"
[ "$count" -ge 4000 ] || { echo "FAIL the ice does not show ($differ)"; status=1; }
if grep -q "ERR|" "$out/gui.log"; then echo "FAIL errors in the GUI's log:"; grep "ERR|" "$out/gui.log"; status=1; fi
convert "$out/paraview-gui.xwd" -crop 1280x1400+0+0 "$out/paraview-gui.png"
rm -f "$out/paraview-gui.xwd"
exit "$status"
