# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""A ready vtkice wheel where it was installed with pip beside PyPI's vtk and PyVista (./ice.sh
wheels-test: fresh venvs of the host's Pythons and of Debian 13's and sid's, no compiler, no
OpenImageIO). No X server: VTK renders through EGL.

usage: ready_wheel.py WORK_DIR [BASELINE.png]
  - the environment is read from a Radiance HDR panorama file, sky above ground, with VTK's
    readers (the wheel has no OpenImageIO): the cube map's +Y face is the sky, -Y the ground;
  - an OpenEXR file is refused with one error naming the format;
  - the installed distribution carries the licence (LICENSE);
  - a PyVista scene of an ice sphere in that environment, rendered through EGL, against
    BASELINE (compare_images.py's check, its alternatives BASELINE_1.png... too).
Prints one line per check; exits 1 when one fails."""
import os
import sys
from importlib.metadata import distribution

here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [here, os.path.join(here, "..", "Scripts")]

import numpy as np  # noqa: E402
import pyvista as pv  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkSkybox, vtkTexture  # noqa: E402

import vtkice  # noqa: E402
import vtkice.pyvista  # noqa: E402
from compare_images import compare_with_alternatives  # noqa: E402
from panorama_files import GROUND, NEGATIVE_Y, POSITIVE_Y, SKY, halves, write_hdr  # noqa: E402

results = []


def check(name, ok, detail=""):
    print("%s %s%s" % ("ok  " if ok else "FAIL", name, ": " + detail if detail else ""))
    results.append(ok)


def read(path):
    """The reader of `path`, updated, and the messages of its errors."""
    reader = vtkice.vtkIceEnvironmentReader()
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(obj, event, message):
        errors.append(message)

    reader.AddObserver("ErrorEvent", on_error)
    reader.SetFileName(path)
    reader.Update()
    return reader, errors


def face_mean(reader, face):
    scalars = vtk_to_numpy(reader.GetOutput(face).GetPointData().GetScalars()).astype(float)
    return scalars.reshape(-1, 3).mean(axis=0) * 255.0


def main(work, baseline=None):
    os.makedirs(work, exist_ok=True)
    print("vtkice %s beside vtk %s, PyVista %s, Python %s" % (
        vtkice.__file__, vtkice._BUILT_AGAINST, pv.__version__, sys.version.split()[0]))

    panorama = os.path.join(work, "panorama.hdr")
    write_hdr(panorama, halves(256, 128))
    reader, errors = read(panorama)
    check("the HDR panorama reads without error", not errors and reader.GetErrorCode() == 0,
          "; ".join(errors))
    check("as float", reader.GetOutput(0).GetPointData().GetScalars().GetDataTypeAsString()
          == "float")
    up, down = face_mean(reader, POSITIVE_Y), face_mean(reader, NEGATIVE_Y)
    check("sky up", np.allclose(up, SKY, atol=4), "+Y face %s, sky %s" % (up.round(1), SKY))
    check("ground down", np.allclose(down, GROUND, atol=4),
          "-Y face %s, ground %s" % (down.round(1), GROUND))

    exr = os.path.join(work, "panorama.exr")
    with open(exr, "wb") as f:
        f.write(b"\x76\x2f\x31\x01" + bytes(60))
    refused, exr_errors = read(exr)
    message = " ".join(exr_errors)
    check("an OpenEXR file is refused naming its format",
          len(exr_errors) == 1 and refused.GetErrorCode() != 0 and "OpenEXR" in message, message)

    files = distribution("vtkice").files or []
    licensed = any(f.name == "LICENSE" for f in files)
    check("the wheel carries its licence", licensed,
          "" if licensed else "no LICENSE among %d files" % len(files))

    texture = vtkTexture()
    reader.ConfigureTexture(texture)
    plotter = pv.Plotter(off_screen=True, window_size=(320, 240))
    plotter.renderer.SetEnvironmentTexture(texture)
    box = vtkSkybox()
    box.SetTexture(texture)
    plotter.add_actor(box)
    vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8, theta_resolution=64, phi_resolution=64),
                           preset=None, NumberOfCracks=0, NumberOfAirPlanes=0, BumpStrength=0.0)
    plotter.camera_position = [(1.6, 0.5, 3.4), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    shot = os.path.join(work, "ready-wheel.png")
    plotter.screenshot(shot)
    window = plotter.render_window.GetClassName()
    plotter.close()
    check("rendered without X", window != "vtkXOpenGLRenderWindow", window)
    if baseline:
        ok, line = compare_with_alternatives(shot, baseline)
        check("the picture matches its baseline", ok, line)
    print("%d passed, %d failed" % (results.count(True), results.count(False)))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
