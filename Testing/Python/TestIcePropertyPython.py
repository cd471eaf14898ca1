# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.vtkIceProperty from Python: the look as one object, shared between mappers; the mapper
has no setters of the look's parameters (vtkMapper does not mirror vtkProperty either). No render
window: the settings act on objects only.
"""
import sys

import vtkice

from ice_test_helpers import check, run_tests


def test_mapper_has_a_property_with_the_defaults():
    mapper = vtkice.vtkIceMapper()
    look = mapper.GetIceProperty()
    check(isinstance(look, vtkice.vtkIceProperty), "GetIceProperty returns a vtkIceProperty")
    check(look.GetIndexOfRefraction() == 1.31 and look.GetNumberOfCracks() == 2 and
          look.GetRoughness() == 0.0, "with the defaults")


def test_the_look_is_set_on_the_property_only():
    mapper = vtkice.vtkIceMapper()
    check(not hasattr(mapper, "SetRoughness") and not hasattr(mapper, "SetNumberOfCracks"),
          "the mapper has no look setters")
    check(hasattr(mapper, "SetInteriorMethod") and hasattr(mapper, "SetTwoSidedRefraction"),
          "how the ice is drawn stays on the mapper")


def test_shared_property():
    look = vtkice.vtkIceProperty()
    first, second = vtkice.vtkIceMapper(), vtkice.vtkIceMapper()
    first.SetIceProperty(look)
    second.SetIceProperty(look)
    before = second.GetMTime()
    first.GetIceProperty().SetCrackReflection(0.9)
    check(second.GetIceProperty().GetCrackReflection() == 0.9,
          "a change through one mapper shows in the other")
    check(second.GetMTime() > before, "and modifies it")


def test_none_restores_the_defaults():
    mapper = vtkice.vtkIceMapper()
    mapper.GetIceProperty().SetRoughness(1.0)
    mapper.SetIceProperty(None)
    check(mapper.GetIceProperty() is not None and mapper.GetIceProperty().GetRoughness() == 0.0,
          "SetIceProperty(None) gives a property with the defaults")


def test_nan_is_refused():
    look = vtkice.vtkIceProperty()
    look.GlobalWarningDisplayOff()
    look.SetFresnelPower(float("nan"))
    check(look.GetFresnelPower() == 3.0, "NaN is refused, the value kept")


def main():
    return run_tests(globals())


if __name__ == "__main__":
    sys.exit(main())
