#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# The `vtk` wheel's Python environment with vtkice installed, made where missing (./ice.sh wheel,
# ./ice.sh web):
#   1. a venv in build-wheel/venv with vtk, pyvista and pytest (the versions below)
#   2. the wheel's SDK in build-wheel/sdk (./ice.sh vtk-sdk; VTKICE_VTK_SOURCE names VTK's source)
#   3. pip install . into the venv (the vtkice package beside the wheel; incremental)
#   4. with --web: the web viewer's packages (Examples/Web/requirements.txt)
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
vtk_version=9.7.0
pyvista_version=0.49.2
root=${VTKICE_WHEEL_DIR:-build-wheel}
venv=$root/venv
sdk=$root/sdk
python=$venv/bin/python
pip=("$venv/bin/pip" install --quiet --disable-pip-version-check)
stage() { echo "== wheel lane: $*"; }

if ! "$python" -c "import vtkmodules, pyvista, pytest, scikit_build_core
from vtkmodules.vtkCommonCore import vtkVersion
assert vtkVersion.GetVTKVersion() == '$vtk_version'" 2>/dev/null; then
  stage "venv $venv (vtk $vtk_version, pyvista $pyvista_version)"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "${pip[@]}" "vtk==$vtk_version" "pyvista==$pyvista_version" pytest scikit-build-core
fi

if [ ! -f "$sdk/lib/cmake/vtk/vtk-config.cmake" ] ||
  [ "$(readlink -f "$sdk/vtkmodules")" != "$("$python" -c 'import os, vtkmodules; print(os.path.realpath(os.path.dirname(vtkmodules.__file__)))')" ]; then
  stage "SDK $sdk"
  . .ci/vtk-source.sh
  vtkice_vtk_source "$vtk_version"
  # The work folder ./ice.sh wheels keeps too: the SDKs share the unpacked source and VTK's build.
  VTKICE_SDK_WORK=${VTKICE_SDK_WORK:-build-wheels/sdk-work} VTKICE_PYTHON=$python \
    bash .ci/vtk-sdk.sh "$sdk"
fi
sdk=$(cd "$sdk" && pwd)

stage "pip install . (scikit-build-core, against $sdk)"
CMAKE_PREFIX_PATH=$sdk "${pip[@]}" --no-build-isolation "$top"

if [ "${1:-}" = --web ]; then
  stage "the web viewer's packages (Examples/Web/requirements.txt)"
  "${pip[@]}" -r Examples/Web/requirements.txt
fi
