# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the scripts that test ice-render's pictures share: one line per check, rendering to a PNG
and reading its pixels back (Debian's /usr/bin/python3, for vtk)."""
import os
import subprocess

import vtk


class Checks:
    """Prints "ok   NAME" or "FAIL NAME" per check and counts the failures."""

    def __init__(self):
        self.failures = 0

    def __call__(self, name, ok, detail=""):
        print(("ok   " if ok else "FAIL ") + name + (": " + detail if detail else ""))
        self.failures += 0 if ok else 1


def run(ice_render, *args):
    return subprocess.run([ice_render, *args], capture_output=True, text=True, timeout=300)


def read_png(path):
    """The pixels of a PNG file: a list of RGB tuples, row by row from the bottom."""
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    return [scalars.GetTuple(i)[:3] for i in range(scalars.GetNumberOfTuples())]


def render(ice_render, work, name, *args):
    """Renders to WORK/NAME.png; returns (its pixels, ice-render's error text or None)."""
    path = os.path.join(work, name + ".png")
    result = run(ice_render, *args, "--out", path)
    if result.returncode != 0:
        return None, result.stderr.strip()
    return read_png(path), None
