# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI (paraview --script): the plugin, found through PV_PLUGIN_PATH, gives
a rounded block an Ice representation with its Ice properties, in an Ice View whose dynamic
environment shows a ground and a cone in the ice, in the forest panorama named by
VTKICE_GUI_PANORAMA as the view's skybox (a gradient where it is empty). The result goes to the
file named by VTKICE_GUI_RESULT, and the view with the ice and with the block hidden to ice.png
and hidden.png beside it, which the test compares (the ice must show)."""
import os

from paraview.simple import (AssignViewToLayout, Cone, CreateView, Delete, GetActiveView,
                             GetLayout, Hide, Plane, Render, SaveScreenshot, SetActiveSource,
                             SetActiveView, Show, Superquadric)

import ice_paraview_helpers as h

result = os.environ["VTKICE_GUI_RESULT"]
panorama = os.environ.get("VTKICE_GUI_PANORAMA", "")
# The Ice View in the place of the window's Render View.
layout = GetLayout()
Delete(GetActiveView())
view = CreateView("IceView")
AssignViewToLayout(view=view, layout=layout, hint=0)
SetActiveView(view)
view.UseColorPaletteForBackground = 0
if panorama:
    view.BackgroundColorMode = "Skybox"
    view.BackgroundTexture = h.create_texture(panorama)
else:
    view.BackgroundColorMode = "Gradient"
    view.Background = [0.3, 0.3, 0.33]
    view.Background2 = [0.75, 0.8, 0.88]
view.DynamicEnvironment = 1
view.OrientationAxesVisibility = 0


def ground_texture(path, half, texels=2048, seed=7):
    """Mottled earth of the panorama's colour, with the block's soft contact shadow at the middle,
    as a PNG for a square ground of side 2 * half (rows along +z); returns its texture proxy."""
    import numpy
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    rng = numpy.random.default_rng(seed)
    mottle = numpy.zeros((texels, texels))
    for cells, weight in ((16, 1.0), (128, 0.6), (1024, 0.35)):  # value noise, bilinear, tiling
        coarse = rng.random((cells + 1, cells + 1))
        x = numpy.linspace(0, cells, texels, endpoint=False)
        i = x.astype(int)
        f = x - i
        rows = coarse[i] * (1 - f)[:, None] + coarse[i + 1] * f[:, None]
        mottle += weight * (rows[:, i] * (1 - f) + rows[:, i + 1] * f)
    mottle = 0.7 + 0.6 * (mottle - mottle.min()) / numpy.ptp(mottle)
    # The contact shadow: darkest along the foot's outline (the block is 0.9 across at the
    # middle), fading over a few tenths, lighter under the clear foot.
    z, x = numpy.meshgrid(numpy.linspace(-half, half, texels), numpy.linspace(-half, half, texels),
                          indexing="ij")
    outside = numpy.hypot(numpy.maximum(numpy.abs(x) - 0.4, 0),
                          numpy.maximum(numpy.abs(z) - 0.4, 0))
    inside = numpy.minimum(numpy.maximum(numpy.abs(x), numpy.abs(z)), 0.4)
    shadow = numpy.where(outside > 0, 0.55 * numpy.exp(-outside / 0.12),
                         0.55 - 0.35 * (0.4 - inside) / 0.4)
    rgb = (mottle * (1 - shadow))[..., None] * numpy.array([0.3, 0.27, 0.23])
    image = vtkImageData()
    image.SetDimensions(texels, texels, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(
        (numpy.clip(rgb, 0, 1) * 255).astype(numpy.uint8).reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    return h.create_texture(path)


# A ground of the panorama's own dark earth, and a cone to see in the ice.
half = 12.0
ground = Show(Plane(Origin=[-half, -0.55, -half], Point1=[half, -0.55, -half],
                    Point2=[-half, -0.55, half]), view)
ground.Texture = ground_texture(os.path.join(os.path.dirname(result), "ground.png"), half)
cone = Show(Cone(Center=[-0.8, 0.0, -1.2], Direction=[0, 1, 0], Radius=0.35, Height=1.1,
                 Resolution=48), view)
cone.AmbientColor = cone.DiffuseColor = [0.9, 0.45, 0.1]

# An ice cube: flat faces, melted round edges, standing on the ground.
block = Superquadric(Center=[0.0, -0.1, 0.0], Scale=[0.9, 0.9, 0.9], ThetaRoundness=0.25,
                      PhiRoundness=0.25, ThetaResolution=64, PhiResolution=64,
                      Toroidal=0)
display = Show(block, view)
available = display.GetProperty("Representation").Available
display.Representation = "Ice"
# ice-render's natural look (the ice-cube preset) by the representation's properties.
display.FresnelModel = 1
display.MaxBounces = 8
display.WetBase = 1
display.Absorption = 1
display.AttenuationColor = [0.8, 0.92, 0.98]
display.AttenuationDistance = 0.6
display.NumberOfCracks = 0
display.NumberOfAirPlanes = 0
display.Milkiness = 0.4
display.MilkyCoreRadius = 0.5
display.BubbleDensity = 0.6
display.IceRoughness = 0.08
display.BumpStrength = 0.02
SetActiveSource(block)
Render(view)
# After the first render: the GUI frames the scene when a view first shows it.
camera = view.GetActiveCamera()
camera.SetPosition(1.5, 0.6, 4.8)
camera.SetFocalPoint(0.0, -0.15, 0.0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(30)
view.CameraPosition = [1.5, 0.6, 4.8]
view.CameraFocalPoint = [0.0, -0.15, 0.0]
view.CameraViewUp = [0, 1, 0]
Render(view)
folder = os.path.dirname(result)
SaveScreenshot(os.path.join(folder, "ice.png"), view)
Hide(block, view)
SaveScreenshot(os.path.join(folder, "hidden.png"), view)
Show(block, view)
Render(view)
with open(result, "w") as out:
    out.write("representations: %s\n" % ", ".join(available))
    out.write("representation: %s\n" % display.Representation)
    out.write("ice properties: %s\n" % ("IndexOfRefraction" in display.ListProperties()))
