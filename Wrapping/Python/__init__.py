"""VTK Ice: real-time ice rendering for VTK (Seipel & Nivfors).

Import ``vtk`` (or the ``vtkmodules`` it needs) first, then use
``vtkice.vtkIceMapper`` like any VTK mapper.
"""
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (vtkIceMapper's base class)

from .RenderingIce import *  # noqa: F401,F403
