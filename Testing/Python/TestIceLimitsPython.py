# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice from Python at and beyond its limits.

- Every clamped vtkIceMapper parameter: infinities and values past the range are clamped to the
  range its Get...MinValue/MaxValue declare, NaN is refused with a warning naming it.
- vtkIceMapper.CheckInput names what is broken in polydata that would crash VTK's filters, and a
  mapper given such data reports one error and draws nothing, while the rest of the scene renders.
- Every source at its largest allowed setting finishes in time proportional to its output: at
  most 4x the processor time per output element of a small setting (plus 2 s). A quadratic
  algorithm fails this (vtkIceTeapotSource's point merge did). Processor time of this process,
  not the clock: other processes on the machine (a parallel ctest, a build) do not count.
Run with Debian's /usr/bin/python3.
"""
import math
import sys
import time

import vtk
import vtkice

from ice_test_helpers import grab, mean_difference

failures = []
passed = [0]


def check(name, ok, detail=""):
    if ok:
        passed[0] += 1
        print("ok   " + name)
    else:
        failures.append(name)
        print("FAIL %s: %s" % (name, detail))


class Messages:
    """VTK's errors and warnings of a block, captured instead of printed."""

    def __enter__(self):
        self.window = vtk.vtkStringOutputWindow()
        self.previous = vtk.vtkOutputWindow.GetInstance()
        vtk.vtkOutputWindow.SetInstance(self.window)
        vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_OFF)
        return self

    def __exit__(self, *args):
        vtk.vtkOutputWindow.SetInstance(self.previous)
        vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_INFO)
        self.text = self.window.GetOutput()


CLAMPED = ["IndexOfRefraction", "RefractionRatio", "AttenuationDistance", "FresnelPower", "BackNormalWeight", "CrackIntensity", "Milkiness",
           "MilkyCoreRadius", "BubbleDensity",
           "BumpStrength", "BumpScale", "GlisteningScale", "GlisteningIntensity",
           "GlisteningAlignmentGain", "SnowAmount"]
INTEGERS = {"NumberOfCracks": (0, 1000), "NumberOfAirPlanes": (0, 1000)}


def parameters():
    mapper = vtkice.vtkIceMapper()
    look = mapper.GetIceProperty()  # the look's parameters; a change of it modifies the mapper
    for name in CLAMPED:
        set_, get = getattr(look, "Set" + name), getattr(look, "Get" + name)
        low, high = getattr(look, "Get%sMinValue" % name)(), getattr(look, "Get%sMaxValue" % name)()
        results = []
        for value, expected in ((-math.inf, low), (math.inf, high), (low - 1.0, low),
                                (high * 2.0 + 1.0, high), (low, low), (high, high)):
            set_(value)
            results.append(get() == expected)
        set_(0.5 * (low + min(high, low + 1.0)))
        before, mtime = get(), mapper.GetMTime()
        with Messages() as messages:
            set_(math.nan)
        refused = get() == before and mapper.GetMTime() == mtime and name in messages.text
        check("%s clamps to [%g, %g] and refuses NaN" % (name, low, high),
              all(results) and refused, "results %s, NaN refused %s" % (results, refused))
    for name, (low, high) in INTEGERS.items():
        set_, get = getattr(look, "Set" + name), getattr(look, "Get" + name)
        set_(-2 ** 31)
        below = get()
        set_(2 ** 31 - 1)
        check("%s clamps to [%d, %d]" % (name, low, high), (below, get()) == (low, high),
              "got %s, %s" % (below, get()))
    for name in ("IceColor", "AttenuationColor"):
        set_, get = getattr(look, "Set" + name), getattr(look, "Get" + name)
        with Messages() as messages:
            set_(0.5, math.nan, 0.5)
        color = get()
        set_(-1.0, 2.0, math.inf)
        check("%s clamps to [0, 1] and refuses NaN" % name,
              get() == (0.0, 1.0, 1.0) and not any(map(math.isnan, color)) and
              "NaN" in messages.text, "%s %s" % (color, get()))


def polydata(points, polys, arrays=()):
    data = vtk.vtkPolyData()
    p = vtk.vtkPoints()
    for point in points:
        p.InsertNextPoint(point)
    data.SetPoints(p)
    cells = vtk.vtkCellArray()
    for poly in polys:
        cells.InsertNextCell(len(poly), poly)
    data.SetPolys(cells)
    for name, values in arrays:
        array = vtk.vtkFloatArray()
        array.SetName(name)
        for v in values:
            array.InsertNextValue(v)
        data.GetPointData().AddArray(array)
    return data


TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def broken_input():
    cases = [
        ("point id out of range", polydata(TETRA, FACES[:3] + [(1, 2, 40)]), "point 40, which does not exist"),
        ("negative point id", polydata(TETRA, FACES[:3] + [(1, 2, -1)]), "point -1, which does not exist"),
        ("polygon of two points", polydata(TETRA, FACES[:3] + [(1, 2)]), "polygon 3 has 2 points"),
        ("all points coincide", polydata([(2, 2, 2)] * 4, FACES), "no extent"),
        ("short point array", polydata(TETRA, FACES, [("temperature", [1.0, 2.0])]),
         "'temperature' has 2 values for 4 points"),
        ("NaN coordinate", polydata([(0, 0, 0), (1, math.nan, 0), (0, 1, 0), (0, 0, 1)], FACES), "NaN"),
        ("no polygons", polydata(TETRA, []), "no polygons"),
    ]
    good = polydata(TETRA, FACES)
    check("CheckInput accepts a tetrahedron", vtkice.vtkIceMapper.CheckInput(good) == "",
          vtkice.vtkIceMapper.CheckInput(good))

    # A cone beside the broken ice: the cone renders as it does alone, the ice reports once.
    renderer = vtk.vtkRenderer()
    cone = vtk.vtkConeSource()
    coneMapper = vtk.vtkPolyDataMapper()
    coneMapper.SetInputConnection(cone.GetOutputPort())
    coneActor = vtk.vtkActor()
    coneActor.SetMapper(coneMapper)
    coneActor.SetPosition(-1.5, 0.0, 0.0)
    renderer.AddActor(coneActor)
    renderer.SetPass(vtkice.vtkIcePass())
    window = vtk.vtkRenderWindow()
    window.SetSize(96, 64)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    renderer.GetActiveCamera().SetPosition(-0.5, 0.3, 6.0)
    renderer.GetActiveCamera().SetFocalPoint(-0.5, 0.3, 0.0)
    renderer.ResetCameraClippingRange()
    alone = grab(window)
    for name, data, expected in cases:
        message = vtkice.vtkIceMapper.CheckInput(data)
        mapper = vtkice.vtkIceMapper()
        mapper.SetInputData(data)
        ice = vtk.vtkActor()
        ice.SetMapper(mapper)
        renderer.AddActor(ice)
        with Messages() as messages:
            image = grab(window)
            grab(window)
        renderer.RemoveActor(ice)
        errors = messages.text.count("ERROR")
        difference = mean_difference(alone, image, 0, 96, 0, 64)
        check("broken input, %s: CheckInput says why, one error, the scene unchanged" % name,
              expected in message and errors == 1 and expected in messages.text and difference == 0.0,
              "message %r, %d errors, scene differs by %.3f" % (message, errors, difference))


def timed(make, small, large):
    """Processor seconds (all of this process's threads) and output size of make(small) and
    make(large)."""
    results = []
    for setting in (small, large):
        source = make(setting)
        start = time.process_time()
        source.Update()
        seconds = time.process_time() - start
        output = source.GetOutputDataObject(0)
        size = output.GetNumberOfCells() if output.IsA("vtkPolyData") else output.GetNumberOfPoints()
        results.append((seconds, size))
    return results


def configured(cls, **settings):
    def make(value):
        source = cls()
        for name, v in settings.items():
            getattr(source, "Set" + name)(value if v is None else v)
        return source
    return make


def sources():
    # (name, factory, small setting, setting beyond the largest allowed, largest allowed).
    cases = [
        ("vtkIceTeapotSource Resolution", configured(vtkice.vtkIceTeapotSource, Resolution=None), 32, 10 ** 6, 256),
        ("vtkIceBlockSource Resolution", configured(vtkice.vtkIceBlockSource, Resolution=None), 32, 10 ** 6, 512),
        ("vtkIceCrackSource Rings and Sectors", configured(vtkice.vtkIceCrackSource, Rings=None, Sectors=None),
         16, 10 ** 6, None),
        ("vtkIceAirTextureSource Size", configured(vtkice.vtkIceAirTextureSource, Size=None), 512, 10 ** 6, 8192),
        ("vtkIceCubeMapSource FaceSize", configured(vtkice.vtkIceCubeMapSource, FaceSize=None), 256, 10 ** 6, 8192),
    ]
    for name, make, small, beyond, largest in cases:
        source = make(beyond)
        if largest is not None:
            clamped = getattr(source, "Get" + name.split()[-1])()
            check("%s clamps %d to %d" % (name, beyond, largest), clamped == largest, str(clamped))
        (t_small, n_small), (t_large, n_large) = timed(make, small, beyond)
        bound = 4.0 * t_small * n_large / n_small + 2.0
        check("%s at its largest: %d outputs in %.1f s of processor time (bound %.1f s, %d in %.2f s at %d)" %
              (name, n_large, t_large, bound, n_small, t_small, small), t_large <= bound)
    texture = vtkice.vtkIceGlisteningTexture()
    texture.SetSize(10 ** 6)
    start = time.process_time()
    image = texture.GetImage()
    seconds = time.process_time() - start
    check("vtkIceGlisteningTexture Size clamps to 1024, %.2f s" % seconds,
          texture.GetSize() == 1024 and image.GetNumberOfPoints() == 1024 * 1024 and seconds < 10)


def main():
    parameters()
    broken_input()
    sources()
    print("%d passed, %d failed" % (passed[0], len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
