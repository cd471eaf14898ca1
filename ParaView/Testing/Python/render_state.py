# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Loads a ParaView state file that uses the Ice plugin and saves its view: state.pvsm image.png"""
import os
import sys

from paraview.simple import GetActiveView, LoadPlugin, LoadState, Render, SaveScreenshot

LoadPlugin(os.environ["VTKICE_PARAVIEW_PLUGIN"], remote=False, ns=globals())
LoadState(sys.argv[1])
view = GetActiveView()
assert view.GetXMLName() == "IceView", "the state's view is %s" % view.GetXMLName()
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[800, 600])
