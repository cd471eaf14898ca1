# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Environment images the Python tests write: panoramas of sky above ground, in the formats
vtkIceEnvironmentReader reads (PNG and JPEG through VTK's writers, Radiance HDR by hand)."""
import struct

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

SKY = (40, 90, 220)     # the upper half of each panorama
GROUND = (60, 170, 50)  # the lower half
POSITIVE_Y, NEGATIVE_Y = 2, 3


def halves(width, height):
    """Rows top first: sky above the horizon, ground below."""
    rgb = np.zeros((height, width, 3), dtype=np.uint8)
    rgb[: height // 2] = SKY
    rgb[height // 2:] = GROUND
    return rgb


def write_vtk(path, rgb, writer_class):
    height, width, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    # VTK's image rows go bottom up.
    image.GetPointData().SetScalars(numpy_to_vtk(rgb[::-1].reshape(-1, 3).copy(), deep=True))
    writer = writer_class()
    writer.SetFileName(str(path))
    writer.SetInputData(image)
    writer.Write()


def write_hdr(path, rgb):
    """A Radiance HDR file of flat (not run-length encoded) RGBE scanlines."""
    height, width, _ = rgb.shape
    with open(path, "wb") as out:
        out.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        out.write(b"-Y %d +X %d\n" % (height, width))
        for row in rgb:
            for r, g, b in row / 255.0:
                top = max(r, g, b)
                exponent = int(np.floor(np.log2(top))) + 1 if top > 0 else -128
                scale = 256.0 / 2.0 ** exponent if top > 0 else 0.0
                out.write(struct.pack("BBBB", int(r * scale), int(g * scale), int(b * scale),
                                      exponent + 128 if top > 0 else 0))
