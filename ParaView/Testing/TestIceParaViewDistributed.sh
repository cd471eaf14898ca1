#!/usr/bin/env bash
# The distributed scene (Python/distributed_scene.py) in pvbatch on 1, 2 and 4 MPI ranks: the 2-
# and 4-rank images must equal the 1-rank image, ice included, and every object must be whole
# on one rank (Python/compare_distributed.py). Oversubscribed: correctness, not speed.
set -euo pipefail
pvbatch=$1 pvpython=$2 mpiexec=$3 out=$4
here=$(dirname "$0")
for ranks in 1 2 4; do
  rm -f "$out/distributed-$ranks"-*.txt
  "$mpiexec" --allow-run-as-root --oversubscribe -n "$ranks" "$pvbatch" --symmetric \
    "$here/Python/distributed_scene.py" "$out/distributed-$ranks.png" "$out/distributed-$ranks"
done
"$pvpython" "$here/Python/compare_distributed.py" "$out/distributed"
