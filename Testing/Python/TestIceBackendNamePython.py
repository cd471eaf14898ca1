# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.use_backend() refuses a name it does not know with a ValueError naming the choices,
and changes nothing (the next render window is VTK's usual one)."""
import sys

import vtk
import vtkice

from ice_test_helpers import check


def main():
    try:
        vtkice.use_backend("vulkan")
    except ValueError as error:
        message = str(error)
    else:
        message = ""
    print("use_backend('vulkan'): " + message)
    check("'vulkan'" in message and "auto, x, egl or osmesa" in message,
          "an unknown back end is refused with the choices")
    window = vtk.vtkRenderWindow()
    check(window.GetClassName() != "vtkIceHeadlessRenderWindow",
          "a refused name installs no back end: " + window.GetClassName())
    print("1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
