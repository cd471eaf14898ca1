# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""builtin.png remote.png local.png: the client/server renderings equal the one-process one.

Dynamic-environment ice through a pvserver (Python/client_server_scene.py): rendered on the
server (remote rendering) and on the client (client-side rendering), the picture must be what
one process renders: no pixel over 16/255 off, mean under 0.5/255.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

builtin, remote, local = (h.read_png(path) for path in sys.argv[1:4])
for name, image in (("remote rendering", remote), ("client-side rendering", local)):
    d = h.difference(builtin, image)
    h.check(image.shape == builtin.shape and (d > 16).sum() == 0 and d.mean() < 0.5,
            "%s renders the one-process image (%d pixels over 16/255, mean %.3f)" %
            (name, (d > 16).sum(), d.mean()))
h.finish()
