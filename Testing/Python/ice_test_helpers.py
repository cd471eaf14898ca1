"""Helpers shared by the Python tests: read a render window back, compare image regions."""
import vtk


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


def check(condition, message):
    """Fails the test with `message` (unlike assert, also under python -O)."""
    if not condition:
        raise AssertionError(message)
