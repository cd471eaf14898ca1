# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Ice View honours the view's own tone mapping (UseToneMapping, Exposure): ParaView puts its
tone-mapping pass around the view's render pass, which in the Ice View is vtkIcePass. With it on
and an exposure of 2, the picture brightens, the background is mapped exactly as a Render View
maps it, and eta=1 ice (refraction ratio 1, no reflection) stays invisible against it: the ice's
colour goes through the same curve as the background around it."""
import os
import sys

import numpy
from paraview.simple import Delete, Hide, Show, Sphere

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

h.load_plugin()
out = os.environ.get("VTKICE_TEST_OUTPUT", ".")
sphere = Sphere(ThetaResolution=96, PhiResolution=96, Radius=1)


def tone_mapped(view):
    view.UseToneMapping = 1
    view.Exposure = 2.0


view = h.make_view("IceView")
display = Show(sphere, view)
h.look_at(view, (0.3, 0.5, 5.0))
surface = h.capture(view, os.path.join(out, "tone-mapping-surface.png"))
display.Representation = "Ice"
h.invisible_ice(display)
plain = h.capture(view, os.path.join(out, "tone-mapping-off.png"))
tone_mapped(view)
mapped = h.capture(view, os.path.join(out, "tone-mapping-on.png"))
Hide(sphere, view)
alone = h.capture(view, os.path.join(out, "tone-mapping-on-alone.png"))

reference = h.make_view("RenderView")
h.look_at(reference, (0.3, 0.5, 5.0))
tone_mapped(reference)
render_view = h.capture(reference, os.path.join(out, "tone-mapping-render-view.png"))

h.check(mapped.mean() - plain.mean() > 20.0,
        "an exposure of 2 brightens the Ice View (mean grey %.1f -> %.1f)" %
        (plain.mean(), mapped.mean()))
d = h.difference(alone, render_view)
h.check(d.max() <= 2, "the Ice View's background is tone mapped as a Render View's (largest "
        "difference %d)" % d.max())
# The sphere's silhouette: where its surface differed from the empty view, both untone-mapped.
view.UseToneMapping = 0
empty = h.capture(view, os.path.join(out, "tone-mapping-off-alone.png"))
inside = h.difference(surface, empty) > 0
interior = h.shrink(inside, 2)
d = h.difference(mapped, alone)
h.check(interior.sum() > 10000 and d[interior].mean() < 1.0 and
        numpy.percentile(d[interior], 99) <= 3,
        "eta=1 ice stays invisible with tone mapping on (%d pixels: mean %.2f, p99 %.0f)" %
        (interior.sum(), d[interior].mean(), numpy.percentile(d[interior], 99)))
Delete(reference)
Delete(view)
h.finish()
