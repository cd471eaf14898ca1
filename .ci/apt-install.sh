#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# .ci/apt-install.sh STEP [--recommends] PACKAGE...: every Debian package install of the project's
# scripts (the host's stages and the lanes' chroots) goes through here. STEP names what installs
# ("the ParaView stage", "lane trixie's chroot") in the lines it prints.
#   1. Waits while another program holds the package lock (unattended upgrades on a machine just
#      booted, another install, a CI run), saying who holds it, at most VTKICE_PACKAGE_LOCK_WAIT
#      seconds (default 1200) in all.
#   2. dpkg --configure -a (a run stopped during an install leaves dpkg half-configured), apt-get
#      update, apt-get install; apt waits on its own for the rest of the bound should a program
#      take the lock in between (DPkg::Lock::Timeout).
# A failure ends with one line naming STEP, the command that failed and the packages.
#   VTKICE_APT_UPDATE_OPTIONS  more options for apt-get update (the lanes: sid's expired Release)
#   VTKICE_PACKAGE_LOCKS       the lock files waited for (dpkg's and apt's by default; the tests
#                              point it at their own)
set -uo pipefail
step=${1:?usage: .ci/apt-install.sh STEP [--recommends] PACKAGE...}
shift
recommends=--no-install-recommends
if [ "${1:-}" = --recommends ]; then
  recommends=
  shift
fi
[ $# -gt 0 ] || { echo "apt-install.sh ($step): no package named" >&2; exit 2; }
wait_limit=${VTKICE_PACKAGE_LOCK_WAIT:-1200}
read -r -a locks <<<"${VTKICE_PACKAGE_LOCKS:-/var/lib/dpkg/lock-frontend /var/lib/dpkg/lock /var/lib/apt/lists/lock /var/cache/apt/archives/lock}"
started=$SECONDS

# The process holding one of the locks, as "PID (NAME)", from the kernel's table of file locks
# (dpkg and apt lock with fcntl; the table names the file by device and inode).
lock_holder() {
  local file inode device key pid
  for file in "${locks[@]}"; do
    [ -e "$file" ] || continue
    read -r inode device < <(stat -L -c '%i %d' "$file")
    key=$(printf '%02x:%02x:%s' $(((device >> 8) & 0xfff)) \
      $(((device & 0xff) | ((device >> 12) & 0xfff00))) "$inode")
    # Waiters are listed with "->"; only a holder counts.
    pid=$(awk -v key="$key" '$2 != "->" && $6 == key { print $5; exit }' /proc/locks)
    if [ -n "$pid" ]; then
      echo "$pid ($(cat "/proc/$pid/comm" 2>/dev/null || echo '?'))"
      return 0
    fi
  done
  return 1
}

wait_for_lock() {
  local holder said=
  while holder=$(lock_holder); do
    if [ $((SECONDS - started)) -ge "$wait_limit" ]; then
      echo "apt-install.sh ($step): the package lock is still held by process $holder after" \
        "${wait_limit} s; nothing installed: ${*}" >&2
      exit 1
    fi
    if [ -z "$said" ]; then
      echo "== $step: waiting for the package lock, held by process $holder" \
        "(at most ${wait_limit} s, VTKICE_PACKAGE_LOCK_WAIT)"
      said=1
    fi
    sleep 1
  done
  [ -z "$said" ] || echo "== $step: the package lock is free after $((SECONDS - started)) s"
}

# run WHAT COMMAND...: COMMAND, or the line that says which step failed, and exit.
run() {
  local what=$1 code
  shift
  "$@"
  code=$?
  if [ "$code" -ne 0 ]; then
    echo "apt-install.sh ($step): $what failed (exit $code) for: ${packages[*]}" >&2
    exit "$code"
  fi
}

packages=("$@")
echo "== $step: installing ${packages[*]}"
sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
export DEBIAN_FRONTEND=noninteractive
wait_for_lock "${packages[@]}"
left() { local l=$((wait_limit - (SECONDS - started))); echo $((l > 0 ? l : 0)); }
run "dpkg --configure -a" "${sudo[@]}" dpkg --configure -a
read -r -a update_options <<<"${VTKICE_APT_UPDATE_OPTIONS:-}"
run "apt-get update" "${sudo[@]}" apt-get -o "DPkg::Lock::Timeout=$(left)" "${update_options[@]}" \
  update -qq
run "apt-get install" "${sudo[@]}" apt-get -o "DPkg::Lock::Timeout=$(left)" install -y -qq \
  $recommends "${packages[@]}"
