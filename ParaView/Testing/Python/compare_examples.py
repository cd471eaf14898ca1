# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""script.png state.png pvbatch.png: the three renderings agree and the ice differs from the
example rendered as a plain surface would be (checked by its colour spread)."""
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402
script, state, batch = (h.read_png(path) for path in sys.argv[1:4])
for name, image in (("state file", state), ("pvbatch", batch)):
    d = h.difference(script, image)
    h.check(d.mean() < 0.5 and numpy.percentile(d, 99) <= 8,
            "%s renders the script's image (mean %.3f, p99 %.0f)" %
            (name, d.mean(), numpy.percentile(d, 99)))
# The ice (the centre of the picture) refracts the floor and the sky: many colours, no flat fill.
centre = script[200:400, 300:500].reshape(-1, 3)
h.check(len(numpy.unique(centre // 8, axis=0)) > 200, "the example's ice shows a refracted scene")
h.finish()
