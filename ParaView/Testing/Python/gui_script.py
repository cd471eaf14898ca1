# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI (paraview --script): the plugin, found through PV_PLUGIN_PATH, gives
a sphere an Ice representation with its Ice properties, in an Ice View whose dynamic environment
shows a ground and a cone in the ice. The result goes to the file named by VTKICE_GUI_RESULT, and
the view with the ice and with the sphere hidden to ice.png and hidden.png beside it, which the
test compares (the ice must show)."""
import os

from paraview.simple import (AssignViewToLayout, Cone, CreateView, Delete, GetActiveView,
                             GetLayout, Hide, Plane, Render, SaveScreenshot, SetActiveSource,
                             SetActiveView, Show, Sphere)

result = os.environ["VTKICE_GUI_RESULT"]
# The Ice View in the place of the window's Render View.
layout = GetLayout()
Delete(GetActiveView())
view = CreateView("IceView")
AssignViewToLayout(view=view, layout=layout, hint=0)
SetActiveView(view)
view.UseColorPaletteForBackground = 0
view.BackgroundColorMode = "Gradient"
view.Background = [0.3, 0.3, 0.33]
view.Background2 = [0.75, 0.8, 0.88]
view.DynamicEnvironment = 1
view.OrientationAxesVisibility = 0

ground = Show(Plane(Origin=[-4, -0.55, -4], Point1=[4, -0.55, -4], Point2=[-4, -0.55, 4]), view)
ground.AmbientColor = ground.DiffuseColor = [0.55, 0.5, 0.45]
cone = Show(Cone(Center=[-0.8, 0.0, -1.2], Direction=[0, 1, 0], Radius=0.35, Height=1.1,
                 Resolution=48), view)
cone.AmbientColor = cone.DiffuseColor = [0.9, 0.45, 0.1]

sphere = Sphere(ThetaResolution=64, PhiResolution=64)
display = Show(sphere, view)
available = display.GetProperty("Representation").Available
display.Representation = "Ice"
# ice-render's natural look (the ice-cube preset) by the representation's properties.
display.FresnelModel = 1
display.MaxBounces = 8
display.Absorption = 1
display.AttenuationColor = [0.8, 0.92, 0.98]
display.AttenuationDistance = 1.2
display.NumberOfCracks = 0
display.NumberOfAirPlanes = 0
display.Milkiness = 0.4
display.MilkyCoreRadius = 0.5
display.BubbleDensity = 1.0
display.IceRoughness = 0.08
display.BumpStrength = 0.02
SetActiveSource(sphere)
Render(view)
# After the first render: the GUI frames the scene when a view first shows it.
camera = view.GetActiveCamera()
camera.SetPosition(1.6, 1.1, 5.6)
camera.SetFocalPoint(0.0, -0.1, 0.0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(30)
view.CameraPosition = [1.6, 1.1, 5.6]
view.CameraFocalPoint = [0.0, -0.1, 0.0]
view.CameraViewUp = [0, 1, 0]
Render(view)
folder = os.path.dirname(result)
SaveScreenshot(os.path.join(folder, "ice.png"), view)
Hide(sphere, view)
SaveScreenshot(os.path.join(folder, "hidden.png"), view)
Show(sphere, view)
Render(view)
with open(result, "w") as out:
    out.write("representations: %s\n" % ", ".join(available))
    out.write("representation: %s\n" % display.Representation)
    out.write("ice properties: %s\n" % ("IndexOfRefraction" in display.ListProperties()))
