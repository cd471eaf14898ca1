#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# ./ice.sh wheel [ctest options]: VTK Ice on the `vtk` wheel from PyPI (VTK 9.7.0) with PyVista.
#   1. a venv in build-wheel/venv with vtk, pyvista and pytest (the versions in .ci/wheel-env.sh)
#   2. the wheel's SDK in build-wheel/sdk (./ice.sh vtk-sdk; VTKICE_VTK_SOURCE names VTK's source)
#   3. pip install . into the venv (the vtkice package beside the wheel), the web viewer's
#      packages (Examples/Web/requirements.txt) and the web tests' (Testing/Wheel/requirements.txt)
#   4. the whole project built against the SDK (build-wheel/build), its ctest suite through EGL
#      without an X server, on the wheel's libraries (the Python tests: in 5)
#   5. pytest Testing/Wheel: the installed package, the project's Python tests on it, PyVista,
#      the web viewer in Debian's headless Chromium and the Jupyter notebook (nbclient)
# The wheels users install are made and tried in fresh venvs by ./ice.sh wheels and wheels-test.
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
root=${VTKICE_WHEEL_DIR:-build-wheel}
venv=$root/venv
python=$venv/bin/python
vtk_version=$(sed -n 's/^vtk_version=//p' .ci/wheel-env.sh)
stage() { echo "== wheel lane: $*"; }

# Chromium and its WebDriver for the web viewer's browser tests, with the first list.
bash .ci/install-deps.sh web

status=0
# Steps 1-3, and the web viewer's packages (shared with ./ice.sh web).
bash .ci/wheel-env.sh --web
sdk=$(cd "$root/sdk" && pwd)
stage "the web tests' packages (Testing/Wheel/requirements.txt)"
"$venv/bin/pip" install --quiet --disable-pip-version-check -r Testing/Wheel/requirements.txt

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

exit "$status"
