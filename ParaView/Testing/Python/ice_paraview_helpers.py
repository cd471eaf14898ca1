# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers of VTK Ice's ParaView tests: load the plugin, render views to arrays, compare."""
import os
import sys

import numpy
from paraview import servermanager
from paraview.simple import CreateTexture, CreateView, Hide, LoadPlugin, Render, SaveScreenshot
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

SIZE = [400, 300]
failures = []


def load_plugin():
    """Loads the plugin named by VTKICE_PARAVIEW_PLUGIN (set by ctest) into this process."""
    path = os.environ["VTKICE_PARAVIEW_PLUGIN"]
    LoadPlugin(path, remote=False, ns=globals())


def say(message):
    """Prints to the process's own stdout: pvpython's sys.stdout (6.1) holds what it is given
    until a normal exit, and finish() leaves with os._exit."""
    print(message, file=sys.__stdout__, flush=True)


def check(condition, message):
    say(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def finish():
    if failures:
        say("%d check(s) failed" % len(failures))
        # ParaView 5.11's pvpython crashes in sys.exit() while views exist (seen without the
        # plugin too): leave at once with the failure's status.
        os._exit(1)
    say("all checks passed")


def make_view(kind="IceView", gradient=True):
    """A view of SIZE; its background a grey gradient (light at the top), which the ice refracts
    and reflects (a single colour would leave clean ice the colour of the background), or with
    gradient=False a single colour."""
    view = CreateView(kind)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    if gradient:
        view.BackgroundColorMode = "Gradient"
        view.Background = [0.25, 0.25, 0.28]
        view.Background2 = [0.85, 0.85, 0.9]
    else:
        view.Background = [0.2, 0.25, 0.35]
    return view


def look_at(view, position=(0.4, 0.6, 4.0)):
    view.CameraPosition = list(position)
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]


def clean_ice(display):
    """Ice with only its optics: no interior, no bumps (pixel tests compare surfaces)."""
    display.NumberOfCracks = 0
    display.NumberOfAirPlanes = 0
    display.BumpStrength = 0


def invisible_ice(display):
    """Clean ice with eta=1 (refraction ratio 1) and no reflection: it shows what lies behind it
    as the view draws it."""
    clean_ice(display)
    display.IndexOfRefraction = 1.0
    display.FresnelPower = 1.0e6


def capture(view, path):
    """Renders `view`, saves it to `path` and returns the image as an (h, w, 3) int array."""
    Render(view)
    SaveScreenshot(path, view, ImageResolution=SIZE)
    return read_png(path)


def read_png(path):
    """The PNG image at `path` as an (h, w, 3) int array, top row first."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    return pixels[::-1, :, :3].astype(int)


def difference(a, b):
    """Per-pixel largest channel difference."""
    return numpy.abs(a - b).max(axis=2)


def surface_then_ice(view, source, display, prefix, setup=None):
    """Captures `display` as Surface, then as Ice (after `setup(display)`), then hidden; saves
    them as prefix-surface/-ice/-empty.png. Returns the ice image, the silhouette (where the
    surface differs from the empty view) and the per-pixel difference of ice from surface."""
    surface = capture(view, prefix + "-surface.png")
    display.Representation = "Ice"
    if setup:
        setup(display)
    ice = capture(view, prefix + "-ice.png")
    Hide(source, view)
    empty = capture(view, prefix + "-empty.png")
    return ice, difference(surface, empty) > 0, difference(ice, surface)


def grow(mask, pixels):
    """`mask` dilated by `pixels` (8-neighbourhood): the silhouette plus its anti-aliased rim."""
    grown = mask.copy()
    for _ in range(pixels):
        step = grown.copy()
        step[1:, :] |= grown[:-1, :]
        step[:-1, :] |= grown[1:, :]
        step[:, 1:] |= grown[:, :-1]
        step[:, :-1] |= grown[:, 1:]
        grown = step
    return grown


def shrink(mask, pixels):
    return ~grow(~mask, pixels)


def create_texture(path):
    """A texture proxy of the image file at `path`."""
    texture = CreateTexture(path)
    manager = servermanager.vtkSMProxyManager
    if (manager.GetVersionMajor(), manager.GetVersionMinor()) == (5, 13):
        # ParaView 5.13's CreateTexture leaves the texture without its image (its skybox then
        # reports "No scalar values found for texture input" and GL_INVALID_VALUE and draws
        # none); given its file name again, the texture reads it. 5.11 and 6.1 read it at once.
        texture.FileName = ""
        texture.FileName = path
    return texture


def panorama_pixels(width=512, height=256):
    """Float RGB in [0, 1], rows bottom first (VTK's order): red by longitude, green by latitude,
    a checker of blue."""
    u, v = numpy.meshgrid(numpy.arange(width) / width, numpy.arange(height) / height)
    red = 127 + 120 * numpy.sin(2 * numpy.pi * 3 * u)
    green = 255 * v
    blue = numpy.where(((numpy.arange(width)[None, :] // 32 + numpy.arange(height)[:, None] // 32)
                        % 2) == 1, 200, 60)
    return numpy.stack([red, green, blue], axis=-1) / 255.0


def write_environment(path):
    """An equirectangular PNG panorama with structure everywhere; returns its texture proxy."""
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    rgb = panorama_pixels()
    height, width, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(
        numpy_to_vtk((255 * rgb).astype(numpy.uint8).reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    return create_texture(path)


def write_hdr_environment(path, brightness=1.6):
    """The same panorama as a Radiance .hdr file (flat RGBE scanlines, values up to
    `brightness`); returns its texture proxy."""
    rgb = panorama_pixels()[::-1] * brightness  # Radiance's "-Y": the top row first
    height, width, _ = rgb.shape
    peak = rgb.max(axis=-1)
    exponent = numpy.where(peak > 1e-32, numpy.floor(numpy.log2(numpy.maximum(peak, 1e-32))) + 1, 0)
    mantissa = numpy.where(peak[..., None] > 1e-32, rgb / numpy.exp2(exponent)[..., None] * 256, 0)
    rgbe = numpy.concatenate([numpy.clip(mantissa, 0, 255), (exponent + 128)[..., None]], axis=-1)
    rgbe[peak <= 1e-32] = 0
    with open(path, "wb") as out:
        out.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
        out.write(rgbe.astype(numpy.uint8).tobytes())
    return create_texture(path)
