# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkIcePass from Python: two-sided refraction changes the ice, both two-sided methods (the
paper's blended normals, the exit point) are selectable and differ, the one-sided switch restores
the pass-less image exactly, and a scene without ice is unchanged by the pass.

Run with Debian's /usr/bin/python3.
"""
import sys

import vtk
import vtkice

from ice_test_helpers import add_ice, check, grab, mean_difference, sky_renderer


def main():
    renderer = sky_renderer(128)

    teapot = vtkice.vtkIceTeapotSource()
    mapper, ice = add_ice(renderer, teapot)
    # Compare the refraction alone: no cracks, air or bumps.
    mapper.GetIceProperty().SetNumberOfCracks(0)
    mapper.GetIceProperty().SetNumberOfAirPlanes(0)
    mapper.GetIceProperty().SetBumpStrength(0.0)

    window = vtk.vtkRenderWindow()
    window.SetSize(200, 150)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 0.6, 4.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.ResetCameraClippingRange()
    box = (80, 120, 60, 90)  # inside the teapot's body

    without_pass = grab(window)
    ice_pass = vtkice.vtkIcePass()
    renderer.SetPass(ice_pass)
    two_sided = grab(window)
    check(ice_pass.GetNumberOfIceProps() == 1)
    check(mapper.GetTwoSidedMethod() == vtkice.vtkIceMapper.TwoSidedBlendedNormals)
    mapper.SetTwoSidedMethodToExitPoint()
    exit_point = grab(window)
    check(mapper.GetTwoSidedMethod() == vtkice.vtkIceMapper.TwoSidedExitPoint)
    mapper.SetTwoSidedMethod(7)
    check(mapper.GetTwoSidedMethod() == vtkice.vtkIceMapper.TwoSidedExitPoint, "clamped")
    mapper.SetTwoSidedMethodToBlendedNormals()
    check(mean_difference(grab(window), two_sided, 0, 200, 0, 150) == 0.0,
          "back to the blended normals, the same picture")
    mapper.TwoSidedRefractionOff()
    one_sided = grab(window)

    methods = mean_difference(two_sided, exit_point, *box)
    print("exit point vs blended normals: %.2f/255" % methods)
    check(methods >= 1.0, "the exit point must refract otherwise")
    changed = mean_difference(without_pass, two_sided, *box)
    restored = mean_difference(without_pass, one_sided, *box)
    print("two-sided vs one-sided: %.2f/255; pass with two-sided off vs no pass: %.2f/255"
          % (changed, restored))
    check(changed >= 6.0, "two-sided refraction must change the ice")
    check(restored == 0.0, "TwoSidedRefractionOff must give the one-sided image")

    # The interior methods from Python: cracks and air once per pixel (default) or by the paper's
    # passes; both change the ice, the paper's passes differently.
    mapper.TwoSidedRefractionOn()
    check(mapper.GetInteriorMethod() == vtkice.vtkIceMapper.InteriorScreenSpace)
    mapper.GetIceProperty().SetNumberOfCracks(2)
    mapper.GetIceProperty().SetNumberOfAirPlanes(19)
    screen = grab(window)
    mapper.SetInteriorMethodToPaperPasses()
    check(mapper.GetInteriorMethod() == vtkice.vtkIceMapper.InteriorPaperPasses)
    paper = grab(window)
    mapper.SetInteriorMethodToScreenSpace()
    check(mapper.GetInteriorMethod() == vtkice.vtkIceMapper.InteriorScreenSpace)
    # 2, the screen-space interior's value before the single pass went, still means it.
    mapper.SetInteriorMethod(2)
    check(mapper.GetInteriorMethod() == vtkice.vtkIceMapper.InteriorScreenSpace,
          "an old saved 2 is the screen-space interior")
    interior = (mean_difference(two_sided, paper, *box), mean_difference(two_sided, screen, *box),
                mean_difference(paper, screen, *box))
    print("interior: paper passes %.2f/255, screen space %.2f/255 from the clear ice, %.2f/255 apart"
          % interior)
    check(interior[0] >= 3.0 and interior[1] >= 3.0, "cracks and air must show in both methods")
    check(interior[2] > 0.0, "the methods differ in detail")
    mapper.GetIceProperty().SetNumberOfCracks(0)
    mapper.GetIceProperty().SetNumberOfAirPlanes(0)

    ice.VisibilityOff()
    with_pass_no_ice = grab(window)
    renderer.SetPass(None)
    no_pass_no_ice = grab(window)
    unchanged = mean_difference(with_pass_no_ice, no_pass_no_ice, 0, 200, 0, 150)
    print("scene without ice, with vs without the pass: %.3f/255" % unchanged)
    check(unchanged == 0.0)
    print("5 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
