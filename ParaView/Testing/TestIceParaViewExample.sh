#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The ParaView example three ways: its pvpython script, its state file loaded in pvpython, and
# the script in pvbatch (one process). All three images must agree, and show ice. The pvpython
# run also saves its state and the view coloured by an array (the documentation's second picture).
set -euo pipefail
pvpython=$1 pvbatch=$2 examples=$3 out=$4
"$pvpython" "$examples/ice_wavelet.py" "$out/example-pvpython.png" "$out/example-saved.pvsm" \
  "$out/example-coloured.png"
"$pvpython" "$(dirname "$0")/Python/render_state.py" "$examples/ice_wavelet.pvsm" \
  "$out/example-state.png"
"$pvbatch" "$examples/ice_wavelet.py" "$out/example-pvbatch.png"
"$pvpython" "$(dirname "$0")/Python/compare_examples.py" "$out/example-pvpython.png" \
  "$out/example-state.png" "$out/example-pvbatch.png"
