# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""prefix translucent-prefix: compares the images and per-rank statistics that distributed_scene.py
wrote for 1, 2 and 4 ranks (prefix-N.png, prefix-N-noice.png, prefix-N-<rank>.txt), and its
images with a translucent sphere on 1 and 2 ranks (translucent-prefix-N.png)."""
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402


def statistics(prefix, ranks):
    """{ice representation: [(local cells, local objects) per rank]}"""
    found = {}
    for rank in range(ranks):
        with open("%s-%d-%d.txt" % (prefix, ranks, rank)) as stats:
            for line in stats:
                words = line.split()
                if words and words[0].startswith("ice"):
                    found.setdefault(words[0], []).append((int(words[2]), int(words[4])))
    return found


prefix = sys.argv[1]
one = h.read_png(prefix + "-1.png")
# The ice: where the one-rank image differs from the same view without ice.
ice = h.difference(one, h.read_png(prefix + "-1-noice.png")) > 10
h.check(ice.sum() > 10000, "the scene shows ice (%d pixels)" % ice.sum())
single = statistics(prefix, 1)
for ranks in (2, 4):
    image = h.read_png("%s-%d.png" % (prefix, ranks))
    d = h.difference(one, image)
    h.check(d.mean() < 0.5 and numpy.percentile(d, 99) <= 8,
            "%d ranks render the 1-rank image (mean %.3f, p99 %.0f)" %
            (ranks, d.mean(), numpy.percentile(d, 99)))
    # Measured 1.4 and 22: the air planes and crack edges (each alone 0.09 / 0.05 over the image);
    # the optics alone agree to 1 level (Documentation/paraview.md, parallel section).
    h.check(d[ice].mean() < 2.0 and numpy.percentile(d[ice], 99) <= 32,
            "%d ranks: on the ice too (mean %.3f, p99 %.0f over %d pixels)" %
            (ranks, d[ice].mean(), numpy.percentile(d[ice], 99), ice.sum()))
    noice = h.difference(h.read_png(prefix + "-1-noice.png"), h.read_png("%s-%d-noice.png" % (prefix, ranks)))
    # ParaView's own pieces of the floor differ from its whole floor by up to 3 levels.
    h.check(noice.max() <= 4, "%d ranks: the scene without ice matches too (max %d)" %
            (ranks, noice.max()))
    for name, pieces in sorted(statistics(prefix, ranks).items()):
        cells, objects = sum(p[0] for p in pieces), sum(p[1] for p in pieces)
        whole_cells, whole_objects = single[name][0]
        h.check(cells == whole_cells and objects == whole_objects,
                "%d ranks, %s: every object whole on one rank (%d objects, %d cells; one rank: "
                "%d, %d)" % (ranks, name, objects, cells, whole_objects, whole_cells))
        h.check(sum(1 for p in pieces if p[0] > 0) >= 2,
                "%d ranks, %s: the objects are spread (cells per rank %s)" %
                (ranks, name, [p[0] for p in pieces]))
# Translucent geometry: ParaView composites the ranks in visibility order of its spatial partition
# and moves the ice to it (cutting objects at its planes). Measured mean 0.67, p99 23; with the ice
# kept out of that partition an ice sphere behind the floor's rank vanished (mean 1.42, p99 46).
translucent = sys.argv[2]
d = h.difference(h.read_png(translucent + "-1.png"), h.read_png(translucent + "-2.png"))
h.check(d.mean() < 1.0 and numpy.percentile(d, 99) <= 32,
        "with a translucent sphere 2 ranks render the 1-rank image (mean %.3f, p99 %.0f)" %
        (d.mean(), numpy.percentile(d, 99)))
h.finish()
