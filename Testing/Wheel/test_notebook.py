# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Examples/Python/ice_jupyter.ipynb executed as Jupyter would (nbclient, a kernel of this venv),
without an X server: it shows ice with PyVista's trame server backend and writes the picture,
and the same scene with a plain surface."""
import os
import pathlib

import numpy as np
import pytest
from PIL import Image

nbclient = pytest.importorskip("nbclient")
nbformat = pytest.importorskip("nbformat")

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "Examples" / "Python" / "ice_jupyter.ipynb"


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    folder = tmp_path_factory.mktemp("notebook")
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    display = os.environ.pop("DISPLAY", None)
    try:
        nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3",
                                resources={"metadata": {"path": str(folder)}}).execute()
    finally:
        if display is not None:
            os.environ["DISPLAY"] = display
    return notebook, folder


def test_shows_the_plotter_as_a_trame_widget(executed):
    notebook, _ = executed
    outputs = [o for cell in notebook.cells for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o["output_type"] == "error"]
    widgets = [o for o in outputs if "application/vnd.jupyter.widget-view+json" in
               o.get("data", {})]
    assert len(widgets) == 1, "plotter.show() displays one trame (server) widget"


def test_picture_shows_ice(executed):
    _, folder = executed
    ice = np.asarray(Image.open(folder / "ice_jupyter.png").convert("RGB"), dtype=float)
    plain = np.asarray(Image.open(folder / "plain_jupyter.png").convert("RGB"), dtype=float)
    assert ice.shape == plain.shape == (480, 640, 3)
    difference = np.abs(ice - plain).max(axis=2)
    # The teapot fills the middle: there the ice differs from the plain surface, at the
    # border (sky, floor) the two scenes agree.
    assert (difference[160:340, 200:440] > 40).mean() > 0.2
    assert (difference[:, :60] > 40).mean() < 0.05
