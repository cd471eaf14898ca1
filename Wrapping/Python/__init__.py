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
        "vtkice was built against VTK %s but this Python imports VTK %s (%s): rebuild vtkice "
        "against this VTK (pip install . with its SDK, see VTK Ice's README)"
        % (_BUILT_AGAINST, _vtkVersion.GetVTKVersion(), vtkmodules.__file__)
    )

from .RenderingIce import *  # noqa: F401,F403,E402
