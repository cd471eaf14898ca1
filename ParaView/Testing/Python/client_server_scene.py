# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Dynamic-environment ice in one process or through a pvserver.

    pvpython client_server_scene.py builtin image.png
    pvpython client_server_scene.py PORT remote.png local.png

With a port the script connects to the pvserver on 127.0.0.1:PORT, loads the plugin on both
sides and renders the scene twice: on the server (remote rendering, render threshold 0) and on
the client (client-side rendering). The scene: an ice sphere with a dynamic cube map beside a red
ball, on a single-colour background that the cube-map faces show around the ball.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import (Connect, Disconnect, GetSettingsProxy, LoadPlugin, Render, SaveScreenshot,
                             Show, Sphere)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

if sys.argv[1] != "builtin":
    Connect("127.0.0.1", int(sys.argv[1]))
    # The plugin is needed on both sides: the server renders, the client owns the proxies.
    LoadPlugin(os.environ["VTKICE_PARAVIEW_PLUGIN"], remote=True, ns=globals())
LoadPlugin(os.environ["VTKICE_PARAVIEW_PLUGIN"], remote=False, ns=globals())

view = h.make_view(gradient=False)
view.DynamicEnvironment = 1
view.CubeMapFaceSize = 256
ice = Sphere(ThetaResolution=96, PhiResolution=96, Radius=1)
display = Show(ice, view)
display.Representation = "Ice"
h.clean_ice(display)
ball = Sphere(Center=[0, 0, -3.0], Radius=1.2, ThetaResolution=32, PhiResolution=32)
ball_display = Show(ball, view)
ball_display.AmbientColor = ball_display.DiffuseColor = [1.0, 0.0, 0.0]
h.look_at(view, (0.4, 0.6, 4.0))

settings = GetSettingsProxy("RenderViewSettings")
outputs = sys.argv[2:]
# Render threshold 0 (MB): the server renders; a large one: the client renders.
for path, threshold in zip(outputs, (0, 1.0e6)):
    if sys.argv[1] != "builtin":
        settings.RemoteRenderThreshold = threshold
    Render(view)
    SaveScreenshot(path, view, ImageResolution=h.SIZE)
    h.say("wrote %s (render threshold %g MB)" % (path, threshold))
if sys.argv[1] != "builtin":
    # A clean goodbye (the server reports a client that vanishes as an error); no views are left.
    Disconnect()
else:
    # 5.11's pvpython can crash leaving with views (ice_paraview_helpers.finish).
    os._exit(0)
