# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.vtkIceLook: the look's settings table (the one ice-render's options and presets use)
from Python, as the web viewer reads it. No render window: the settings act on objects only.
Run with Debian's /usr/bin/python3 (ctest) or the wheel's venv (pytest Testing/Wheel).
"""
import os
import sys
import tempfile

import vtk
import vtkice

from ice_test_helpers import check, run_tests

Look = vtkice.vtkIceLook
PRESETS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples",
                       "Presets")


def scene():
    """A mapper, a pass with its cube-map pass set (the dynamic cube map on) and a camera."""
    mapper, ice_pass = vtkice.vtkIceMapper(), vtkice.vtkIcePass()
    cube_maps, camera = vtkice.vtkIceCubeMapPass(), vtk.vtkCamera()
    ice_pass.SetCubeMapPass(cube_maps)
    return mapper, ice_pass, cube_maps, camera


def test_lists_every_setting_once():
    names = [Look.GetName(i) for i in range(Look.GetNumberOfSettings())]
    check(len(names) == len(set(names)), "names are unique")
    check({"eta", "cracks", "two-sided", "interior", "color", "cube-map", "view-angle"} <=
          set(names))
    check(Look.GetName(Look.GetNumberOfSettings()) is None, "out of range: None")
    check(Look.FindSetting("cracks") == names.index("cracks"))
    check(Look.FindSetting("no-such-setting") == -1)


def test_kinds_help_and_camera():
    kinds = {Look.GetKind(i) for i in range(Look.GetNumberOfSettings())}
    check(kinds == {"number", "integer", "switch", "choice", "vector"}, kinds)
    check(all(Look.GetHelp(i) for i in range(Look.GetNumberOfSettings())), "every one has help")
    check(Look.IsCameraSetting(Look.FindSetting("camera-position")))
    check(not Look.IsCameraSetting(Look.FindSetting("eta")))
    check(Look.GetSynonymOf(Look.FindSetting("eta")) == "ior", "eta is 1 / ior")
    check(Look.GetSynonymOf(Look.FindSetting("ior")) is None)


def test_ranges_are_the_librarys():
    mapper = vtkice.vtkIceMapper()
    ior = Look.FindSetting("ior")
    check(Look.GetMinimum(ior) == mapper.GetIceProperty().GetIndexOfRefractionMinValue())
    check(Look.GetMaximum(ior) == mapper.GetIceProperty().GetIndexOfRefractionMaxValue())
    check(Look.GetMaximum(Look.FindSetting("eta")) == 1.0, "eta: air / ice, up to 1")
    cracks = Look.FindSetting("cracks")
    check(Look.GetMaximum(cracks) == mapper.GetIceProperty().GetNumberOfCracksMaxValue())
    check(Look.GetMinimum(Look.FindSetting("glistening")) == 0.0, "a switch has no range")


def test_choices_in_enum_order():
    interior = Look.FindSetting("interior")
    names = [Look.GetChoice(interior, j) for j in range(Look.GetNumberOfChoices(interior))]
    check(names == ["paper-passes", "screen-space"], names)
    check(names.index("paper-passes") == vtkice.vtkIceMapper.InteriorPaperPasses)
    check(names.index("screen-space") == vtkice.vtkIceMapper.InteriorScreenSpace)
    check(Look.GetChoice(interior, 2) is None)
    check(Look.GetNumberOfChoices(Look.FindSetting("eta")) == 0)


def test_defaults():
    mapper = vtkice.vtkIceMapper()
    eta = float(Look.GetDefault(Look.FindSetting("eta")))
    check(abs(eta - mapper.GetIceProperty().GetRefractionRatio()) < 1e-9, "printed with 10 digits")
    check(Look.GetDefault(Look.FindSetting("cube-map")) == "on")
    check(Look.GetDefault(Look.FindSetting("camera-position")) == "", "the scene frames its model")


def test_apply_sets_and_value_reads():
    mapper, ice_pass, cube_maps, camera = scene()
    check(Look.Apply(mapper, ice_pass, cube_maps, camera, "cracks", "7") == "")
    check(mapper.GetIceProperty().GetNumberOfCracks() == 7)
    check(Look.GetValue(mapper, ice_pass, cube_maps, camera, "cracks") == "7")
    check(Look.Apply(mapper, ice_pass, cube_maps, camera, "cube-map", "off") == "")
    check(ice_pass.GetCubeMapPass() is None)
    check(Look.Apply(mapper, ice_pass, cube_maps, camera, "interior", "paper-passes") == "")
    check(mapper.GetInteriorMethod() == vtkice.vtkIceMapper.InteriorPaperPasses)
    check(Look.Apply(mapper, ice_pass, cube_maps, camera, "color", "0.5,0.6,0.7") == "")
    check(mapper.GetIceProperty().GetIceColor() == (0.5, 0.6, 0.7))


def test_apply_refuses_bad_values_and_changes_nothing():
    mapper, ice_pass, cube_maps, camera = scene()
    before = mapper.GetIceProperty().GetRefractionRatio()
    problem = Look.Apply(mapper, ice_pass, cube_maps, camera, "eta", "50")
    check("bad eta '50'" in problem and "[" in problem, problem)
    problem = Look.Apply(mapper, ice_pass, cube_maps, camera, "eta", "1.31")
    check("--ior 1.31" in problem, "an eta above 1 names the ior: " + problem)
    check(mapper.GetIceProperty().GetRefractionRatio() == before)
    check("unknown setting" in Look.Apply(mapper, ice_pass, cube_maps, camera, "etta", "1"))
    check("one of" in Look.Apply(mapper, ice_pass, cube_maps, camera, "interior", "fast"))
    # The single-pass interior is gone: its name is refused with the choices there are.
    problem = Look.Apply(mapper, ice_pass, cube_maps, camera, "interior", "single-pass")
    check("screen-space" in problem, problem)
    check(Look.Apply(None, ice_pass, cube_maps, camera, "eta", "0.7") != "", "no mapper")
    check(Look.GetValue(None, ice_pass, cube_maps, camera, "eta") == "")


def test_apply_preset():
    mapper, ice_pass, cube_maps, camera = scene()
    glacier = os.path.join(PRESETS, "glacier.ice")
    check(Look.ApplyPreset(mapper, ice_pass, cube_maps, camera, glacier) == "")
    look = mapper.GetIceProperty()
    check(look.GetNumberOfCracks() == 5 and look.GetNumberOfAirPlanes() == 0 and
          mapper.GetMaxBounces() == 8)
    with tempfile.TemporaryDirectory() as folder:
        bad = os.path.join(folder, "bad.ice")
        with open(bad, "w") as f:
            f.write("cracks = 3\neta = 50\n")
        problem = Look.ApplyPreset(mapper, ice_pass, cube_maps, camera, bad)
    check(problem.startswith(bad + ":2: "), problem)
    check(look.GetNumberOfCracks() == 5, "a preset with a problem changes nothing")


def main():
    return run_tests(globals())


if __name__ == "__main__":
    sys.exit(main())
