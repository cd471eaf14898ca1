#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The distributed scene (Python/distributed_scene.py) in pvbatch on 1, 2 and 4 MPI ranks: the 2-
# and 4-rank images must equal the 1-rank image, ice included, and every object must be whole
# on one rank; with a translucent sphere added, 2 ranks must still render the 1-rank image
# (Python/compare_distributed.py). Oversubscribed: correctness, not speed.
set -euo pipefail
pvbatch=$1 pvpython=$2 mpiexec=$3 out=$4
here=$(dirname "$0")
scene() { # ranks name [translucent]
  rm -f "$out/$2-$1"-*.txt
  "$mpiexec" --allow-run-as-root --oversubscribe -n "$1" "$pvbatch" --symmetric \
    "$here/Python/distributed_scene.py" "$out/$2-$1.png" "$out/$2-$1" ${3:-}
}
for ranks in 1 2 4; do scene "$ranks" distributed; done
# With a translucent sphere: ParaView's ordered compositing (1 and 2 ranks).
for ranks in 1 2; do scene "$ranks" translucent translucent; done
"$pvpython" "$here/Python/compare_distributed.py" "$out/distributed" "$out/translucent"
