# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice from Python: properties with VTK's clamping, and ice that renders correctly.

With RefractionRatio 1 and a huge FresnelPower, ice is invisible against a skybox of the same
cube map; with the defaults it is clearly visible. Run with Debian's /usr/bin/python3.
"""
import sys

import vtk
import vtkice

from ice_test_helpers import add_ice, check, grab, mean_difference, sky_renderer


def main():
    mapper = vtkice.vtkIceMapper()
    look = mapper.GetIceProperty()
    check(abs(look.GetIndexOfRefraction() - 1.31) < 1e-12)
    check(abs(look.GetRefractionRatio() - 1.0 / 1.31) < 1e-12, "RefractionRatio is 1 / IOR")
    look.SetIndexOfRefraction(1.5)
    check(abs(look.GetRefractionRatio() - 1.0 / 1.5) < 1e-12, "IOR sets RefractionRatio")
    look.SetIndexOfRefraction(1.31)
    check(look.GetFresnelPower() == 3.0)
    check(abs(look.GetBackNormalWeight() - 0.33) < 1e-12)
    look.SetBackNormalWeight(5.0)
    check(look.GetBackNormalWeight() == 1.0, "BackNormalWeight is clamped to [0, 1]")
    look.SetBackNormalWeight(0.33)

    renderer = sky_renderer(128)

    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    mapper, ice = add_ice(renderer, sphere, mapper)

    window = vtk.vtkRenderWindow()
    window.SetSize(160, 160)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 0.3, 3.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.ResetCameraClippingRange()

    # The sphere covers the central square of the image in every render below.
    box = (60, 100, 60, 100)
    ice.VisibilityOff()
    window.Render()
    background = grab(window)

    ice.VisibilityOn()
    mapper.GetIceProperty().SetRefractionRatio(1.0)
    mapper.GetIceProperty().SetFresnelPower(1.0e6)
    window.Render()
    invisible = mean_difference(background, grab(window), *box)

    mapper.GetIceProperty().SetIndexOfRefraction(1.31)
    mapper.GetIceProperty().SetFresnelPower(3.0)
    window.Render()
    visible = mean_difference(background, grab(window), *box)

    print("eta 1: mean difference %.3f/255; default ice: %.3f/255" % (invisible, visible))
    check(invisible <= 1.0, "ice with eta 1 must be invisible against the skybox")
    check(visible >= 5.0, "default ice must be visible")
    print("1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
