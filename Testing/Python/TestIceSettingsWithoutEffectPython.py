# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""A setting that cannot show says so, once: snow needs Glistening, absorption needs vtkIcePass
(the back faces give the path in the ice), the milky core and the bubbles the screen-space
interior. Where it
shows, nothing is said."""
import sys

import vtk
import vtkice

from ice_test_helpers import add_ice, check, run_tests, sky_renderer


def warnings_of_one_render(configure, with_pass):
    """The warning text of rendering a sphere whose mapper `configure` set up, twice."""
    renderer = sky_renderer(32)
    mapper, _ = add_ice(renderer, vtk.vtkSphereSource())
    mapper.GetIceProperty().SetNumberOfCracks(0)
    mapper.GetIceProperty().SetNumberOfAirPlanes(0)
    configure(mapper)
    if with_pass:
        renderer.SetPass(vtkice.vtkIcePass())
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(64, 64)
    window.AddRenderer(renderer)
    output = vtk.vtkStringOutputWindow()
    previous = vtk.vtkOutputWindow.GetInstance()
    vtk.vtkOutputWindow.SetInstance(output)
    vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_OFF)
    try:
        window.Render()
        window.Render()
    finally:
        vtk.vtkOutputWindow.SetInstance(previous)
        vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_INFO)
    window.Finalize()
    return output.GetOutput()


def snow(mapper):
    mapper.GetIceProperty().SetSnowAmount(0.6)


def snow_and_glistening(mapper):
    mapper.GetIceProperty().SetSnowAmount(0.6)
    mapper.GetIceProperty().GlisteningOn()


def absorption(mapper):
    mapper.GetIceProperty().SetAttenuationColor(0.5, 0.7, 0.9)
    mapper.GetIceProperty().SetAttenuationDistance(1.0)


def core_in_paper_passes(mapper):
    mapper.GetIceProperty().SetMilkyCoreRadius(0.5)
    mapper.SetInteriorMethod(vtkice.vtkIceMapper.InteriorPaperPasses)


def core_in_screen_space(mapper):
    mapper.GetIceProperty().SetMilkyCoreRadius(0.5)


def bubbles_in_paper_passes(mapper):
    mapper.GetIceProperty().SetBubbleDensity(0.5)
    mapper.SetInteriorMethod(vtkice.vtkIceMapper.InteriorPaperPasses)


def bubbles_in_screen_space(mapper):
    mapper.GetIceProperty().SetBubbleDensity(0.5)


def bounces_with_blended_normals(mapper):
    mapper.SetMaxBounces(4)


def bounces_with_the_exit_point(mapper):
    mapper.SetMaxBounces(4)
    mapper.SetTwoSidedMethodToExitPoint()


def test_snow_without_glistening_warns_once():
    text = warnings_of_one_render(snow, with_pass=True)
    check(text.count("shows nothing") == 1 and "Glistening on" in text, text)


def test_snow_with_glistening_says_nothing():
    text = warnings_of_one_render(snow_and_glistening, with_pass=True)
    check("nothing" not in text, text)


def test_absorption_without_the_pass_warns_once():
    text = warnings_of_one_render(absorption, with_pass=False)
    check(text.count("show nothing") == 1 and "vtkIcePass" in text, text)


def test_absorption_with_the_pass_says_nothing():
    text = warnings_of_one_render(absorption, with_pass=True)
    check("nothing" not in text, text)


def test_core_with_paper_passes_warns_once():
    text = warnings_of_one_render(core_in_paper_passes, with_pass=True)
    check(text.count("shows nothing") == 1 and "InteriorScreenSpace" in text, text)


def test_core_in_screen_space_says_nothing():
    text = warnings_of_one_render(core_in_screen_space, with_pass=True)
    check("nothing" not in text, text)


def test_bubbles_with_paper_passes_warn_once():
    text = warnings_of_one_render(bubbles_in_paper_passes, with_pass=True)
    check(text.count("shows nothing") == 1 and "BubbleDensity" in text and
          "InteriorScreenSpace" in text, text)


def test_bubbles_in_screen_space_say_nothing():
    text = warnings_of_one_render(bubbles_in_screen_space, with_pass=True)
    check("nothing" not in text, text)


def test_bounces_with_blended_normals_warn_once():
    text = warnings_of_one_render(bounces_with_blended_normals, with_pass=True)
    check(text.count("shows nothing") == 1 and "SetTwoSidedMethodToExitPoint" in text, text)


def test_bounces_with_the_exit_point_say_nothing():
    text = warnings_of_one_render(bounces_with_the_exit_point, with_pass=True)
    check("nothing" not in text, text)


def main():
    return run_tests(globals())


if __name__ == "__main__":
    sys.exit(main())
