#!/usr/bin/env bash
# ./ice.sh wheel [ctest options]: VTK Ice on the `vtk` wheel from PyPI (VTK 9.7.0) with PyVista.
#   1. a venv in build-wheel/venv with vtk, pyvista and pytest (the versions below)
#   2. the wheel's SDK in build-wheel/sdk (./ice.sh vtk-sdk; VTKICE_VTK_SOURCE names VTK's source)
#   3. pip install . into the venv (the vtkice package beside the wheel)
#   4. the whole project built against the SDK (build-wheel/build), its ctest suite through EGL
#      without an X server, on the wheel's libraries (the Python tests: in 5)
#   5. pytest Testing/Wheel: the installed package, the project's Python tests on it, PyVista
#   6. pip wheel ., installed into a second fresh venv, imported there
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
vtk_version=9.7.0
pyvista_version=0.49.2
root=${VTKICE_WHEEL_DIR:-build-wheel}
venv=$root/venv
sdk=$root/sdk
python=$venv/bin/python
stage() { echo "== wheel lane: $*"; }

bash .ci/install-deps.sh

if ! "$python" -c "import vtkmodules, pyvista, pytest, scikit_build_core
from vtkmodules.vtkCommonCore import vtkVersion
assert vtkVersion.GetVTKVersion() == '$vtk_version'" 2>/dev/null; then
  stage "venv $venv (vtk $vtk_version, pyvista $pyvista_version)"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check "vtk==$vtk_version" \
    "pyvista==$pyvista_version" pytest scikit-build-core
fi

if [ ! -f "$sdk/lib/cmake/vtk/vtk-config.cmake" ] ||
  [ "$(readlink -f "$sdk/vtkmodules")" != "$("$python" -c 'import os, vtkmodules; print(os.path.realpath(os.path.dirname(vtkmodules.__file__)))')" ]; then
  stage "SDK $sdk"
  # VTK's source archive: where VTKICE_VTK_SOURCE says, else found by name in a folder beside
  # the checkout (where CI lays it).
  if [ -z "${VTKICE_VTK_SOURCE:-}" ]; then
    VTKICE_VTK_SOURCE=$(find "$(dirname "$top")" -mindepth 2 -maxdepth 3 \
      -name "vtk-$vtk_version-source.tar.xz" -print -quit 2>/dev/null || true)
  fi
  if [ -z "$VTKICE_VTK_SOURCE" ]; then
    echo "./ice.sh wheel: set VTKICE_VTK_SOURCE to VTK $vtk_version's source archive" \
      "(vtk-$vtk_version-source.tar.xz, VTK's release download)" >&2
    exit 2
  fi
  export VTKICE_VTK_SOURCE
  VTKICE_PYTHON=$python bash .ci/vtk-sdk.sh "$sdk"
fi
sdk=$(cd "$sdk" && pwd)

status=0
stage "pip install . (scikit-build-core, against $sdk)"
CMAKE_PREFIX_PATH=$sdk "$venv/bin/pip" install --quiet --disable-pip-version-check \
  --no-build-isolation "$top"

stage "the project against the SDK (build in $root/build), ctest through EGL without X"
if [ ! -f "$root/build/build.ninja" ]; then
  cmake -S . -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$sdk" \
    -DPython3_EXECUTABLE="$top/$python"
fi
cmake --build "$root/build"
# The Python tests run under pytest below, on the installed package.
# In parallel as in ./ice.sh test-vtk (tests that measure time or memory run alone).
env -u DISPLAY VTKICE_BACKEND=egl ctest --test-dir "$root/build" --output-on-failure \
  -j "${VTKICE_TEST_JOBS:-$(nproc)}" -LE python \
  "$@" || status=1

stage "pytest Testing/Wheel (the installed vtkice, PyVista)"
env -u DISPLAY "$venv/bin/python" -m pytest -q -p no:cacheprovider Testing/Wheel || status=1

stage "pip wheel . into a second fresh venv"
rm -rf "$root/dist" "$root/venv-fresh"
CMAKE_PREFIX_PATH=$sdk "$venv/bin/pip" wheel --quiet --disable-pip-version-check \
  --no-build-isolation --no-deps -w "$root/dist" "$top"
/usr/bin/python3 -m venv "$root/venv-fresh"
"$root/venv-fresh/bin/pip" install --quiet --disable-pip-version-check "vtk==$vtk_version" \
  "$root"/dist/vtkice-*.whl
(cd /tmp && env -u DISPLAY "$top/$root/venv-fresh/bin/python" -c "
import vtkmodules.vtkRenderingOpenGL2, vtkice
print('fresh venv: vtkice', vtkice.__file__, 'imports beside vtk', vtkice._BUILT_AGAINST)
m = vtkice.vtkIceMapper()
assert m.IsA('vtkOpenGLPolyDataMapper')
") || status=1
exit "$status"
