# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Reads one uploaded model file for the web viewer, in a child process of its own (VTK's readers
crash on some broken files; the server must not): ice_web_read.py MODEL OUT.vtp. Exit status 0:
OUT.vtp written; 1: the problem is the last line printed; anything else: the reader crashed.
"""
import os
import sys

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

READERS = {".stl": vtkSTLReader, ".ply": vtkPLYReader, ".obj": vtkOBJReader}


def main(path, out):
    reader = READERS[os.path.splitext(path)[1].lower()]()
    reader.SetFileName(path)
    errors = []
    # Observed, VTK's errors are not printed: the page gets one line.
    reader.AddObserver(vtkCommand.ErrorEvent, lambda _object, _event: errors.append(1))
    reader.Update()
    output = reader.GetOutput()
    if errors or reader.GetErrorCode():
        print("cannot read it: the reader reported an error")
        return 1
    if output.GetNumberOfPolys() + output.GetNumberOfStrips() == 0:
        print("it has no polygons")
        return 1
    # Point arrays with fewer values than points (an OBJ file with fewer texture coordinates than
    # vertices) are not used by the ice; drop them as ice-render does.
    data = output.GetPointData()
    for i in reversed(range(data.GetNumberOfArrays())):
        array = data.GetAbstractArray(i)
        if array is not None and array.GetNumberOfTuples() < output.GetNumberOfPoints():
            data.RemoveArray(i)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(out)
    writer.SetInputData(output)
    return 0 if writer.Write() == 1 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
