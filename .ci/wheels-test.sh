#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh wheels-test: the wheels ./ice.sh wheels left in dist/, as a user gets them.
#   1. each wheel: auditwheel show gives its manylinux tag; no extension or library in it wants
#      a std::__cxx11 symbol (B5cxx11: VTK's old libstdc++ ABI throughout); its size
#   2. each wheel with its Python here: pip install vtk==9.7.0 pyvista WHEEL into a fresh venv,
#      then Testing/Wheel/ready_wheel.py without X (EGL), against its baseline
#   3. in chroots of Debian 13 and sid that have no compiler and no OpenImageIO, only Python 3.13
#      and Mesa: the cp313 wheel the same way (the packages pip fetched here, offline there)
#   4. with another vtk (9.7.1) in its venv, import vtkice says which vtk it needs
# Chroots in VTKICE_WHEELS_ROOT (/var/tmp/vtkice-wheels), reused while their package list holds.
set -euo pipefail
if [ -z "${VTKICE_WHEELS_NAMESPACE:-}" ]; then
  exec unshare --mount --propagation private env VTKICE_WHEELS_NAMESPACE=1 bash "$0" "$@"
fi
cd "$(dirname "$0")/.."
top=$PWD
work=$top/build-wheels
vtk_version=$(sed -n 's/^vtk_version=//p' .ci/wheel-env.sh)
pyvista_version=$(sed -n 's/^pyvista_version=//p' .ci/wheel-env.sh)
other_vtk=9.7.1
plat=manylinux_2_31_x86_64
baseline=$top/Testing/Data/Baseline/ReadyWheel.png
tools=$work/tools
say() { echo "== wheels-test: $*"; }
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

wheels=(dist/vtkice-*-"$plat".whl)
[ -e "${wheels[0]}" ] || { echo "wheels-test: no wheel in dist/: ./ice.sh wheels first" >&2; exit 2; }

# 1. What auditwheel and nm say of each wheel.
for wheel in "${wheels[@]}"; do
  # VTK's libraries are not on the library path here: auditwheel judges the wheel by the
  # symbol versions it wants of the system's libraries (its lines wrapped, joined here).
  shown=$(PATH=$tools/bin:$PATH "$tools/bin/auditwheel" show "$wheel" 2>&1 | tr -s '\n ' '  ')
  if grep -q "constrains the platform tag to \"$plat\"" <<<"$shown"; then
    echo "ok   $(basename "$wheel"): auditwheel: $plat, $(du -k "$wheel" | cut -f1) KiB"
  else
    fail "$(basename "$wheel"): auditwheel show: $shown"
  fi
  unpacked=$(mktemp -d)
  (cd "$unpacked" && python3 -m zipfile -e "$top/$wheel" .)
  cxx11=$(find "$unpacked" -name '*.so*' -exec nm -D --undefined-only {} + | grep -c B5cxx11 || true)
  rm -rf "$unpacked"
  [ "$cxx11" -eq 0 ] && echo "ok   $(basename "$wheel"): no B5cxx11 symbol wanted" ||
    fail "$(basename "$wheel"): $cxx11 B5cxx11 symbols wanted (the new libstdc++ ABI)"
done

# ready WHERE VENV PYTHON WHEEL [PIP OPTIONS...]: a fresh venv, the wheel with vtk and PyVista, the
# check without X.
ready() {
  local where=$1 venv=$2 python=$3 wheel=$4
  shift 4
  rm -rf "$venv"
  "$python" -m venv "$venv" &&
    "$venv/bin/pip" install --quiet --disable-pip-version-check "$@" "vtk==$vtk_version" \
      "pyvista==$pyvista_version" "$wheel" &&
    (cd /tmp && env -u DISPLAY "$venv/bin/python" "$top/Testing/Wheel/ready_wheel.py" \
      "$venv.work" "$baseline") || fail "$where: $(basename "$wheel")"
}

# 2. The host's Pythons.
for wheel in "${wheels[@]}"; do
  tag=$(basename "$wheel" | cut -d- -f3)
  v=${tag#cp3}
  v=3.$v
  python=$(ls -d "${PYENV_ROOT:-${HOME:-/root}/.pyenv}"/versions/$v.*/bin/python$v 2>/dev/null | tail -1 ||
    true)
  [ -n "$python" ] || python=$(command -v "python$v" || true)
  if [ -z "$python" ]; then
    fail "no Python $v here for $(basename "$wheel")"
    continue
  fi
  say "Python $v here ($python): a fresh venv, pip install vtk==$vtk_version pyvista $(basename "$wheel")"
  ready "Python $v here" "$work/test-venv-$v" "$python" "$top/$wheel"
  last_venv=$work/test-venv-$v
done

# 4. Another vtk under the last venv's vtkice.
say "vtk $other_vtk in $last_venv: import vtkice"
"$last_venv/bin/pip" install --quiet --disable-pip-version-check "vtk==$other_vtk" 2>/dev/null
message=$("$last_venv/bin/python" -c 'import vtkice' 2>&1 | tail -1) && fail "vtkice imported beside vtk $other_vtk"
if grep -q "ImportError: vtkice was built against VTK $vtk_version but this Python imports VTK $other_vtk .*pip install vtk==$vtk_version" <<<"$message"; then
  echo "ok   $message"
else
  fail "import vtkice beside vtk $other_vtk: $message"
fi

# 3. Debian 13 and sid: Python 3.13 and Mesa, nothing to compile with.
cp313=$(ls dist/vtkice-*-cp313-*-"$plat".whl)
downloads=$work/downloads-3.13
say "the packages for Python 3.13 (pip download, for the chroots)"
"$tools/bin/pip" download --quiet --disable-pip-version-check --only-binary=:all: \
  --python-version 3.13 -d "$downloads" "vtk==$vtk_version" "pyvista==$pyvista_version"
packages=(python3.13 python3.13-venv libegl1 libegl-mesa0 libgl1-mesa-dri libopengl0 libgl1)
for suite in trixie sid; do
  root=${VTKICE_WHEELS_ROOT:-/var/tmp/vtkice-wheels}/test-$suite
  if [ "$(cat "$root/.vtkice-wheels" 2>/dev/null)" != "${packages[*]}" ]; then
    say "making the chroot $root (Debian $suite: Python 3.13, Mesa)"
    command -v mmdebstrap >/dev/null || bash .ci/apt-install.sh "wheels-test: mmdebstrap" mmdebstrap
    rm -rf "$root"
    mmdebstrap --variant=minbase --include="$(IFS=,; echo "${packages[*]}")" \
      --aptopt='Acquire::Check-Valid-Until "false"' "$suite" "$root" \
      "deb ${VTKICE_DEBIAN_MIRROR:-http://deb.debian.org/debian} $suite main"
    echo "${packages[*]}" >"$root/.vtkice-wheels"
  fi
  for target in proc dev dev/shm "$top"; do mkdir -p "$root/$target"; done
  mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
  mountpoint -q "$root/dev" || mount --bind /dev "$root/dev"
  mountpoint -q "$root/dev/shm" || mount -t tmpfs tmpfs "$root/dev/shm"
  mountpoint -q "$root$top" || mount --bind "$top" "$root$top"
  in_root() { chroot "$root" env -i PATH=/usr/bin:/bin HOME=/root LANG=C.UTF-8 bash -c "$@"; }
  if in_root 'command -v cc gcc g++ c++ clang' >/dev/null ||
    in_root 'ls /usr/lib/x86_64-linux-gnu/libOpenImageIO*' >/dev/null 2>&1; then
    fail "Debian $suite's chroot has a compiler or OpenImageIO"
  fi
  say "Debian $suite ($(in_root 'python3.13 --version')): a fresh venv, pip install vtk==$vtk_version pyvista $(basename "$cp313")"
  in_root "$(declare -f ready fail); top=$top vtk_version=$vtk_version pyvista_version=$pyvista_version \
    baseline=$baseline failures=0; ready 'Debian $suite' $work/test-venv-$suite python3.13 $top/$cp313 \
    --no-index --find-links $downloads; exit \$failures" || fail "Debian $suite"
done

echo "wheels-test: $failures failures"
[ "$failures" -eq 0 ]
