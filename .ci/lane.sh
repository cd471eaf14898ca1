#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh lane trixie|sid [ctest options]: VTK Ice on another Debian suite's VTK and ParaView, in
# chroots made from Debian's packages (mmdebstrap): trixie has VTK 9.3 and ParaView 5.13 (with its
# own VTK 9.3), sid VTK 9.6 and ParaView 6.1 (on that VTK). A chroot is made once and reused while
# its package list is unchanged; packages the list adds are installed into it (VTKICE_LANE_ROOT,
# default /var/tmp/vtkice-lanes). Inside, the source tree is bound at /src and the VTK stage runs
# as on the host but with each test once (./ice.sh test-vtk with VTKICE_TESTS_ONCE=1: the tests
# labelled backend through EGL, the others under Xvfb) in build-lane-SUITE/, then PyVista's test with Debian's python3-pyvista, then the ParaView stage
# (./ice.sh paraview: the plugin and its tests) in build-lane-SUITE-paraview/. VTKICE_LANE_STAGES
# ("vtk paraview" by default) picks the stages. trixie's python3-paraview cannot be installed
# beside its python3-vtk9: its ParaView stage runs in a second chroot, trixie-paraview; sid's runs
# in the same chroot.
# The mounts live in this run's own mount namespace: undone on every exit (Ctrl-C, kill too), never
# seen by another run. Ends with a table of its stages (.ci/stages.sh), exit 1 when one failed.
set -euo pipefail
# In a mount namespace of its own: the chroots' mounts are seen by this run only and vanish with
# it, however it ends, and a chroot another run is using shows no mounts here.
if [ -z "${VTKICE_LANE_NAMESPACE:-}" ]; then
  exec unshare --mount --propagation private env VTKICE_LANE_NAMESPACE=1 bash "$0" "$@"
fi
cd "$(dirname "$0")/.."
top=$PWD

suite=${1:-}
[ $# -gt 0 ] && shift
case "$suite" in
  trixie | sid) ;;
  *)
    echo "usage: ./ice.sh lane trixie|sid [ctest options]" >&2
    exit 2
    ;;
esac
mirror=${VTKICE_DEBIAN_MIRROR:-http://deb.debian.org/debian}
lanes=${VTKICE_LANE_ROOT:-/var/tmp/vtkice-lanes}
build_dir=build-lane-$suite
stages=" ${VTKICE_LANE_STAGES:-vtk paraview} "

# The VTK stage's packages (.ci/install-deps.sh, which runs inside too and finds them), PyVista
# and pytest for its test, and what the tests' scripts call.
packages=(
  libvtk9-dev python3-vtk9 cmake ninja-build g++ pkg-config ccache libglm-dev libopenimageio-dev
  xvfb xauth x11-utils libgl1-mesa-dri libegl-dev libegl-mesa0 dpkg-dev lintian ffmpeg
  python3-pyvista python3-pytest procps file
)
# The ParaView stage's packages (install-deps.sh's paraview list), and the development packages
# ParaView's CMake package looks for that paraview-dev does not depend on (Debian 13 and sid).
paraview_packages=(
  paraview paraview-dev python3-paraview python3-dev cmake ninja-build g++ pkg-config ccache
  libglm-dev libopenimageio-dev xvfb xauth libgl1-mesa-dri x11-apps imagemagick openmpi-bin
  mpi-default-dev libx11-dev libutfcpp-dev libdouble-conversion-dev libglew-dev libgl-dev
  libegl-dev libxt-dev libfreetype-dev libhdf5-mpi-dev procps file
)
# sid's Mesa has no OSMesa any more (the build leaves the osmesa back end out). blender-data (the
# host's panoramas for ice-render --env NAME) is left out of the chroots: there ice-render's
# message without it is what the test checks.
skip=blender-data
if [ "$suite" = trixie ]; then
  packages+=(libosmesa6-dev)
  paraview_root=$lanes/$suite-paraview
else
  skip="blender-data libosmesa6-dev"
  # ParaView 6.1 is built on sid's own VTK: one chroot holds both stages.
  packages+=(paraview paraview-dev python3-paraview python3-dev x11-apps imagemagick openmpi-bin
    mpi-default-dev libx11-dev libutfcpp-dev libdouble-conversion-dev libglew-dev libgl-dev
    libxt-dev libfreetype-dev libhdf5-mpi-dev)
  paraview_root=$lanes/$suite
  paraview_packages=("${packages[@]}")
fi

# Mounts under the lanes' folder in this run's namespace (the stages mount in subshells), undone
# in reverse order whatever happens.
unmount_all() {
  local target
  awk -v root="$lanes/" 'index($2, root) == 1 { print $2 }' /proc/mounts | tac |
    while read -r target; do umount -l "$target" 2>/dev/null || true; done
}
trap unmount_all EXIT
trap 'unmount_all; exit 130' INT TERM
mount_in() { # mount_in ROOT TARGET MOUNT-ARGS...: unless this run mounted it already
  local target=$1$2
  shift 2
  mkdir -p "$target"
  if mountpoint -q "$target"; then
    return 0
  fi
  mount "$@" "$target"
}
# A chroot with mounts under it (made outside a lane run) is never removed.
mounted_under() { grep -q " $1/" /proc/mounts; }

inside() { # inside ROOT SCRIPT [ARGS...]: bash -c SCRIPT in the chroot, with none of our environment
  local root=$1
  shift
  chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    VTKICE_BUILD_DIR="$build_dir" VTKICE_SKIP_PACKAGES="$skip" VTKICE_TESTS_ONCE=1 \
    bash -c "$1" bash "${@:2}"
}

# prepare_chroot ROOT PACKAGE...: makes ROOT, a minbase chroot of $suite with PACKAGE... (unless it
# was made before), mounts what the stages use in it and installs the packages the list gained.
prepare_chroot() {
  local root=$1
  shift
  local stamp="$suite $*"
  local start=$SECONDS
  if [ ! -f "$root/.vtkice-lane" ]; then
    if mounted_under "$root"; then
      echo "lane $suite: $root has mounts of another run; not touching it" >&2
      exit 1
    fi
    echo "== lane $suite: making the chroot $root (mmdebstrap, Debian's packages)"
    rm -rf "$root"
    mkdir -p "$lanes"
    local sources=("deb $mirror $suite main")
    if [ "$suite" = trixie ]; then
      sources+=("deb $mirror $suite-updates main" "deb ${mirror%/debian}/debian-security $suite-security main")
    fi
    # sid's Release file on some mirrors is past its Valid-Until date.
    mmdebstrap --variant=minbase --include="$(IFS=,; echo "$*")" \
      --aptopt='Acquire::Check-Valid-Until "false"' "$suite" "$root" "${sources[@]}"
    printf '%s' "$stamp" >"$root/.vtkice-lane"
    echo "== lane $suite: $root made in $((SECONDS - start)) s"
  fi
  mount_in "$root" /proc -t proc proc
  mount_in "$root" /sys -t sysfs sys
  mount_in "$root" /dev --bind /dev
  mount_in "$root" /dev/pts --bind /dev/pts
  mount_in "$root" /dev/shm -t tmpfs tmpfs
  mount_in "$root" /src --bind "$top"
  if [ "$(cat "$root/.vtkice-lane")" != "$stamp" ]; then
    # The package list changed since the chroot was made: add what is missing (mmdebstrap
    # removed the package lists, so update first; the mirror's Valid-Until is not checked).
    inside "$root" 'VTKICE_APT_UPDATE_OPTIONS="-o Acquire::Check-Valid-Until=false" \
      bash /src/.ci/apt-install.sh "lane $1: the packages the chroot'"'"'s list adds" "${@:2}"' \
      "$suite" "$@"
    printf '%s' "$stamp" >"$root/.vtkice-lane"
  fi
}

. .ci/stages.sh
root=$lanes/$suite
declare -A made=()
make_root() { # make_root ROOT PACKAGE...: the stage making the chroot, once; made[ROOT]=yes or no
  if [ -z "${made[$1]:-}" ]; then
    stage_run "chroot $(basename "$1")" prepare_chroot "$@"
    made[$1]=$([ "$stage_status" -eq 0 ] && echo yes || echo no)
  fi
}
stage_run "mmdebstrap on the host" bash -c \
  'command -v mmdebstrap >/dev/null || bash .ci/apt-install.sh "lane $0: mmdebstrap" mmdebstrap' \
  "$suite"
if [ "$stage_status" -ne 0 ]; then
  made[$root]=no
  made[$paraview_root]=no
fi
# lane_ready WORD ROOT SKIPPED PACKAGE...: lane_go=yes when the stages WORD of VTKICE_LANE_STAGES
# run, in ROOT made for them; else a row SKIPPED says why not. Called as a plain command (make_root
# runs a stage).
lane_ready() {
  local word=$1 chroot_root=$2 skipped=$3
  shift 3
  lane_go=no
  if [[ $stages != *" $word "* ]]; then
    stage_skip "$skipped" VTKICE_LANE_STAGES
    return 0
  fi
  make_root "$chroot_root" "$@"
  if [ "${made[$chroot_root]}" = yes ]; then
    lane_go=yes
  else
    stage_skip "$skipped" "no chroot"
  fi
}
# Debian's versions without their revisions ("VTK 9.3.0, PyVista 0.44.1"): versions ROOT SCRIPT.
versions() { inside "$1" "$2" | sed -E 's/[+~-][^ ,]*//g'; }

lane_ready vtk "$root" "VTK and PyVista" "${packages[@]}"
if [ "$lane_go" = yes ]; then
  versions=$(versions "$root" 'dpkg-query -W -f "VTK \${Version}" libvtk9-dev; dpkg-query -W -f ", PyVista \${Version}" python3-pyvista')
  echo "== lane $suite: $versions"
  stage_run "${versions%%,*} (./ice.sh test-vtk)" \
    inside "$root" 'cd /src && ./ice.sh test-vtk "$@"' "$@"
  echo "== lane $suite: PyVista (Debian's python3-pyvista) with the vtkice of $build_dir"
  stage_run "${versions#*, } (test_pyvista.py)" \
    inside "$root" 'cd /src && env -u DISPLAY PYTHONPATH=/src/$VTKICE_BUILD_DIR/lib/python3/dist-packages \
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" python3 -m pytest -q -p no:cacheprovider \
    Testing/Wheel/test_pyvista.py'
fi

# sid's one chroot is made and mounted once, for both stages.
lane_ready paraview "$paraview_root" ParaView "${paraview_packages[@]}"
if [ "$lane_go" = yes ]; then
  version=$(versions "$paraview_root" 'dpkg-query -W -f "ParaView \${Version}" paraview-dev')
  echo "== lane $suite: the ParaView stage in $build_dir-paraview, $version"
  stage_run "$version (./ice.sh paraview)" \
    inside "$paraview_root" 'cd /src && VTKICE_PARAVIEW_BUILD_DIR=$VTKICE_BUILD_DIR-paraview \
    ./ice.sh paraview "$@"' "$@"
fi
stage_table
