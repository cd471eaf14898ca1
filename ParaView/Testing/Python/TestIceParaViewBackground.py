# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Without a skybox the ice shows the view's own background: eta=1 ice (refraction ratio 1, no
reflection) is invisible against a single-colour and a gradient background, in the Render View
and the Ice View. Before, the ice showed a built-in sky (green hills, a horizon) instead."""
import os
import sys

import numpy
from paraview.simple import Delete, Hide, Show, Sphere

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

h.load_plugin()
out = os.environ.get("VTKICE_TEST_OUTPUT", ".")
sphere = Sphere(ThetaResolution=96, PhiResolution=96, Radius=1)

for kind in ("RenderView", "IceView"):
    for background in ("single", "gradient"):
        name = "background-%s-%s" % (kind, background)
        view = h.make_view(kind, gradient=False)
        if background == "gradient":
            view.BackgroundColorMode = "Gradient"
            view.Background = [0.55, 0.65, 0.8]
            view.Background2 = [0.05, 0.1, 0.3]
        display = Show(sphere, view)
        h.look_at(view, (0.3, 0.5, 5.0))
        surface = h.capture(view, os.path.join(out, name + "-surface.png"))
        display.Representation = "Ice"
        h.invisible_ice(display)
        invisible = h.capture(view, os.path.join(out, name + "-invisible.png"))
        # The ice is drawn: tinted, it shows.
        display.IceColor = [1.0, 0.5, 0.5]
        tinted = h.capture(view, os.path.join(out, name + "-tinted.png"))
        Hide(sphere, view)
        alone = h.capture(view, os.path.join(out, name + "-alone.png"))
        inside = h.difference(surface, alone) > 0
        interior = h.shrink(inside, 2)
        h.check(interior.sum() > 10000 and h.difference(tinted, alone)[interior].mean() > 10,
                "%s: the ice is drawn (%d pixels; tinted, mean difference %.1f)" %
                (name, interior.sum(), h.difference(tinted, alone)[interior].mean()))
        # Inside the silhouette (less its anti-aliased rim) eta=1 ice shows the background as
        # the view draws it; the built-in sky differs by tens of levels.
        d = h.difference(invisible, alone)
        h.check(d[interior].mean() < 1.0 and numpy.percentile(d[interior], 99) <= 3,
                "%s: eta=1 ice is invisible against the background (mean %.2f, p99 %.0f, "
                "max %d)" % (name, d[interior].mean(), numpy.percentile(d[interior], 99),
                             d[interior].max()))
        h.check(d[~h.grow(inside, 1)].max() == 0, "%s: nothing changes around the ice" % name)
        Delete(view)

h.finish()
