# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Everything else keeps working around ice: a scene of ParaView's own representations (surface,
wireframe, translucent surface, volume, a selection), orientation axes, a scalar bar and a text
annotation looks the same in the Ice View as in ParaView's Render View, pixel for pixel; with an
ice object added, everything outside the ice's silhouette still does. Interaction (LOD) keeps
the ice ice, and two views side by side both render."""
import os
import sys

import numpy
from paraview.simple import (ColorBy, Cone, Delete, GetColorTransferFunction,
                             GetOpacityTransferFunction,
                             Hide, SelectIDs, SetActiveSource, Show, Sphere, Text, Wavelet)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ice_paraview_helpers as h  # noqa: E402

h.load_plugin()
out = os.environ.get("VTKICE_TEST_OUTPUT", ".")


def build_scene(view):
    """ParaView's own representations and annotations; returns the ice sphere's display."""
    view.OrientationAxesVisibility = 1
    cone = Cone(Center=[-2.2, 0, 0], Resolution=24)
    wire = Show(cone, view)
    wire.Representation = "Wireframe"
    glass = Show(Sphere(Center=[2.2, 0, 0], Radius=0.8), view)
    glass.Opacity = 0.4
    wavelet = Wavelet(WholeExtent=[-6, 6, -6, 6, -6, 6])
    volume = Show(wavelet, view)
    volume.Representation = "Volume"
    volume.Scale = [0.08, 0.08, 0.08]
    # ParaView 5.13 renamed the display's Position to Translation (the old name raises there).
    if "Translation" in volume.ListProperties():
        volume.Translation = [0.0, -2.0, 0.0]
    else:
        volume.Position = [0.0, -2.0, 0.0]
    ColorBy(volume, ("POINTS", "RTData"))
    lut = GetColorTransferFunction("RTData")
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(40.0, 280.0)
    GetOpacityTransferFunction("RTData").RescaleTransferFunction(40.0, 280.0)
    volume.SetScalarBarVisibility(view, True)
    text = Text(Text="VTK Ice")
    Show(text, view)
    # A selection on the cone: ParaView draws its highlight.
    SetActiveSource(cone)
    SelectIDs(IDs=[0, 0, 0, 1, 0, 2], FieldType="CELL", Source=cone)
    ice = Show(Sphere(Radius=1.0, ThetaResolution=64, PhiResolution=64), view)
    ice.Representation = "Ice"
    h.clean_ice(ice)
    return ice


def scene_view(kind):
    view = h.make_view(kind)
    ice = build_scene(view)
    h.look_at(view, (0.5, 1.5, 11.0))
    return view, ice


images = {}
for kind in ("RenderView", "IceView"):
    view, ice = scene_view(kind)
    images[kind + " with ice"] = h.capture(view, os.path.join(out, "scene-%s-ice.png" % kind))
    ice.Visibility = 0
    images[kind] = h.capture(view, os.path.join(out, "scene-%s.png" % kind))
    ice.Visibility = 1
    # The sphere as a plain surface: its silhouette (ice can match what is behind it in places,
    # as it refracts the view's background).
    ice.Representation = "Surface"
    images[kind + " with surface"] = h.capture(view, os.path.join(out, "scene-%s-surface.png" %
                                                                   kind))
    ice.Representation = "Ice"
    if kind == "IceView":
        ice_view = view

without = h.difference(images["RenderView"], images["IceView"])
h.check(without.max() == 0,
        "without ice the Ice View renders ParaView's scene exactly as the Render View "
        "(largest difference %d)" % without.max())
scene = h.difference(images["IceView"], h.capture(h.make_view("IceView"),
                                                  os.path.join(out, "scene-empty.png")))
h.check((scene > 0).sum() > 8000, "the scene covers %d pixels" % (scene > 0).sum())
silhouette = h.grow(h.difference(images["IceView with surface"], images["IceView"]) > 0, 1)
h.check(5000 < silhouette.sum() < 60000, "the ice covers %d pixels" % silhouette.sum())
with_ice = h.difference(images["IceView with ice"], images["RenderView with ice"])
h.check(with_ice[~silhouette].max() == 0,
        "with ice, everything outside its silhouette is as in the Render View")
h.check((with_ice[silhouette] > 8).mean() > 0.3,
        "and the ice itself is two-sided in the Ice View (%.0f %% of it differs from one-sided)"
        % (100 * (with_ice[silhouette] > 8).mean()))

# Interaction: ParaView draws the LOD mapper, which is ice too.
ice_view.LODThreshold = 0.0
ice_view.InteractiveRender()
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
grab = vtkWindowToImageFilter()
grab.SetInput(ice_view.GetRenderWindow())
grab.ReadFrontBufferOff()
grab.Update()
width, height, _ = grab.GetOutput().GetDimensions()
interactive = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(
    height, width, -1)[::-1, :, :3].astype(int)
if interactive.shape == images["IceView with ice"].shape:
    # Ice, not the plain surface: the two differ all over the silhouette.
    lod = h.difference(interactive, images["IceView with surface"])
    h.check((lod[silhouette] > 8).mean() > 0.8,
            "during interaction (LOD) the ice is still ice (%.0f %% of its pixels differ from "
            "Surface)" % (100 * (lod[silhouette] > 8).mean()))
else:
    h.check(False, "the interactive render has the view's size (%s)" % (interactive.shape,))

# Two Ice Views at once.
second, _ = scene_view("IceView")
h.check(h.difference(h.capture(second, os.path.join(out, "scene-second.png")),
                     images["IceView with ice"]).max() <= 2,
        "a second Ice View renders the same picture")
h.finish()
