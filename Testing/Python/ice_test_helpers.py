# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers shared by the Python tests: read a render window back, compare image regions."""
import vtk
import vtkice


def grab(window):
    """Renders `window` and returns a copy of its RGB pixels."""
    window.Render()
    capture = vtk.vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.SetInputBufferTypeToRGB()
    capture.ReadFrontBufferOff()
    capture.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(capture.GetOutput())
    return image


def mean_difference(a, b, x0, x1, y0, y1):
    """Mean over the box of the largest channel difference between two images, in 0..255."""
    total = 0.0
    for y in range(y0, y1):
        for x in range(x0, x1):
            total += max(abs(a.GetScalarComponentAsDouble(x, y, 0, c) -
                             b.GetScalarComponentAsDouble(x, y, 0, c)) for c in range(3))
    return total / ((x1 - x0) * (y1 - y0))


def check(condition, message=None):
    """Fails the test with `message`, or the line of the check (unlike assert, also under
    python -O)."""
    if not condition:
        if message is None:
            import traceback

            message = traceback.extract_stack(limit=2)[0].line
        raise AssertionError(message)


def sky_renderer(face_size):
    """A renderer whose environment and skybox are vtkIceCubeMapSource's sky, `face_size` pixels a
    face; returns the renderer (it holds the texture)."""
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(face_size)
    texture = vtk.vtkTexture()
    sky.ConfigureTexture(texture)
    renderer = vtk.vtkRenderer()
    renderer.SetEnvironmentTexture(texture)
    skybox = vtk.vtkSkybox()
    skybox.SetTexture(texture)
    renderer.AddActor(skybox)
    return renderer


def add_ice(renderer, source, mapper=None):
    """Draws `source`'s output as ice in `renderer`; returns the mapper and the actor."""
    mapper = mapper or vtkice.vtkIceMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    ice = vtk.vtkActor()
    ice.SetMapper(mapper)
    renderer.AddActor(ice)
    return mapper, ice


def run_tests(namespace, *arguments):
    """Runs every function of `namespace` (a module's globals()) whose name starts with test_,
    in name order, each with `arguments`; prints ok or FAIL per test. Returns the exit status."""
    tests = [value for name, value in sorted(namespace.items()) if name.startswith("test_")]
    failed = 0
    for test in tests:
        try:
            test(*arguments)
            print("ok   " + test.__name__)
        except AssertionError as error:
            failed += 1
            print("FAIL %s: %s" % (test.__name__, error))
    print("%d passed, %d failed" % (len(tests) - failed, failed))
    return 1 if failed else 0
