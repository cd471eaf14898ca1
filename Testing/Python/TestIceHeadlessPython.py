# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.use_backend() lets a script without an X display render ice.

DISPLAY is removed before VTK is imported, as on a server; without vtkice.use_backend() Debian's
VTK 9.1 aborts at the first render ("bad X server connection"). The default vtkRenderWindow must
then render the ice sphere (its pixels differ from the background alone) through a back end
that needs no X server.
"""
import os
import sys

os.environ.pop("DISPLAY", None)

import vtk  # noqa: E402
import vtkice  # noqa: E402

from ice_test_helpers import add_ice, check, grab, mean_difference, sky_renderer  # noqa: E402


def main():
    found = vtkice.use_backend("auto")
    print("use_backend('auto'): " + found)
    check(not found.startswith("x"), "auto without DISPLAY must not choose X: " + found)

    renderer = sky_renderer(64)
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(48)
    mapper, ice = add_ice(renderer, sphere)

    window = vtk.vtkRenderWindow()
    window.SetSize(120, 120)
    window.AddRenderer(renderer)
    renderer.GetActiveCamera().SetPosition(0.0, 0.3, 3.0)
    renderer.ResetCameraClippingRange()

    ice.VisibilityOff()
    background = grab(window)
    ice.VisibilityOn()
    with_ice = grab(window)
    print("window %s" % window.GetClassName())
    check(window.GetClassName() != "vtkXOpenGLRenderWindow", "the window needs no X server")
    difference = mean_difference(background, with_ice, 45, 75, 45, 75)
    print("ice against the background: mean difference %.2f/255" % difference)
    check(difference >= 5.0, "the ice sphere must be rendered")
    print("1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
