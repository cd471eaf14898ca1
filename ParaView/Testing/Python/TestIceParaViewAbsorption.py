# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Absorption in the Ice View: with Absorption on, eta=1 ice (refraction ratio 1, no reflection)
in front of a single-colour background shows that colour times the transmittance of the path
through it, c^(d / D) (glTF's attenuation colour c and distance D): at the centre of a sphere of
radius 1 seen head on, d = 2. Off, the ice is invisible again."""
import os
import sys

import numpy
from paraview.simple import Delete, Show, Sphere

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

h.load_plugin()
out = os.environ.get("VTKICE_TEST_OUTPUT", ".")
sphere = Sphere(ThetaResolution=96, PhiResolution=96, Radius=1)
view = h.make_view("IceView", gradient=False)
view.Background = [0.8, 0.8, 0.8]
display = Show(sphere, view)
h.look_at(view, (0.0, 0.0, 5.0))
display.Representation = "Ice"
h.invisible_ice(display)
invisible = h.capture(view, os.path.join(out, "absorption-off.png"))

color = numpy.array([0.3, 0.6, 0.9])
distance = 1.5
display.Absorption = 1
display.AttenuationColor = list(color)
display.AttenuationDistance = distance
absorbed = h.capture(view, os.path.join(out, "absorption-on.png"))
rows, columns = absorbed.shape[:2]
centre = (slice(rows // 2 - 2, rows // 2 + 3), slice(columns // 2 - 2, columns // 2 + 3))
expected = invisible[centre].reshape(-1, 3).mean(axis=0) * color ** (2.0 / distance)
measured = absorbed[centre].reshape(-1, 3).mean(axis=0)
h.check(numpy.abs(measured - expected).max() <= 4.0,
        "the sphere's centre shows the background times c^(2/D): %s, expected %s" %
        (numpy.round(measured, 1), numpy.round(expected, 1)))

display.Absorption = 0
again = h.capture(view, os.path.join(out, "absorption-off-again.png"))
h.check(h.difference(again, invisible).max() == 0, "Absorption off gives the invisible ice back")
Delete(view)
h.finish()
