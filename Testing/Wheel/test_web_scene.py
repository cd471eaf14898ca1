# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The web viewer's scene without a browser (Examples/Web/ice_web_scene.py): the controls come
from vtkice.vtkIceLook, uploads are checked as ice-render checks its --model, a screenshot is a
PNG of the picture."""
import io
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "Examples" / "Web"))
ice_web_scene = pytest.importorskip("ice_web_scene")
import vtkice  # noqa: E402


def test_controls_are_the_tables_look_settings():
    names = [s["name"] for s in ice_web_scene.look_settings()]
    Look = vtkice.vtkIceLook
    table = [Look.GetName(i) for i in range(Look.GetNumberOfSettings())
             if not Look.IsCameraSetting(i) and not Look.GetSynonymOf(i)]
    assert names == table and "cracks" in names and "camera-position" not in names
    assert "ior" in names and "eta" not in names, "one control for ior and its synonym eta"


def test_obj_upload_is_read_and_framed(tmp_path):
    obj = tmp_path / "tetra.obj"
    obj.write_text("v 0 0 0\nv 4 0 0\nv 0 4 0\nv 0 0 4\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    polydata, problem = ice_web_scene.read_model_file(str(obj))
    assert problem == "" and polydata.GetNumberOfPolys() == 4
    bounds = polydata.GetBounds()
    assert max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]) == \
        pytest.approx(2.0)


def test_cut_ply_upload_is_refused(tmp_path):
    ply = tmp_path / "cut.ply"
    ply.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 100\n"
                    b"property float x\nproperty float y\nproperty float z\nend_header\n" +
                    b"\0" * 12)
    polydata, problem = ice_web_scene.read_model_file(str(ply))
    assert polydata is None and "cut off" in problem


def test_upload_without_polygons_is_refused(tmp_path):
    obj = tmp_path / "points.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\n")
    polydata, problem = ice_web_scene.read_model_file(str(obj))
    assert polydata is None and "no polygons" in problem


def test_other_file_types_are_refused(tmp_path):
    other = tmp_path / "model.vtk"
    other.write_text("# vtk DataFile Version 3.0\n")
    assert ice_web_scene.read_model_file(str(other)) == (None, "not an STL, PLY or OBJ file")


def test_screenshot_is_a_png_of_the_ice():
    from PIL import Image

    scene = ice_web_scene.IceScene(size=(320, 240))
    ice = np.asarray(Image.open(io.BytesIO(scene.screenshot_png())).convert("RGB"), float)
    scene.set_ice(False)
    plain = np.asarray(Image.open(io.BytesIO(scene.screenshot_png())).convert("RGB"), float)
    assert ice.shape == (240, 320, 3)
    assert (np.abs(ice - plain).max(axis=2) > 40).mean() > 0.02


def test_scene_opens_on_ice_renders_default_look():
    """The viewer starts from ice-render's default look (the ice-cube preset), not the library's
    paper look; preset=None keeps the library's defaults."""
    Look = vtkice.vtkIceLook
    natural = ice_web_scene.IceScene(size=(64, 48))
    library = ice_web_scene.IceScene(size=(64, 48), preset=None)
    # The shipped preset's own values, as its file writes them.
    with open(vtkice.preset_path("ice-cube")) as preset:
        shipped = dict(line.split(" = ", 1) for line in preset.read().splitlines()
                       if " = " in line and not line.startswith("#"))
    for name in ("bounces", "two-sided-method", "bubbles", "milky-core", "air", "cracks"):
        assert natural.value(name) == shipped[name].strip(), name
        assert library.value(name) == Look.GetDefault(Look.FindSetting(name)), name
    assert library.value("bounces") == "1" and library.value("air") == "19"
    # The page's first state names that preset: the app does not apply it again.
    assert natural.preset == "ice-cube" and library.preset is None
    assert natural.apply("cracks", "3") == "" and natural.preset is None


def test_preset_replaces_the_look():
    scene = ice_web_scene.IceScene(size=(64, 48))
    assert "glacier" in ice_web_scene.presets()
    assert scene.apply("milkiness", "0.1") == ""
    assert scene.apply_preset("glacier") == ""
    assert scene.value("cracks") == "5" and scene.value("milkiness") == "0.7"
    assert scene.apply_preset("clear") == ""
    # clear.ice does not name milkiness: glacier's goes back to the default.
    assert scene.value("cracks") == "0" and scene.value("milkiness") == \
        vtkice.vtkIceLook.GetDefault(vtkice.vtkIceLook.FindSetting("milkiness"))
