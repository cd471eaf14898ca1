# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Glistening ice and snow from Python: vtkIceMapper's Glistening options with VTK's clamping,
vtkIceGlisteningTexture's random unit vectors, and a glistening plane that renders: glints with
Glistening on (none off), white snow where the ice is dark. Run with Debian's /usr/bin/python3.
"""
import math
import sys

import vtk
import vtkice

from ice_test_helpers import check


def grab(window):
    capture = vtk.vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.SetInputBufferTypeToRGB()
    capture.ReadFrontBufferOff()
    capture.Update()
    return capture.GetOutput()


def pixels(image):
    """Rows of (r, g, b) tuples, bottom row first."""
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return [[scalars.GetTuple3(y * w + x) for x in range(w)] for y in range(h)]


def check_properties():
    mapper = vtkice.vtkIceMapper()
    check(not mapper.GetIceProperty().GetGlistening(), "Glistening is off by default")
    check(mapper.GetIceProperty().GetSnowAmount() == 0.0)
    check(abs(mapper.GetIceProperty().GetGlisteningScale() - 0.03) < 1e-12)
    check(mapper.GetIceProperty().GetGlisteningIntensity() == 1.0)
    check(mapper.GetIceProperty().GetGlisteningAlignmentGain() == 2.0)
    mapper.GetIceProperty().SetGlistening(True)
    check(mapper.GetIceProperty().GetGlistening())
    mapper.GetIceProperty().SetSnowAmount(2.0)
    check(mapper.GetIceProperty().GetSnowAmount() == 1.0, "SnowAmount is clamped to [0, 1]")
    mapper.GetIceProperty().SetSnowAmount(-1.0)
    check(mapper.GetIceProperty().GetSnowAmount() == 0.0, "SnowAmount is clamped to [0, 1]")
    mapper.GetIceProperty().SetGlisteningAlignmentGain(0.5)
    check(mapper.GetIceProperty().GetGlisteningAlignmentGain() == 1.0, "the gain is at least 1")


def check_texture():
    texture = vtkice.vtkIceGlisteningTexture()
    texture.SetSize(300)
    check(texture.GetSize() == 256, "Size is rounded down to a power of two")
    image = texture.GetImage()
    check(image.GetDimensions() == (256, 256, 1))
    scalars = image.GetPointData().GetScalars()
    check(scalars.GetNumberOfComponents() == 4)
    n = scalars.GetNumberOfTuples()
    mean = [0.0, 0.0, 0.0]
    worst = 0.0
    for t in range(n):
        texel = scalars.GetTuple4(t)
        v = [2.0 * c / 255.0 - 1.0 for c in texel[:3]]
        worst = max(worst, abs(math.sqrt(sum(c * c for c in v)) - 1.0))
        for c in range(3):
            mean[c] += v[c] / n
    print("texture: largest |length - 1| %.4f, mean vector (%.4f, %.4f, %.4f)"
          % (worst, mean[0], mean[1], mean[2]))
    check(worst < 0.015, "texels hold unit vectors (8-bit)")
    check(max(abs(c) for c in mean) < 0.01, "directions are uniform over the sphere")
    again = vtkice.vtkIceGlisteningTexture()
    again.SetSize(256)
    other = vtkice.vtkIceGlisteningTexture()
    other.SetSize(256)
    other.SetSeed(2)
    same = again.GetImage().GetPointData().GetScalars()
    different = other.GetImage().GetPointData().GetScalars()
    check(all(same.GetTuple4(t) == scalars.GetTuple4(t) for t in range(0, n, 97)))
    check(any(different.GetTuple4(t) != scalars.GetTuple4(t) for t in range(0, n, 97)))


def check_rendering():
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(64)
    environment = vtk.vtkTexture()
    sky.ConfigureTexture(environment)
    renderer = vtk.vtkRenderer()
    renderer.SetEnvironmentTexture(environment)
    plane = vtk.vtkPlaneSource()
    plane.SetOrigin(-50.0, 0.0, 50.0)
    plane.SetPoint1(50.0, 0.0, 50.0)
    plane.SetPoint2(-50.0, 0.0, -50.0)
    plane.SetResolution(16, 16)
    mapper = vtkice.vtkIceMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    mapper.GetIceProperty().SetIceColor(0.2, 0.25, 0.3)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    sun = vtk.vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPosition(0.5, 0.6, -0.6)
    sun.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(sun)
    window = vtk.vtkRenderWindow()
    window.SetSize(160, 120)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 1.0, 0.0)
    camera.SetFocalPoint(0.0, 0.4, -1.0)
    camera.SetViewAngle(40.0)
    camera.SetClippingRange(0.05, 200.0)

    def render():
        window.Render()
        return pixels(grab(window))

    def glints(rows):
        """Pixels at least 80/255 brighter (mean of r, g, b) than all four neighbours' mean."""
        lum = [[sum(p) / 3.0 for p in row] for row in rows]
        count = 0
        for y in range(1, len(lum) - 1):
            for x in range(1, len(lum[0]) - 1):
                around = (lum[y - 1][x] + lum[y + 1][x] + lum[y][x - 1] + lum[y][x + 1]) / 4.0
                count += 1 if lum[y][x] - around >= 80.0 else 0
        return count

    def mean_brightness(rows):
        values = [sum(p) / 3.0 for row in rows for p in row]
        return sum(values) / len(values)

    plain = render()
    mapper.GetIceProperty().SetGlistening(True)
    ice = render()
    mapper.GetIceProperty().SetSnowAmount(1.0)
    snow = render()
    print("glints: %d with Glistening off, %d on; mean brightness %.1f dark ice, %.1f snow"
          % (glints(plain), glints(ice), mean_brightness(ice), mean_brightness(snow)))
    check(glints(plain) == 0, "no glints with Glistening off")
    check(glints(ice) > 10, "Glistening on: glints")
    check(mean_brightness(snow) > mean_brightness(ice) + 40.0, "snow is white, the ice dark")


def main():
    check_properties()
    check_texture()
    check_rendering()
    print("3 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
