# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Sourced: vtkice_vtk_source VERSION sets VTKICE_VTK_SOURCE to VTK VERSION's source archive, where
# VTKICE_VTK_SOURCE says, else found by name in a folder beside the checkout (where CI lays it);
# stops with what to do when there is none.
vtkice_vtk_source() {
  local version=$1 top
  top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  if [ -z "${VTKICE_VTK_SOURCE:-}" ]; then
    VTKICE_VTK_SOURCE=$(find "$(dirname "$top")" -mindepth 2 -maxdepth 3 \
      -name "vtk-$version-source.tar.xz" -print -quit 2>/dev/null || true)
  fi
  if [ -z "$VTKICE_VTK_SOURCE" ]; then
    echo "$(basename "$0"): set VTKICE_VTK_SOURCE to VTK $version's source archive" \
      "(vtk-$version-source.tar.xz, VTK's release download)" >&2
    exit 2
  fi
  export VTKICE_VTK_SOURCE
}
