#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package of this build: cpack makes it; dpkg-deb shows its name, its dependencies on
# Debian's packages and its files; lintian finds no error in it; unpacked into a fresh folder
# that nothing else uses, its CMake package builds and runs the installed-consumer example, its
# Python module imports with Debian's Python, its ice-render renders with a shipped preset.
# usage: TestDebianPackage.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -u
build=$1
source=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
check() {
  if [ "$2" = 0 ]; then echo "ok   $1"; else echo "FAIL $1"; failures=$((failures + 1)); fi
}
preload=()
[ -n "${VTKICE_ASAN_RUNTIME:-}" ] && preload=(env "LD_PRELOAD=$VTKICE_ASAN_RUNTIME")

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/package" >"$work/cpack.log" 2>&1
deb=$(ls "$work"/package/vtkice_*_amd64.deb 2>/dev/null | head -1)
check "cpack made $(basename "${deb:-no package}")" "$([ -n "$deb" ] && echo 0 || echo 1)"
[ -n "$deb" ] || { cat "$work/cpack.log"; echo "1 failed"; exit 1; }

info=$(dpkg-deb --field "$deb" Package Depends Recommends)
echo "$info" | sed 's/^/     /'
echo "$info" | grep -q "^Package: vtkice$"; check "package name vtkice" $?
# The Debian package of the VTK this build links (libvtk9.1 on Debian 12, libvtk9.3 on 13, ...).
vtk_library=$(ldd "$build"/lib/libRenderingIce.so | awk '/libvtkCommonCore/ {print $3; exit}')
vtk_package=$(dpkg -S "$(readlink -f "$vtk_library")" 2>/dev/null | head -1 | cut -d: -f1)
echo "$info" | grep -qE "(^|[ ,])${vtk_package:-no-vtk-package} \(>= "
check "depends on Debian's ${vtk_package:-VTK package (none found for $vtk_library)}" $?
echo "$info" | grep -q "libopenimageio"; check "depends on Debian's OpenImageIO library" $?
contents=$(dpkg-deb --contents "$deb" | awk '{print $6}')
for file in ./usr/bin/ice-render ./usr/bin/ice-bench ./usr/include/vtkice/vtkIceMapper.h \
  ./usr/lib/cmake/VTKIce/VTKIceConfig.cmake ./usr/lib/python3/dist-packages/vtkice/__init__.py \
  ./usr/share/vtkice/presets/glacier.ice ./usr/share/doc/vtkice/copyright \
  ./usr/share/doc/vtkice/changelog.gz ./usr/share/doc/vtkice/Documentation/usage.md; do
  echo "$contents" | grep -qx "$file"; check "holds $file" $?
done
dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/doc/vtkice/copyright |
  grep -q "^License: BSD-3-Clause$"
check "its copyright file gives the licence, BSD-3-Clause" $?
if command -v lintian >/dev/null; then
  lintian "$deb" >"$work/lintian.txt" 2>&1
  sed 's/^/     /' "$work/lintian.txt" | grep -v "root privileges"
  ! grep -q "^E: " "$work/lintian.txt"; check "lintian: no error" $?
else
  check "lintian is installed (.ci/install-deps.sh installs it)" 1
fi

# A fresh root for the package's /usr, used as users' projects use /usr.
root="$work/root"
dpkg-deb -x "$deb" "$root"
export LD_LIBRARY_PATH="$root/usr/lib"
PYTHONPATH="$root/usr/lib/python3/dist-packages" "${preload[@]}" /usr/bin/python3 -c \
  "import vtk, vtkice; assert vtkice.vtkIceMapper().GetClassName() == 'vtkIceMapper'"
check "the package's Python module imports with Debian's Python" $?
cmake -S "$source/Testing/Install" -B "$work/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$root/usr" >"$work/consumer.log" 2>&1 &&
  cmake --build "$work/consumer" >>"$work/consumer.log" 2>&1
check "the installed-consumer example builds against the package's CMake files" $?
"${preload[@]}" "$work/consumer/ice-consumer" >>"$work/consumer.log" 2>&1
check "and runs" $?
grep -q "$root/usr/include/vtkice" "$work/consumer/build.ninja"
check "with the package's headers" $?
env -u DISPLAY "${preload[@]}" "$root/usr/bin/ice-render" --model sphere --preset glacier \
  --size 64x48 --out "$work/packaged.png" >/dev/null
check "the package's ice-render renders with its shipped preset" $?
echo "$failures failed"
[ "$failures" -eq 0 ]
