#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The parallel scaling figure of Documentation/paraview.md: distributed_scene.py's benchmark scene
# (500 ice chunks over a terrain) in pvbatch on 1, 2 and 4 ranks, plotted to a PNG.
#   ParaView/Testing/ice_scaling.sh build-paraview out-dir [chunks]
# Run it with the ParaView packages installed (./ice.sh paraview) and an X server (xvfb-run).
set -euo pipefail
build=$(realpath "$1") out=$2 chunks=${3:-500}
here=$(dirname "$(realpath "$0")")
mkdir -p "$out"
export VTKICE_PARAVIEW_PLUGIN="$build/lib/paraview-5.11/plugins/IcePlugin/IcePlugin.so"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for ranks in 1 2 4; do
  rm -f "$out/scaling-$ranks"-*.txt
  mpiexec --allow-run-as-root --oversubscribe -n "$ranks" pvbatch --symmetric \
    "$here/Python/distributed_scene.py" "$out/scaling-$ranks.png" "$out/scaling-$ranks" "$chunks"
done
pvpython "$here/Python/plot_scaling.py" "$out/scaling" "$out/paraview-scaling.png"
