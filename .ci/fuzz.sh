#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh fuzz [seconds]: the libFuzzer harnesses of Testing/Fuzz, each for `seconds` (default 60),
# all at once, from their seeds (Testing/Fuzz/Corpus/) and what earlier runs here found
# (build-fuzz/corpus/). Builds with clang (clang-14, libclang-rt-14-dev: installed if missing) in
# build-fuzz/, the whole project instrumented for coverage and AddressSanitizer. A crash fails the
# run and leaves its input in build-fuzz/crashes/: copy it to Testing/Fuzz/Regressions/HARNESS/,
# where the ordinary suite replays it (Fuzz.HARNESS), and fix the code.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build_dir=${VTKICE_FUZZ_BUILD_DIR:-build-fuzz}
harnesses=(FuzzCheckInput FuzzModelFile FuzzEnvironmentHeader FuzzPreset)

bash .ci/install-deps.sh fuzz
if [ ! -f "$build_dir/build.ninja" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build_dir" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DVTKICE_WRAP_PYTHON=OFF \
    -DVTKICE_FUZZ=ON
fi
cmake --build "$build_dir" --target fuzzers
mkdir -p "$build_dir/crashes"
for harness in "${harnesses[@]}"; do
  mkdir -p "$build_dir/corpus/$harness"
  # Leaks are left to ./ice.sh sanitize (VTK's and OpenImageIO's caches would stop the search).
  ASAN_OPTIONS=detect_leaks=0 "$build_dir/bin/$harness" -max_total_time="$seconds" \
    -print_final_stats=1 -artifact_prefix="$build_dir/crashes/$harness-" \
    "$build_dir/corpus/$harness" "Testing/Fuzz/Corpus/$harness" \
    >"$build_dir/$harness.log" 2>&1 &
done
status=0
wait || true
printf '%-22s %10s %8s %8s %7s  %s\n' harness executions exec/s coverage corpus result
for harness in "${harnesses[@]}"; do
  log=$build_dir/$harness.log
  units=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  corpus=$(find "$build_dir/corpus/$harness" -type f | wc -l)
  crash=$(ls "$build_dir/crashes/$harness-"* 2>/dev/null | head -1 || true)
  result=ok
  if [ -n "$crash" ] || ! grep -q "^stat::number_of_executed_units" "$log"; then
    result="FAILED: ${crash:-no statistics} (log: $log)"
    status=1
  fi
  printf '%-22s %10s %8s %8s %7s  %s\n' "$harness" "${units:--}" "${rate:--}" "${coverage:--}" \
    "$corpus" "$result"
done
exit "$status"
