#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The table that ends ./ice.sh test and ./ice.sh lane (.ci/stages.sh), on made-up stages.
# usage: TestStageTable.sh SOURCE_DIR WORK_DIR CASE
#   results   passed, failed and skipped rows with the tests ctest's and pytest's lines count and
#             each stage's output shown; exit 1 since one failed
#   passed    every stage passed: exit 0
#   nested    a script with stages of its own run as a stage (a lane under ./ice.sh test): its rows
#             indented under its own row, which fails with them; one table
#   errexit   a command failing inside a stage's shell function ends that stage (failed), not the
#             script: the next stage runs
set -u
source_dir=$1
work=$2
case_name=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export STAGES=$source_dir/.ci/stages.sh
unset VTKICE_STAGE_RECORD VTKICE_STAGE_DEPTH

fail() { echo "FAIL $case_name: $*"; echo "--- output"; cat out.txt; exit 1; }
# row NAME RESULT TESTS: the table has a row of NAME (with its indent) with RESULT and TESTS.
row() {
  grep -qE "^$(printf '%s' "$1" | sed 's/[][().*]/\\&/g') +$2 +$3 +[0-9]+\.[0-9]" out.txt ||
    fail "no row '$1  $2  $3'"
}

cat >ctest-like.sh <<'EOF'
echo "100% tests passed, 0 tests failed out of 27"
echo "100% tests passed, 0 tests failed out of 77"
EOF
cat >pytest-like.sh <<'EOF'
echo "2 failed, 47 passed, 3 skipped in 3.10s"
exit 1
EOF

case "$case_name" in
  results)
    bash -c 'set -euo pipefail; . "$STAGES"
      stage_run "VTK stage" bash ctest-like.sh
      stage_run "wheel stage" bash pytest-like.sh
      stage_skip "fuzzing" "not asked for"
      stage_table' >out.txt 2>&1
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, not 1"
    grep -q "tests failed out of 77" out.txt && grep -q "2 failed, 47 passed" out.txt ||
      fail "the stages' output is not shown"
    row "VTK stage" passed 104
    row "wheel stage" failed 49
    grep -qE "^fuzzing +skipped +- +0\.0  \(not asked for\)$" out.txt || fail "no skipped row"
    echo "ok: $(grep -c -E 'passed|failed|skipped' out.txt) lines"
    ;;
  passed)
    bash -c 'set -euo pipefail; . "$STAGES"
      stage_run "VTK stage" bash ctest-like.sh
      stage_run "no tests" true
      stage_table' >out.txt 2>&1
    code=$?
    [ "$code" -eq 0 ] || fail "exit $code, not 0"
    row "VTK stage" passed 104
    row "no tests" passed -
    echo ok
    ;;
  nested)
    cat >lane-like.sh <<'EOF'
set -euo pipefail
. "$STAGES"
stage_run "chroot" true
stage_run "VTK 9.3" bash ctest-like.sh
stage_run "PyVista" bash pytest-like.sh
stage_table
EOF
    bash -c 'set -euo pipefail; . "$STAGES"
      stage_run "VTK stage" true
      stage_run "lane trixie" bash lane-like.sh
      stage_table' >out.txt 2>&1
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, not 1"
    [ "$(grep -c '^== Stages' out.txt)" -eq 1 ] || fail "not one table"
    # In this order: the lane's row, then its own stages indented.
    [ "$(sed -n '/^== Stages/,$p' out.txt | sed -n '3,7p' | cut -c1-16 | sed 's/ *$//' | tr '\n' '|')" = \
      "VTK stage|lane trixie|  chroot|  VTK 9.3|  PyVista|" ] || fail "rows not in order, indented"
    row "lane trixie" failed 153
    row "  chroot" passed -
    row "  VTK 9.3" passed 104
    row "  PyVista" failed 49
    echo ok
    ;;
  errexit)
    bash -c 'set -euo pipefail; . "$STAGES"
      broken() { echo before; false; echo "after the failure"; }
      stage_run "broken" broken
      stage_run "next" echo "the next stage ran"
      stage_table' >out.txt 2>&1
    code=$?
    [ "$code" -eq 1 ] || fail "exit $code, not 1"
    grep -q "after the failure" out.txt && fail "the stage went on after a failing command"
    grep -q "the next stage ran" out.txt || fail "the next stage did not run"
    row broken failed -
    row next passed -
    echo ok
    ;;
  *)
    echo "FAIL unknown case $case_name"
    exit 1
    ;;
esac
