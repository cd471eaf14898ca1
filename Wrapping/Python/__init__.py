# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""VTK Ice: real-time ice rendering for VTK (Seipel & Nivfors).

Import ``vtk`` (or the ``vtkmodules`` it needs) first, then use
``vtkice.vtkIceMapper`` like any VTK mapper. With PyVista: ``vtkice.pyvista``.
"""
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (vtkIceMapper's base class)
from vtkmodules.vtkCommonCore import vtkVersion as _vtkVersion

# VTK has no ABI stability between releases: the package runs on the VTK it was built against.
_BUILT_AGAINST = "@VTK_VERSION@"
if _vtkVersion.GetVTKVersion() != _BUILT_AGAINST:
    raise ImportError(
        "vtkice was built against VTK %s but this Python imports VTK %s (%s): install the vtk it "
        "needs (pip install vtk==%s) or build vtkice against this VTK (pip install . with its SDK, "
        "see VTK Ice's README)"
        % (_BUILT_AGAINST, _vtkVersion.GetVTKVersion(), vtkmodules.__file__, _BUILT_AGAINST)
    )

# One package for the project's modules, as VTK's own are one.
from .FiltersIce import *  # noqa: F401,F403,E402
from .RenderingIce import *  # noqa: F401,F403,E402
from .IOIce import *  # noqa: F401,F403,E402
from .LookIce import *  # noqa: F401,F403,E402
# The paper's passes (InteriorPaperPasses): importing them registers their object factory.
from .RenderingIcePaper import *  # noqa: F401,F403,E402


# The look ice-render starts from, and vtkice.pyvista.add_ice: natural ice (the library's own
# defaults are the paper's look).
DEFAULT_PRESET = "ice-cube"


def presets():
    """The names of the shipped looks (ice-render's presets): clear, ice-cube, lake, ..."""
    import os

    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "presets")
    return sorted(f[:-4] for f in os.listdir(folder) if f.endswith(".ice"))


def preset_path(name):
    """The file of the shipped look `name` (see presets()), for vtkIceLook.ApplyPreset; a
    ValueError lists the names where there is no such look."""
    import os

    if name not in presets():
        raise ValueError("no preset %r (the shipped ones are %s)" % (name, ", ".join(presets())))
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "presets", name + ".ice")


def use_backend(name="auto"):
    """Chooses how every render window created from now on draws: "x" (an X display), "egl" or
    "osmesa" (no X server needed), or "auto" (X when DISPLAY opens, else EGL, else OSMesa), as
    ``ice-render --backend`` does. Call it before the first render window is made (PyVista: before
    the first Plotter); use one back end per process. Returns a line saying what was found.

    Without it, VTK older than 9.4 aborts a script when no X display can be opened. Where vtkice
    was built without its back ends (the pip wheel, for VTK >= 9.4), VTK's own fallback from X to
    EGL to OSMesa serves; a named back end is then asked of VTK (VTK_DEFAULT_OPENGL_WINDOW).
    """
    if name not in ("auto", "x", "egl", "osmesa"):
        raise ValueError("unknown back end %r (expected auto, x, egl or osmesa)" % (name,))
    try:
        from . import _headless
    except ImportError:
        _headless = None
    if _headless is not None:
        return _headless.install(name)
    if name == "auto":
        return "auto: VTK's own choice (X, else EGL, else OSMesa)"
    import os

    os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = {
        "x": "vtkXOpenGLRenderWindow",
        "egl": "vtkEGLRenderWindow",
        "osmesa": "vtkOSOpenGLRenderWindow",
    }[name]
    return "%s: VTK's %s" % (name, os.environ["VTK_DEFAULT_OPENGL_WINDOW"])
