# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Sourced by ./ice.sh test and ./ice.sh lane: each stage's result in one table at the end.
#   stage_run NAME COMMAND...  runs COMMAND (its output shown as it comes), records passed or
#                              failed, the tests it ran (ctest's "out of N" lines, pytest's and
#                              the plain "N passed, M failed" lines) and its minutes; its exit status in
#                              stage_status. Call it as a plain command, never in an if, && or ||:
#                              there bash would ignore errexit inside COMMAND's functions
#   stage_skip NAME WHY        records a stage not run
#   stage_table                the table (by the outermost script only: a lane run by
#                              ./ice.sh test adds its rows, indented, under its own); returns 1
#                              when a stage of this script failed
# The rows live in the file VTKICE_STAGE_RECORD, which the outermost script makes.
if [ -z "${VTKICE_STAGE_RECORD:-}" ]; then
  VTKICE_STAGE_RECORD=$(mktemp "${TMPDIR:-/tmp}/vtkice-stages.XXXXXX")
  export VTKICE_STAGE_RECORD
  stage_owner=1
else
  stage_owner=
fi
export VTKICE_STAGE_DEPTH=${VTKICE_STAGE_DEPTH:-0}
stage_failed=0

# Tests a stage's output says it ran: ctest's summary lines and pytest's closing lines. In bash:
# sid's mawk (1.3.4 20260302) reads NF as 0 in a rule after one that names $NF.
stage_count_tests() {
  local line rest n=0 found=
  while IFS= read -r line; do
    if [[ $line =~ tests\ failed\ out\ of\ ([0-9]+) ]]; then
      n=$((n + BASH_REMATCH[1])) found=1
    elif [[ $line =~ ^=*\ *[0-9]+\ (passed|failed) ]] &&
      [[ $line =~ \ in\ [0-9.]+s || $line =~ ^[0-9]+\ passed,\ [0-9]+\ failed$ ]]; then
      rest=$line
      while [[ $rest =~ ([0-9]+)\ (passed|failed|errors?)(.*) ]]; do
        n=$((n + BASH_REMATCH[1])) found=1 rest=${BASH_REMATCH[3]}
      done
    fi
  done <<<"$(grep -E 'tests failed out of|^=* *[0-9]+ (passed|failed)' "$1")"
  if [ -n "$found" ]; then echo "$n"; else echo -; fi
}

# stage_row LINE DEPTH NAME RESULT TESTS SECONDS: writes the row, at line LINE when it exists.
stage_row() {
  local row
  row=$(printf '%s\t%s\t%s\t%s\t%s' "$2" "$3" "$4" "$5" "$6")
  if [ "$1" -le "$(wc -l <"$VTKICE_STAGE_RECORD")" ]; then
    awk -v n="$1" -v row="$row" 'NR == n { print row; next } { print }' "$VTKICE_STAGE_RECORD" \
      >"$VTKICE_STAGE_RECORD.new" && mv "$VTKICE_STAGE_RECORD.new" "$VTKICE_STAGE_RECORD"
  else
    printf '%s\n' "$row" >>"$VTKICE_STAGE_RECORD"
  fi
}

stage_run() {
  local name=$1 line log start code errexit=
  shift
  line=$(($(wc -l <"$VTKICE_STAGE_RECORD") + 1))
  # The row first: the rows of a nested script's stages come under it.
  stage_row "$line" "$VTKICE_STAGE_DEPTH" "$name" running - 0
  log=$(mktemp "${TMPDIR:-/tmp}/vtkice-stage.XXXXXX")
  start=$SECONDS
  [[ $- == *e* ]] && errexit=1
  set +e
  # A subshell with the caller's errexit: a failing command inside COMMAND ends it, not us.
  (
    [ -z "$errexit" ] || set -e
    VTKICE_STAGE_DEPTH=$((VTKICE_STAGE_DEPTH + 1)) "$@"
  ) 2>&1 | tee "$log"
  code=${PIPESTATUS[0]}
  [ -z "$errexit" ] || set -e
  local result=passed
  [ "$code" -eq 0 ] || { result=failed; stage_failed=1; }
  stage_row "$line" "$VTKICE_STAGE_DEPTH" "$name" "$result" "$(stage_count_tests "$log")" \
    $((SECONDS - start))
  rm -f "$log"
  stage_status=$code
}

stage_skip() {
  printf '%s\t%s\tskipped\t-\t0\t%s\n' "$VTKICE_STAGE_DEPTH" "$1" "$2" >>"$VTKICE_STAGE_RECORD"
}

stage_table() {
  [ -n "$stage_owner" ] || return "$stage_failed"
  echo
  echo "== Stages"
  printf '%-44s %-8s %6s %8s\n' stage result tests minutes
  local depth name result tests seconds why
  while IFS=$'\t' read -r depth name result tests seconds why; do
    printf '%-44s %-8s %6s %8s%s\n' "$(printf '%*s' $((2 * depth)) '')$name" "$result" "$tests" \
      "$(awk -v s="$seconds" 'BEGIN { printf "%.1f", s / 60 }')" "${why:+  ($why)}"
  done <"$VTKICE_STAGE_RECORD"
  rm -f "$VTKICE_STAGE_RECORD"
  return "$stage_failed"
}
