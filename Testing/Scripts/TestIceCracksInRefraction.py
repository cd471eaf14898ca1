# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""ice-render --cracks-in-refraction (cracks drawn into the back faces, bending the refraction)
draws no dark line where a crack is seen edge-on: the block of the paper look has no more dark
pixels with it than without it (a crack edge-on once swung the refraction into the dark trees of
the dynamic cube map along a jagged line: 12 % more dark pixels).

usage: TestIceCracksInRefraction.py ICE_RENDER WORK_DIR   (Debian's /usr/bin/python3, for vtk)
"""
import os
import sys

from ice_render_tool import Checks, render

ICE_RENDER, WORK = sys.argv[1], sys.argv[2]
LOOK = ["--model", "block", "--preset", "paper", "--size", "640x480"]


def dark_pixels(pixels):
    return sum(1 for p in pixels if sum(p) / 3 < 45)


def main():
    os.makedirs(WORK, exist_ok=True)
    check = Checks()
    without, error = render(ICE_RENDER, WORK, "without", *LOOK)
    with_cracks, error_with = render(ICE_RENDER, WORK, "with", *LOOK, "--cracks-in-refraction")
    if error or error_with:
        sys.exit("ice-render: %s" % (error or error_with))
    off, on = dark_pixels(without), dark_pixels(with_cracks)
    check("--cracks-in-refraction adds no dark line", on <= 1.03 * off,
          "%d dark pixels with it, %d without" % (on, off))
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
