# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The path-traced comparison's scenes, shared by make_references.py (Mitsuba 3) and
TestIcePathTracedPython.py (VTK Ice): the same meshes, cameras, materials and environment.

The environment is vtkIceCubeMapSource's DirectionTest pattern, an analytic function of the
direction: VTK Ice samples it into a cube map, Mitsuba into an equirectangular panorama."""
import math

import numpy

SIZE = 256  # image width and height in pixels
BLOCK = 4  # the comparison averages BLOCK x BLOCK pixels first (the references' noise)
VIEW_ANGLE = 30.0  # vertical field of view in degrees
IOR = 1.31


def environment(directions):
    """DirectionTest's colour (vtkIceCubeMapSource::Evaluate) of unit directions [..., 3]."""
    offsets = numpy.arange(3, dtype=float)
    return 0.5 + 0.45 * numpy.sin(4.0 * directions + offsets)


# name: (mesh, camera position looking at the origin, material). Materials are vtkIceProperty
# settings: attenuation (colour, distance), roughness.
SCENES = {
    "clear-sphere": ("sphere", (0.0, 0.6, 4.2), {}),
    "absorbing-sphere": ("sphere", (0.0, 0.6, 4.2),
                         {"attenuation": ((0.5, 0.8, 0.95), 1.0)}),
    "rough-sphere": ("sphere", (0.0, 0.6, 4.2), {"roughness": 0.3}),
    "cube-corner": ("cube", (2.6, 2.2, 2.9), {}),
    "torus": ("torus", (0.0, 2.6, 3.6), {}),
}
# The largest mean difference each scene may have (in /255).
GOALS = {"clear-sphere": 1.5, "absorbing-sphere": 2.0, "rough-sphere": 3.0, "cube-corner": 4.0,
         "torus": 3.0}


def mesh(name):
    """The scene's triangles with point normals, a vtkPolyData (vtk imported here only)."""
    import vtk

    if name == "sphere":
        source = vtk.vtkSphereSource()
        source.SetRadius(1.0)
        source.SetThetaResolution(128)
        source.SetPhiResolution(64)
        output_port = source.GetOutputPort()
    elif name == "cube":
        # Flat faces: each face its own four points and normal.
        source = vtk.vtkCubeSource()
        source.SetXLength(1.6)
        source.SetYLength(1.6)
        source.SetZLength(1.6)
        triangles = vtk.vtkTriangleFilter()
        triangles.SetInputConnection(source.GetOutputPort())
        output_port = triangles.GetOutputPort()
    elif name == "torus":
        torus = vtk.vtkParametricTorus()
        torus.SetRingRadius(1.0)
        torus.SetCrossSectionRadius(0.45)
        source = vtk.vtkParametricFunctionSource()
        source.SetParametricFunction(torus)
        source.SetUResolution(128)
        source.SetVResolution(64)
        source.SetScalarModeToNone()
        # The source repeats the points of its two seams: merged, the surface is closed.
        clean = vtk.vtkCleanPolyData()
        clean.SetInputConnection(source.GetOutputPort())
        clean.SetTolerance(1.0e-6)
        clean.ConvertPolysToLinesOff()  # the triangles the merge makes degenerate stay (unseen)
        normals = vtk.vtkPolyDataNormals()
        normals.SetInputConnection(clean.GetOutputPort())
        normals.SplittingOff()
        normals.ConsistencyOn()
        normals.AutoOrientNormalsOn()
        output_port = normals.GetOutputPort()
    else:
        raise ValueError("unknown mesh " + name)
    algorithm = output_port.GetProducer()
    algorithm.Update()
    # Triangles only (the torus's merge leaves two vertices of collapsed triangles).
    surface = vtk.vtkPolyData()
    surface.ShallowCopy(algorithm.GetOutputDataObject(0))
    surface.SetVerts(vtk.vtkCellArray())
    return surface


def pixel_directions(camera_position):
    """Unit world directions through the pixel centres, [SIZE, SIZE, 3], row 0 at the top,
    for a camera at camera_position looking at the origin with +Y up (VTK's and Mitsuba's)."""
    eye = numpy.asarray(camera_position, dtype=float)
    forward = -eye / numpy.linalg.norm(eye)
    right = numpy.cross(forward, (0.0, 1.0, 0.0))
    right /= numpy.linalg.norm(right)
    up = numpy.cross(right, forward)
    half = math.tan(math.radians(VIEW_ANGLE) / 2.0)
    centres = (numpy.arange(SIZE) + 0.5) / SIZE * 2.0 - 1.0
    x = centres[None, :, None] * half
    y = -centres[:, None, None] * half
    d = forward + x * right + y * up
    return d / numpy.linalg.norm(d, axis=-1, keepdims=True)


def block_means(image):
    """image [SIZE, SIZE, c] averaged over BLOCK x BLOCK blocks."""
    n = SIZE // BLOCK
    return image.reshape(n, BLOCK, n, BLOCK, -1).mean(axis=(1, 3))


def comparison(rendered, reference_blocks, mask):
    """Mean |difference| (in /255) and its 95th percentile over the blocks whose pixels all lie
    on the object, at least one pixel away from its outline: rendered [SIZE, SIZE, 3] linear,
    reference_blocks [SIZE/BLOCK, SIZE/BLOCK, 3], mask [SIZE, SIZE] bool."""
    inner = mask.copy()
    for axis in (0, 1):
        for shift in (1, -1):
            inner &= numpy.roll(mask, shift, axis=axis)
    full = block_means(inner[..., None].astype(float))[..., 0] >= 1.0
    difference = numpy.abs(block_means(rendered) - reference_blocks).mean(axis=-1)[full] * 255.0
    return float(difference.mean()), float(numpy.percentile(difference, 95)), int(full.sum())


def write_png(image, path):
    """A linear image [SIZE, SIZE, 3] (row 0 at the top) as an sRGB PNG (vtk imported here only)."""
    import vtk
    from vtk.util import numpy_support

    srgb = numpy.where(image <= 0.0031308, 12.92 * image, 1.055 * numpy.power(
        numpy.clip(image, 0.0031308, None), 1.0 / 2.4) - 0.055)
    rgb = (numpy.clip(srgb, 0.0, 1.0) * 255.0 + 0.5).astype(numpy.uint8)[::-1].reshape(-1, 3)
    data = vtk.vtkImageData()
    data.SetDimensions(SIZE, SIZE, 1)
    data.GetPointData().SetScalars(numpy_support.numpy_to_vtk(rgb.copy(), deep=True))
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()
