# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI (paraview --script): the plugin, found through PV_PLUGIN_PATH, gives
the sphere an Ice representation with its Ice properties; the result goes to the file named by
VTKICE_GUI_RESULT, which the test reads."""
import os

from paraview.simple import GetActiveViewOrCreate, Render, SetActiveSource, Show, Sphere

sphere = Sphere(ThetaResolution=64, PhiResolution=64)
view = GetActiveViewOrCreate("RenderView")
display = Show(sphere, view)
available = display.GetProperty("Representation").Available
display.Representation = "Ice"
display.NumberOfCracks = 2
SetActiveSource(sphere)
Render(view)
with open(os.environ["VTKICE_GUI_RESULT"], "w") as result:
    result.write("representations: %s\n" % ", ".join(available))
    result.write("representation: %s\n" % display.Representation)
    result.write("ice properties: %s\n" % ("IndexOfRefraction" in display.ListProperties()))
