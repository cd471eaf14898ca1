# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkIceEnvironmentReader in the installed package beside the wheel: it reads through Debian's
OpenImageIO (the new libstdc++ ABI) while VTK and the package use the wheel's old one. PNG, JPEG and
HDR panoramas and a PNG cross load with the right layout and colours (EXR: Cxx.TestIceEnvironmentReader
in the same lane)."""
import numpy as np
import pytest
from panorama_files import GROUND, NEGATIVE_Y, POSITIVE_Y, SKY, halves, write_hdr, write_vtk
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkJPEGWriter, vtkPNGWriter

import vtkice


def read(path):
    reader = vtkice.vtkIceEnvironmentReader()
    errors = []
    reader.AddObserver("ErrorEvent", lambda *args: errors.append(args))
    reader.SetFileName(str(path))
    reader.Update()
    assert not errors and reader.GetErrorCode() == 0
    return reader


def face_mean(reader, face):
    scalars = vtk_to_numpy(reader.GetOutput(face).GetPointData().GetScalars()).astype(float)
    if scalars.max() <= 4.0:  # float faces (HDR): back to 0..255
        scalars = scalars * 255.0
    return scalars.reshape(-1, 3).mean(axis=0)


@pytest.mark.parametrize("kind", ["png", "jpg", "hdr"])
def test_panorama_loads_with_sky_up_and_ground_down(tmp_path, kind):
    rgb = halves(256, 128)
    path = tmp_path / ("panorama." + kind)
    if kind == "png":
        write_vtk(path, rgb, vtkPNGWriter)
    elif kind == "jpg":
        write_vtk(path, rgb, vtkJPEGWriter)
    else:
        write_hdr(path, rgb)
    reader = read(path)
    assert reader.GetLayoutAsString() == "Equirectangular"
    assert reader.GetOutput(POSITIVE_Y).GetDimensions() == (64, 64, 1)
    assert face_mean(reader, POSITIVE_Y) == pytest.approx(SKY, abs=4)
    assert face_mean(reader, NEGATIVE_Y) == pytest.approx(GROUND, abs=4)
    if kind == "hdr":
        assert reader.GetOutput(0).GetPointData().GetScalars().GetDataTypeAsString() == "float"


def test_horizontal_cross_loads_face_by_face(tmp_path):
    size = 32
    cross = np.zeros((3 * size, 4 * size, 3), dtype=np.uint8)
    # The +Y face (top row, second column) sky, the -Y face (bottom row) ground.
    cross[0:size, size:2 * size] = SKY
    cross[2 * size:3 * size, size:2 * size] = GROUND
    path = tmp_path / "cross.png"
    write_vtk(path, cross, vtkPNGWriter)
    reader = read(path)
    assert reader.GetLayoutAsString() == "HorizontalCross"
    assert face_mean(reader, POSITIVE_Y) == pytest.approx(SKY, abs=1)
    assert face_mean(reader, NEGATIVE_Y) == pytest.approx(GROUND, abs=1)


def test_a_broken_file_gives_one_error_naming_it(tmp_path):
    path = tmp_path / "broken.png"
    path.write_bytes(b"not a PNG")
    reader = vtkice.vtkIceEnvironmentReader()
    errors = []
    reader.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    reader.SetFileName(str(path))
    reader.Update()
    assert len(errors) == 1 and reader.GetErrorCode() != 0
    assert reader.GetLayoutAsString() == "Unknown"
