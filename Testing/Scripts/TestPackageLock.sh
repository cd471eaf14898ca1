#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# .ci/apt-install.sh on a machine where another program holds the package lock. apt-get and dpkg
# are fakes on PATH that log their calls; a second process holds a POSIX lock (as dpkg takes
# it) on the test's own lock file.
# usage: TestPackageLock.sh SOURCE_DIR WORK_DIR CASE
#   wait            the lock held 3 s: the install says it waits, who holds the lock, then runs
#                   apt-get only once the lock is free, and succeeds
#   timeout         the lock held past VTKICE_PACKAGE_LOCK_WAIT: no apt-get, one line naming the
#                   step and the holder, exit non-zero
#   failed-install  apt-get install fails: one line naming the step, the command and the package
set -u
source_dir=$1
work=$2
case_name=$3
rm -rf "$work" && mkdir -p "$work/bin" && cd "$work" || exit 1
: >calls.log
for tool in apt-get dpkg; do
  cat >"bin/$tool" <<EOF
#!/bin/sh
echo "\$(date +%s.%N) $tool \$*" >>"$work/calls.log"
case "\$*" in *install*) [ -z "\${FAKE_INSTALL_FAILS:-}" ] || exit 100 ;; esac
exit 0
EOF
  chmod +x "bin/$tool"
done
# Run as another user than root, the script calls sudo: this one keeps PATH's fakes.
printf '#!/bin/sh\nexec "$@"\n' >bin/sudo && chmod +x bin/sudo
: >lock
export VTKICE_PACKAGE_LOCKS=$work/lock
export PATH=$work/bin:$PATH

fail() { echo "FAIL $case_name: $*"; echo "--- output"; cat out.txt; echo "--- calls"; cat calls.log; exit 1; }

# hold SECONDS: a process holding the lock for SECONDS; prints its PID once the lock is held.
hold() {
  python3 -c '
import fcntl, sys, time
f = open(sys.argv[1], "w")
fcntl.lockf(f, fcntl.LOCK_EX)
print("held", flush=True)
time.sleep(float(sys.argv[2]))
' "$work/lock" "$1" >held.txt &
  holder=$!
  for _ in $(seq 100); do grep -q held held.txt 2>/dev/null && return 0; sleep 0.1; done
  fail "the lock holder did not start"
}

step="the test's packages"
case "$case_name" in
  wait)
    hold 3
    released_after=$(date +%s.%N)
    bash "$source_dir/.ci/apt-install.sh" "$step" some-package >out.txt 2>&1
    code=$?
    wait "$holder"
    [ "$code" -eq 0 ] || fail "exit $code"
    grep -q "== $step: waiting for the package lock, held by process $holder (python3)" out.txt ||
      fail "no line saying it waits and who holds the lock"
    grep -q "== $step: the package lock is free after" out.txt || fail "no line saying the lock is free"
    first=$(head -1 calls.log | cut -d' ' -f1)
    # The first call comes only once the 3 s hold is over.
    awk -v a="$first" -v b="$released_after" 'BEGIN { exit !(a - b >= 2.5) }' ||
      fail "dpkg or apt-get ran while the lock was held ($first, lock taken at $released_after)"
    grep -q "apt-get .*install -y -qq --no-install-recommends some-package" calls.log ||
      fail "apt-get install was not called"
    echo "ok: waited $(awk -v a="$first" -v b="$released_after" 'BEGIN { printf "%.1f", a - b }') s, then installed"
    ;;
  timeout)
    hold 20
    VTKICE_PACKAGE_LOCK_WAIT=2 bash "$source_dir/.ci/apt-install.sh" "$step" some-package >out.txt 2>&1
    code=$?
    kill "$holder" 2>/dev/null
    [ "$code" -ne 0 ] || fail "exit 0 with the lock held"
    [ ! -s calls.log ] || fail "dpkg or apt-get ran with the lock held"
    grep -q "^apt-install.sh ($step): the package lock is still held by process $holder (python3) after 2 s; nothing installed: some-package$" out.txt ||
      fail "no line naming the step and the holder"
    echo "ok: $(tail -1 out.txt)"
    ;;
  failed-install)
    FAKE_INSTALL_FAILS=1 bash "$source_dir/.ci/apt-install.sh" "$step" some-package other-package >out.txt 2>&1
    code=$?
    [ "$code" -eq 100 ] || fail "exit $code, not apt-get's 100"
    [ "$(tail -1 out.txt)" = "apt-install.sh ($step): apt-get install failed (exit 100) for: some-package other-package" ] ||
      fail "the last line does not name the step, the command and the packages"
    echo "ok: $(tail -1 out.txt)"
    ;;
  *)
    echo "FAIL unknown case $case_name"
    exit 1
    ;;
esac
