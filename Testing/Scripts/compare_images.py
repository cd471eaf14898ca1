# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Numeric comparison of two RGB(A) images of the same size, as in the C++ tests' strict check.

usage: compare_images.py A.png B.png [--alternatives]
Prints the mean and largest channel difference (in 1/255) and the share of pixels off by more
than 16/255; exits 1 unless mean <= 1/255 and at most 0.2 % of the pixels are off by more than
16/255. With --alternatives, B is a baseline and its alternatives B_1.png, B_2.png, ... (VTK's
way, where a platform draws the scene differently) count too: A must match one of them. Uses
VTK's image filters (Debian's python3-vtk9 has no numpy).
"""
import os
import sys

import vtk


def rgb(path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    extract = vtk.vtkImageExtractComponents()
    extract.SetInputConnection(reader.GetOutputPort())
    extract.SetComponents(0, 1, 2)
    cast = vtk.vtkImageCast()
    cast.SetInputConnection(extract.GetOutputPort())
    cast.SetOutputScalarTypeToInt()
    cast.Update()
    return cast.GetOutput()


def compare(a_path, b_path):
    """(ok, the line that says how A compares with B)."""
    a, b = rgb(a_path), rgb(b_path)
    if a.GetDimensions() != b.GetDimensions():
        return False, "%s is %s, %s is %s" % (a_path, a.GetDimensions(), b_path, b.GetDimensions())
    difference = vtk.vtkImageMathematics()
    difference.SetOperationToSubtract()
    difference.SetInput1Data(a)
    difference.SetInput2Data(b)
    absolute = vtk.vtkImageMathematics()
    absolute.SetOperationToAbsoluteValue()
    absolute.SetInputConnection(difference.GetOutputPort())
    # The largest of the three channel differences of each pixel.
    channels = []
    for component in range(3):
        channel = vtk.vtkImageExtractComponents()
        channel.SetInputConnection(absolute.GetOutputPort())
        channel.SetComponents(component)
        channels.append(channel)
    largest = channels[0]
    for channel in channels[1:]:
        maximum = vtk.vtkImageMathematics()
        maximum.SetOperationToMax()
        maximum.SetInputConnection(0, largest.GetOutputPort())
        maximum.SetInputConnection(1, channel.GetOutputPort())
        largest = maximum
    histogram = vtk.vtkImageAccumulate()
    histogram.SetInputConnection(largest.GetOutputPort())
    histogram.SetComponentExtent(0, 255, 0, 0, 0, 0)
    histogram.SetComponentOrigin(0, 0, 0)
    histogram.SetComponentSpacing(1, 1, 1)
    histogram.Update()
    counts = histogram.GetOutput().GetPointData().GetScalars()
    pixels = histogram.GetVoxelCount()
    mean = histogram.GetMean()[0]
    worst = histogram.GetMax()[0]
    far = sum(counts.GetValue(i) for i in range(17, 256)) / float(pixels)
    ok = mean <= 1.0 and far <= 0.002
    return ok, ("%s vs %s: %d pixels, mean %.3f/255, max %d/255, %.3f%% off by more than 16/255"
                % (a_path, b_path, pixels, mean, worst, 100.0 * far))


def compare_with_alternatives(a_path, b_path, alternatives=True):
    """(ok, the line) for A against baseline B or, with `alternatives`, one of B_1.png, ..."""
    candidates = [b_path]
    stem = b_path[:-4] if b_path.endswith(".png") else b_path
    while alternatives and os.path.exists("%s_%d.png" % (stem, len(candidates))):
        candidates.append("%s_%d.png" % (stem, len(candidates)))
    results = [compare(a_path, candidate) for candidate in candidates]
    passed = [line for ok, line in results if ok]
    return (True, passed[0]) if passed else (False, results[0][1])


def main(a_path, b_path, alternatives=False):
    ok, line = compare_with_alternatives(a_path, b_path, alternatives)
    print(("ok   " if ok else "FAIL ") + line)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], "--alternatives" in sys.argv[3:]))
