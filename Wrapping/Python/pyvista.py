# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Ice in a PyVista plotter.

    import pyvista as pv
    import vtkice.pyvista

    plotter = pv.Plotter()
    plotter.set_environment_texture(pv.examples.download_sky_box_cube_map())  # or any cube map
    vtkice.pyvista.add_ice(plotter, pv.Sphere(), NumberOfCracks=4, Milkiness=0.6)
    plotter.show()

``add_ice`` draws a mesh with a ``vtkIceMapper`` and puts a ``vtkIcePass`` into the plotter's
render passes where PyVista's own passes expect the pass that draws the scene: the ice works with
PyVista's SSAO, depth of field, eye-dome lighting and blur, before or after they are switched
on; with its shadows or SSAA it loses its interior (a warning says so). ``tone_mapping(plotter,
"filmic", exposure=-1)`` maps a photographed HDR environment's light to the screen.
"""
import re
import warnings

import pyvista as _pv
from vtkmodules.vtkCommonCore import vtkObject as _vtkObject
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper as _vtkOpenGLPolyDataMapper
from vtkmodules.vtkRenderingOpenGL2 import vtkToneMappingPass as _vtkToneMappingPass

from . import (DEFAULT_PRESET, preset_path, vtkIceCubeMapPass, vtkIceLook, vtkIceMapper,
               vtkIcePaperInterior, vtkIcePass, vtkIceProperty)

__all__ = ["add_ice", "ice_pass", "tone_mapping"]


def _setter(mapper, name):
    """The Set method for a parameter given as 'NumberOfCracks' or 'number_of_cracks': the
    look's are the mapper's vtkIceProperty's, how the ice is drawn the mapper's own, and the
    paper's passes' own (crack_clipping) its vtkIcePaperInterior's."""
    camel = name if name[:1].isupper() else "".join(part.title() for part in name.split("_"))
    for target in (mapper.GetIceProperty(), mapper, mapper.GetPaperInterior()):
        method = getattr(target, "Set" + camel, None)
        if method is not None:
            return method
    raise TypeError("vtkice.pyvista: vtkIceMapper has no parameter %r; the ice's own are %s"
                    % (name, ", ".join(_look_parameters())))


def _settable(cls, base):
    """The Name of each SetName/GetName pair `cls` has beyond `base`."""
    own = set(dir(cls)) - set(dir(base))
    return {m[3:] for m in own if re.match(r"Set[A-Z]", m) and hasattr(cls, "Get" + m[3:])}


def _look_parameters():
    """The parameters of the ice's look (vtkIceProperty), those vtkIceMapper adds to VTK's
    mapper (those of vtkOpenGLPolyDataMapper work too) and the paper passes' own."""
    return sorted(_settable(vtkIceProperty, _vtkObject) |
                  _settable(vtkIceMapper, _vtkOpenGLPolyDataMapper) |
                  _settable(vtkIcePaperInterior, _vtkObject))


def ice_pass(plotter):
    """The plotter's vtkIcePass, put into its render passes the first time it is asked for.

    PyVista draws the scene with the first pass of its pass collection (a vtkRenderStepsPass)
    inside a camera pass, which its SSAO, depth-of-field, eye-dome-lighting, anti-aliasing and
    blur passes wrap, and beside which it adds the shadow passes. The ice pass takes that first
    place (it draws the scene with a vtkRenderStepsPass of its own), so every PyVista pass
    switched on before or after keeps the ice. PyVista hands the renderer no pass at all when none
    of its own is on: the ice pass is handed over then. With PyVista's shadows or SSAA the ice
    loses its interior (the shadow pass draws the surfaces again over it; SSAA renders the scene
    at another size): a RuntimeWarning says so.
    """
    renderer = plotter.renderer
    existing = getattr(renderer, "_vtkice_pass", None)
    if existing is not None:
        return existing
    passes = renderer._render_passes
    collection = passes._pass_collection
    first = collection.GetItemAsObject(0)
    if first is None or not first.IsA("vtkRenderStepsPass"):
        raise RuntimeError("vtkice.pyvista: this PyVista's render passes have no vtkRenderStepsPass "
                           "first (PyVista %s); set the pass yourself: "
                           "plotter.renderer.SetPass(vtkice.vtkIcePass())" % _pv.__version__)
    icepass = vtkIcePass()
    collection.ReplaceItem(0, icepass)
    update = passes._update_passes

    def update_keeping_ice():
        update()
        if renderer.GetPass() is None:
            renderer.SetPass(passes._camera_pass)
        lost = [name for name, on in (("shadows", passes._shadow_map_pass is not None),
                                      ("SSAA anti-aliasing", passes._ssaa_pass is not None)) if on]
        if lost:
            warnings.warn("vtkice.pyvista: with PyVista's %s the ice is drawn without its interior "
                          "(cracks, air): they cannot be combined yet" % " and ".join(lost),
                          RuntimeWarning, stacklevel=3)

    passes._update_passes = update_keeping_ice
    renderer._vtkice_pass = icepass
    update_keeping_ice()
    return icepass


def tone_mapping(plotter, curve="filmic", exposure=0.0):
    """Maps the plotter's light to the screen through a tone curve, as ``ice-render
    --tone-mapping CURVE --exposure EV`` does: ``curve`` one of "none", "reinhard", "exponential",
    "filmic", "aces"; ``exposure`` in stops (+1 doubles the light; VTK applies it in the
    exponential, filmic and ACES curves). A photographed HDR environment is brighter than white
    where the sun shines: without a curve it is clipped. The curve is VTK's vtkToneMappingPass,
    put around the plotter's ice pass the first time; returns it. A bad name or value raises
    ValueError saying what is accepted.
    """
    icepass = ice_pass(plotter)
    renderer = plotter.renderer
    curves = getattr(renderer, "_vtkice_tone_mapping", None)
    if curves is None:
        curves = _vtkToneMappingPass()
        vtkIceLook.ResetToneMapping(curves)
        curves.SetDelegatePass(icepass)
        collection = renderer._render_passes._pass_collection
        for i in range(collection.GetNumberOfItems()):
            if collection.GetItemAsObject(i) is icepass:
                collection.ReplaceItem(i, curves)
        renderer._vtkice_tone_mapping = curves
        if renderer.GetPass() is icepass:
            renderer.SetPass(curves)
    # The look table's settings (the names and ranges of ice-render's options); they act on the
    # tone-mapping pass only, the scratch mapper and cube-map pass stand for the rest of a scene.
    for name, value in (("tone-mapping", curve), ("exposure", exposure)):
        problem = vtkIceLook.Apply(vtkIceMapper(), icepass, vtkIceCubeMapPass(),
                                   renderer.GetActiveCamera(), curves, name, str(value))
        if problem:
            raise ValueError("vtkice.pyvista.tone_mapping: " + problem)
    return curves


def add_ice(plotter, mesh, name=None, pickable=True, dynamic_environment=False,
            preset=DEFAULT_PRESET, **look):
    """Adds `mesh` to `plotter` as ice and returns its actor (a pyvista.Actor).

    `mesh` is any PyVista or VTK data set (its surface is used). The ice starts from the look
    `preset`, one of vtkice.presets(): by default "ice-cube", natural ice as ice-render draws it
    (the light traced through it, a cloudy core of small bubbles); None keeps the library's
    defaults (the paper's look). `look` then sets the ice's parameters by name, those of the look
    on the mapper's vtkIceProperty and those of the drawing on the mapper, e.g.
    ``NumberOfCracks=4`` or ``number_of_cracks=4``, ``IceColor=(0.8, 0.9, 1.0)``,
    ``TwoSidedRefraction=False``. An unknown name raises TypeError listing the parameters, an
    unknown preset ValueError listing the shipped ones; the plotter is then left as it was. The ice reflects and refracts the renderer's environment texture
    (``plotter.renderer.SetEnvironmentTexture``); with ``dynamic_environment=True`` the plotter's
    ice pass also renders a cube map of the scene around each ice (a vtkIceCubeMapPass), so the
    plotter's other objects show in the ice.
    """
    data = _pv.wrap(mesh)
    if not isinstance(data, _pv.PolyData):
        data = data.extract_surface()
    mapper = vtkIceMapper()
    mapper.SetInputData(data)
    # Names checked before the plotter changes.
    setters = [(_setter(mapper, key), value) for key, value in look.items()]
    path = preset_path(preset) if preset is not None else None
    icepass = ice_pass(plotter)
    if path is not None:
        # A shipped look names the ice's settings only; a scratch cube-map pass stands for one
        # the plotter may not have.
        problem = vtkIceLook.ApplyPreset(mapper, icepass, vtkIceCubeMapPass(),
                                         plotter.renderer.GetActiveCamera(), path)
        if problem:
            raise ValueError("vtkice.pyvista.add_ice: " + problem)
    for setter, value in setters:
        if isinstance(value, (tuple, list)):
            setter(*value)
        else:
            setter(value)
    actor = _pv.Actor(mapper=mapper)
    actor.SetPickable(bool(pickable))
    if dynamic_environment and icepass.GetCubeMapPass() is None:
        icepass.SetCubeMapPass(vtkIceCubeMapPass())
    plotter.add_actor(actor, name=name, pickable=pickable)
    return actor

