#!/usr/bin/env bash
# ./ice.sh lane trixie|sid [ctest options]: VTK Ice on another Debian suite's VTK, in a chroot made
# from Debian's packages (mmdebstrap): trixie has VTK 9.3, sid VTK 9.6. The chroot is made once
# and reused while its package list is unchanged (VTKICE_LANE_ROOT, default /var/tmp/vtkice-lanes).
# Inside, the source tree is bound at /src and the VTK stage runs as on the host
# (./ice.sh test-vtk: ctest under Xvfb, then the backend tests through EGL) in build-lane-SUITE/,
# then PyVista's test with Debian's python3-pyvista. Mounts are undone on every exit (Ctrl-C too).
set -euo pipefail
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
root=$lanes/$suite
build_dir=build-lane-$suite

# The VTK stage's packages (.ci/install-deps.sh, which runs inside too and finds them), PyVista
# and pytest for its test, and what the tests' scripts call.
packages=(
  libvtk9-dev python3-vtk9 cmake ninja-build g++ pkg-config libglm-dev libopenimageio-dev
  xvfb xauth x11-utils libgl1-mesa-dri libegl-dev libegl-mesa0 dpkg-dev lintian ffmpeg
  python3-pyvista python3-pytest procps file
)
# sid's Mesa has no OSMesa any more (the build leaves the osmesa back end out).
skip=
if [ "$suite" = trixie ]; then
  packages+=(libosmesa6-dev)
else
  skip=libosmesa6-dev
fi

if ! command -v mmdebstrap >/dev/null 2>&1; then
  echo "== lane $suite: installing mmdebstrap"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq mmdebstrap >/dev/null
fi

stamp="$suite ${packages[*]}"
if [ ! -f "$root/.vtkice-lane" ] || [ "$(cat "$root/.vtkice-lane")" != "$stamp" ]; then
  echo "== lane $suite: making the chroot $root (mmdebstrap, Debian's packages)"
  rm -rf "$root"
  mkdir -p "$lanes"
  sources=("deb $mirror $suite main")
  if [ "$suite" = trixie ]; then
    sources+=("deb $mirror $suite-updates main" "deb ${mirror%/debian}/debian-security $suite-security main")
  fi
  # sid's Release file on some mirrors is past its Valid-Until date.
  mmdebstrap --variant=minbase --include="$(IFS=,; echo "${packages[*]}")" \
    --aptopt='Acquire::Check-Valid-Until "false"' "$suite" "$root" "${sources[@]}"
  printf '%s' "$stamp" >"$root/.vtkice-lane"
fi

# Mounts, undone in reverse order whatever happens.
mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[$i]}" 2>/dev/null || true
  done
  mounted=()
}
trap unmount_all EXIT
trap 'unmount_all; exit 130' INT TERM
mount_in() { # mount_in TARGET MOUNT-ARGS...
  local target=$root$1
  shift
  mkdir -p "$target"
  mount "$@" "$target"
  mounted+=("$target")
}
mount_in /proc -t proc proc
mount_in /sys -t sysfs sys
mount_in /dev --bind /dev
mount_in /dev/pts --bind /dev/pts
mount_in /dev/shm -t tmpfs tmpfs
mount_in /src --bind "$top"

inside() {
  chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    VTKICE_BUILD_DIR="$build_dir" VTKICE_SKIP_PACKAGES="$skip" bash -c "$1" bash "${@:2}"
}
echo "== lane $suite: $(inside 'dpkg-query -W -f "VTK \${Version}" libvtk9-dev; dpkg-query -W -f ", PyVista \${Version}" python3-pyvista')"

status=0
inside 'cd /src && ./ice.sh test-vtk "$@"' "$@" || status=1
echo "== lane $suite: PyVista (Debian's python3-pyvista) with the vtkice of $build_dir"
inside 'cd /src && env -u DISPLAY PYTHONPATH=/src/$VTKICE_BUILD_DIR/lib/python3/dist-packages \
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" python3 -m pytest -q -p no:cacheprovider \
  Testing/Wheel/test_pyvista.py' || status=1
exit "$status"
