# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.vtkIceModelFile: ice-render's checks of a model file before a reader reads it, from
Python (the web viewer's uploads). Files are made here; nothing is rendered.
"""
import os
import struct
import sys
import tempfile

import vtkice

from ice_test_helpers import check, run_tests

Check = vtkice.vtkIceModelFile.CheckFile


def binary_stl(triangles, announced):
    return b"\0" * 80 + struct.pack("<I", announced) + b"\0" * (50 * triangles)


def write(folder, name, data):
    path = os.path.join(folder, name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def test_missing_file(folder):
    problem = Check(os.path.join(folder, "missing.stl"))
    check(problem.startswith("cannot open model file"), problem)


def test_not_a_regular_file(folder):
    problem = Check(folder)
    check("not a regular file" in problem, problem)


def test_stl_that_agrees_with_its_header(folder):
    check(Check(write(folder, "good.stl", binary_stl(3, 3))) == "")


def test_stl_that_promises_more_triangles(folder):
    problem = Check(write(folder, "short.stl", binary_stl(2, 1000)))
    check("does not match its header" in problem and "short.stl" in problem, problem)


def test_cut_ply(folder):
    header = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n"
    problem = Check(write(folder, "cut.ply", header + b"0\n1\n"))
    check("PLY file" in problem, problem)


def test_other_formats_are_left_to_their_reader(folder):
    check(Check(write(folder, "any.obj", b"v 0 0 0\n")) == "")


def test_printable(folder):
    check(vtkice.vtkIceModelFile.Printable("a\x01b", 240) == "a?b")


def main():
    with tempfile.TemporaryDirectory() as folder:
        return run_tests(globals(), folder)


if __name__ == "__main__":
    sys.exit(main())
