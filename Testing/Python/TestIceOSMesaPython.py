# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.use_backend("osmesa") either renders ice or refuses with a line saying what to do.

With VTK < 9.4 OSMesa needs VTK's GL calls routed to libIceHeadless, which Python (having
loaded VTK first) only gets with LD_PRELOAD; without it the back end must be refused before any
window is made, not render nothing with a GLEW error.
"""
import os
import sys

os.environ.pop("DISPLAY", None)

import vtk  # noqa: E402
import vtkice  # noqa: E402

from ice_test_helpers import add_ice, check, grab, mean_difference  # noqa: E402


def main():
    try:
        found = vtkice.use_backend("osmesa")
    except RuntimeError as error:
        message = str(error)
        print("use_backend('osmesa') refused: " + message)
        check("LD_PRELOAD=" in message or "no osmesa back end" in message,
              "the refusal says what to do")
        print("1 passed, 0 failed")
        return 0
    print("use_backend('osmesa'): " + found)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(0.2, 0.3, 0.4)
    sphere = vtk.vtkSphereSource()
    mapper, ice = add_ice(renderer, sphere)
    window = vtk.vtkRenderWindow()
    window.SetSize(80, 80)
    window.AddRenderer(renderer)
    ice.VisibilityOff()
    background = grab(window)
    ice.VisibilityOn()
    difference = mean_difference(background, grab(window), 30, 50, 30, 50)
    print("window %s, ice against the background %.2f/255" % (window.GetClassName(), difference))
    check(difference >= 5.0, "the ice sphere must be rendered")
    print("1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
