# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.vtkIceEnvironmentReader from Python: one error for a missing file, and six face images
written with VTK (top row first) read back exactly. Run with Debian's /usr/bin/python3.
"""
import os
import sys
import tempfile

import vtk
import vtkice

from ice_test_helpers import check

FACES = ["px", "nx", "py", "ny", "pz", "nz"]


def watch_errors(obj):
    errors = []

    def on_error(caller, event, message):
        # Keep the message, not VTK's "ERROR: In file, line N / class (address): " preamble.
        errors.append(message.split("): ", 1)[-1].strip())

    on_error.CallDataType = vtk.VTK_STRING
    obj.AddObserver("ErrorEvent", on_error)
    return errors


def main():
    reader = vtkice.vtkIceEnvironmentReader()
    check(reader.GetFaceSize() == 0)
    reader.SetFaceSize(100000)
    check(reader.GetFaceSize() == 8192, "FaceSize is clamped to [0, 8192]")
    reader.SetFaceSize(0)

    errors = watch_errors(reader)
    reader.SetFileName("/no/such/environment")
    reader.Update()
    print("missing file:", errors)
    check(len(errors) == 1 and "does not exist" in errors[0])
    check(reader.GetLayoutAsString() == "Unknown")
    check(reader.GetOutput(0).GetNumberOfPoints() == 0)

    source = vtkice.vtkIceCubeMapSource()
    source.SetPatternToDirectionTest()
    source.SetFaceSize(16)
    source.Update()
    with tempfile.TemporaryDirectory() as folder:
        for port, name in enumerate(FACES):
            # VTK's PNG writer puts row 0 at the bottom; face files have it at the top.
            flip = vtk.vtkImageFlip()
            flip.SetInputConnection(source.GetOutputPort(port))
            flip.SetFilteredAxis(1)
            writer = vtk.vtkPNGWriter()
            writer.SetInputConnection(flip.GetOutputPort())
            writer.SetFileName(os.path.join(folder, name + ".png"))
            writer.Write()
        reader.SetFileName(folder)
        reader.Update()
        check(reader.GetLayout() == vtkice.vtkIceEnvironmentReader.Faces)
        for port in range(6):
            read = reader.GetOutput(port).GetPointData().GetScalars()
            made = source.GetOutput(port).GetPointData().GetScalars()
            check(read.GetNumberOfTuples() == made.GetNumberOfTuples() == 16 * 16)
            worst = max(abs(read.GetComponent(t, c) - made.GetComponent(t, c))
                        for t in range(read.GetNumberOfTuples()) for c in range(3))
            check(worst == 0, "face %s differs by %d" % (FACES[port], worst))
    check(len(errors) == 1, "no further errors")

    texture = vtk.vtkTexture()
    reader.ConfigureTexture(texture)
    check(texture.GetCubeMap() and texture.GetInterpolate())
    print("faces read back exactly; layout", reader.GetLayoutAsString())
    print("1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
