# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""VTK Ice in ParaView: an iso-surface of ParaView's Wavelet source drawn as ice in the Ice View,
beside ordinary representations, refracting a dynamic cube map of the scene.

    pvpython Examples/ParaView/ice_wavelet.py [image.png] [state.pvsm] [coloured.png]

coloured.png: the same view with the ice coloured by an array, its normals' y component (RTData is
the iso-value all over it); the state keeps the ice uncoloured.

The plugin is found through PV_PLUGIN_PATH (for a build by ./ice.sh paraview:
build-paraview/lib/paraview-5.11/plugins/IcePlugin) or loaded from VTKICE_PARAVIEW_PLUGIN, its
path (Documentation/paraview.md).
"""
import os
import sys

from paraview.simple import (ColorBy, Contour, CreateView, GetColorTransferFunction,
                             LoadDistributedPlugin, LoadPlugin, Render, SaveScreenshot,
                             SaveState, Show, Slice, Wavelet)

if "VTKICE_PARAVIEW_PLUGIN" in os.environ:
    LoadPlugin(os.environ["VTKICE_PARAVIEW_PLUGIN"], remote=False, ns=globals())
else:
    LoadDistributedPlugin("IcePlugin", remote=False, ns=globals())

view = CreateView("IceView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.BackgroundColorMode = "Gradient"
view.Background = [0.55, 0.65, 0.8]
view.Background2 = [0.1, 0.15, 0.3]
view.DynamicEnvironment = 1

wavelet = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
# The ice: an iso-surface of the wavelet's RTData, coloured by nothing (ice colour), in a look
# near ice-render's ice-cube: Fresnel's equations, faintly blue where thick (the wavelet is 40
# units across), small bubbles instead of air planes, two cracks, a barely frosted surface.
iso = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[190.0])
ice = Show(iso, view)
ice.Representation = "Ice"
ice.FresnelModel = "Dielectric"
ice.Absorption = 1
ice.AttenuationColor = [0.8, 0.92, 0.98]
ice.AttenuationDistance = 24.0
ice.NumberOfCracks = 2
ice.NumberOfAirPlanes = 0
ice.BubbleDensity = 0.5
ice.Milkiness = 0.4
ice.IceRoughness = 0.08
ColorBy(ice, None)
# Ordinary data around it: a slice below, coloured by RTData, which the ice refracts.
floor = Slice(Input=wavelet)
floor.SliceType.Origin = [0, -12, 0]
floor.SliceType.Normal = [0, 1, 0]
floor_display = Show(floor, view)
ColorBy(floor_display, ("POINTS", "RTData"))
# ParaView's default map, in every version: a vivid one (Inferno) seen through the ice made it
# read as glowing lava.
GetColorTransferFunction("RTData").ApplyPreset("Cool to Warm", True)

view.CameraPosition = [38, 30, 62]
view.CameraFocalPoint = [0, -3, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 30
Render(view)
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[800, 600])
if len(sys.argv) > 2:
    SaveState(sys.argv[2])
if len(sys.argv) > 3:
    ColorBy(ice, ("POINTS", "Normals", "Y"))
    Render(view)
    SaveScreenshot(sys.argv[3], view, ImageResolution=[800, 600])
