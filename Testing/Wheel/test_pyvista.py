# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkice.pyvista: ice in a PyVista plotter (vtk wheel, off screen, no X server)."""
import numpy as np
import pytest

pv = pytest.importorskip("pyvista")
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
from vtkmodules.vtkRenderingCore import vtkSkybox, vtkTexture  # noqa: E402

import vtkice  # noqa: E402
import vtkice.pyvista  # noqa: E402

SIZE = (320, 240)
CAMERA = [(1.6, 0.5, 3.4), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
# The library's look without cracks, air or bumps: the tests of the plotter's mechanics.
CLEAN = dict(preset=None, NumberOfCracks=0, NumberOfAirPlanes=0, BumpStrength=0.0)
# Module-level meshes: PyVista names an actor after its mesh's address, which a freed temporary
# mesh would hand on to the next one (replacing its actor).
CONE = pv.Cone(center=(-0.6, 0.0, -1.5), direction=(0, 1, 0), radius=0.6, height=1.5)
FLOOR = pv.Plane(center=(0.0, -1.1, 0.0), direction=(0, 1, 0), i_size=6, j_size=6)


def environment():
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(128)
    texture = vtkTexture()
    sky.ConfigureTexture(texture)
    return texture


def plotter_with_scene(texture, skybox=True):
    """A plotter with PyVista's own objects: a cone and a floor, and the cube map around them."""
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    plotter.renderer.SetEnvironmentTexture(texture)
    if skybox:
        box = vtkSkybox()
        box.SetTexture(texture)
        plotter.add_actor(box)
    plotter.add_mesh(CONE, color="orange")
    plotter.add_mesh(FLOOR, color="seagreen")
    plotter.camera_position = CAMERA
    return plotter


def shot(plotter):
    image = plotter.screenshot(return_img=True).astype(int)
    plotter.close()
    return image


def silhouette(mesh):
    """The pixels the mesh covers, from the same camera (white, unlit, on black)."""
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    plotter.set_background("black")
    plotter.add_mesh(mesh, color="white", lighting=False)
    plotter.camera_position = CAMERA
    return shot(plotter).max(axis=2) > 0


def grow(mask, pixels):
    """The mask and its neighbours within `pixels` (anti-aliased edges)."""
    out = mask.copy()
    for dy in range(-pixels, pixels + 1):
        for dx in range(-pixels, pixels + 1):
            out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return out


def test_ice_changes_pixels_only_inside_its_silhouette():
    texture = environment()
    sphere = pv.Sphere(radius=0.8, theta_resolution=64, phi_resolution=64)
    without = shot(plotter_with_scene(texture))
    plotter = plotter_with_scene(texture)
    vtkice.pyvista.add_ice(plotter, sphere)
    with_ice = shot(plotter)
    inside = silhouette(sphere)
    changed = np.abs(with_ice - without).max(axis=2) > 2
    assert changed[inside].mean() > 0.5, "the ice barely shows"
    outside = changed & ~grow(inside, 2)
    assert outside.sum() == 0, "%d pixels changed outside the ice" % outside.sum()


def test_eta_one_ice_is_invisible_against_a_skybox():
    texture = environment()
    sphere = pv.Sphere(radius=0.8, theta_resolution=96, phi_resolution=96)
    plain = pv.Plotter(off_screen=True, window_size=SIZE)
    plain.renderer.SetEnvironmentTexture(texture)
    box = vtkSkybox()
    box.SetTexture(texture)
    plain.add_actor(box)
    plain.camera_position = CAMERA
    background = shot(plain)

    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    plotter.renderer.SetEnvironmentTexture(texture)
    box = vtkSkybox()
    box.SetTexture(texture)
    plotter.add_actor(box)
    vtkice.pyvista.add_ice(plotter, sphere, RefractionRatio=1.0, FresnelPower=1.0e6, **CLEAN)
    plotter.camera_position = CAMERA
    image = shot(plotter)
    # The interior, away from the silhouette where the edge blends with the background.
    inside = ~grow(~silhouette(sphere), 3)
    difference = np.abs(image - background).max(axis=2)[inside]
    assert inside.sum() > 10000
    assert difference.mean() <= 1.0 and np.percentile(difference, 99) <= 4.0, (
        "mean %.2f p99 %.1f" % (difference.mean(), np.percentile(difference, 99)))


def test_pyvista_picker_returns_the_ice_actor():
    plotter = plotter_with_scene(environment())
    actor = vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8))
    picked = []
    plotter.enable_mesh_picking(lambda a: picked.append(a), use_actor=True, show=False,
                                left_clicking=True, picker="hardware")
    plotter.show(auto_close=False)  # off screen: renders and starts the interactor, no loop
    plotter.iren._mouse_left_button_click(SIZE[0] // 2, SIZE[1] // 2)
    assert plotter.picked_actor is actor
    assert picked and picked[-1] is actor
    plotter.close()


@pytest.mark.parametrize("name, switch_on", [
    ("ssao", lambda p: p.enable_ssao()),
    ("eye-dome lighting", lambda p: p.enable_eye_dome_lighting()),
    ("depth of field", lambda p: p.enable_depth_of_field()),
    ("blur", lambda p: p.add_blurring()),
])
def test_ice_pass_keeps_working_with_pyvistas_passes(name, switch_on):
    """PyVista rebuilds its pass chain when one of its passes is switched on or off: the ice pass
    stays in it and draws the ice (one ice prop found), before and after."""
    plotter = plotter_with_scene(environment())
    vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8), **CLEAN)
    icepass = vtkice.pyvista.ice_pass(plotter)
    plotter.screenshot(return_img=True)  # an off-screen plotter renders for a screenshot
    assert icepass.GetNumberOfIceProps() == 1
    switch_on(plotter)
    plotter.screenshot(return_img=True)
    assert icepass.GetNumberOfIceProps() == 1, "ice lost with %s" % name
    plotter.close()


@pytest.mark.parametrize("name, switch_on", [
    ("shadows", lambda p: p.enable_shadows()),
    ("SSAA", lambda p: p.enable_anti_aliasing("ssaa")),
])
def test_passes_that_cannot_be_combined_say_so(name, switch_on):
    plotter = plotter_with_scene(environment())
    vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8))
    with pytest.warns(RuntimeWarning, match=name):
        switch_on(plotter)
    plotter.close()


def test_ice_pass_stays_when_pyvistas_passes_are_switched_off():
    plotter = plotter_with_scene(environment())
    vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8), **CLEAN)
    icepass = vtkice.pyvista.ice_pass(plotter)
    plotter.enable_ssao()
    plotter.disable_ssao()
    plotter.screenshot(return_img=True)
    assert plotter.renderer.GetPass() is not None
    assert icepass.GetNumberOfIceProps() == 1
    plotter.close()


def test_unknown_look_parameter_names_the_known_ones():
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    with pytest.raises(TypeError, match="NumberOfCracks"):
        vtkice.pyvista.add_ice(plotter, pv.Sphere(), NumberOfCrackz=3)
    plotter.close()


def _look_values(actor, plotter):
    """Every setting of the ice's look (vtkIceLook's table, camera settings left out) on the
    actor's mapper, as text."""
    Look = vtkice.vtkIceLook
    icepass = vtkice.pyvista.ice_pass(plotter)
    cube_maps = vtkice.vtkIceCubeMapPass()
    camera = plotter.renderer.GetActiveCamera()
    return {Look.GetName(i): Look.GetValue(actor.GetMapper(), icepass, cube_maps, camera,
                                           Look.GetName(i))
            for i in range(Look.GetNumberOfSettings()) if not Look.IsCameraSetting(i)}


def test_ice_starts_from_ice_renders_default_look():
    """add_ice's ice is ice-render's default (the ice-cube preset), not the library's paper look:
    every setting the preset names has the preset's value."""
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    values = _look_values(vtkice.pyvista.add_ice(plotter, pv.Sphere()), plotter)
    named = {}
    with open(vtkice.preset_path(vtkice.DEFAULT_PRESET)) as preset:
        for line in preset:
            line = line.split("#")[0].strip()
            if line:
                key, value = (part.strip() for part in line.split("="))
                named[key] = value
    assert vtkice.DEFAULT_PRESET == "ice-cube" and len(named) > 8
    for key, value in named.items():
        got = values[key]
        if key in ("fresnel", "two-sided-method"):
            assert got == value, key
        else:
            assert [float(v) for v in got.split(",")] == pytest.approx(
                [float(v) for v in value.split(",")]), key
    plotter.close()


def test_no_preset_keeps_the_librarys_defaults():
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    values = _look_values(vtkice.pyvista.add_ice(plotter, pv.Sphere(), preset=None), plotter)
    Look = vtkice.vtkIceLook
    for i in range(Look.GetNumberOfSettings()):
        name = Look.GetName(i)
        if name in values and not name.startswith(("cube-map", "tone-mapping", "exposure")):
            assert values[name] == Look.GetDefault(i), name
    plotter.close()


def test_unknown_preset_names_the_shipped_ones_and_changes_nothing():
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    with pytest.raises(ValueError, match="ice-cube"):
        vtkice.pyvista.add_ice(plotter, pv.Sphere(), preset="ice-cubes")
    assert getattr(plotter.renderer, "_vtkice_pass", None) is None
    assert len(plotter.renderer.actors) == 0
    plotter.close()


def test_look_parameters_reach_the_mapper():
    plotter = pv.Plotter(off_screen=True, window_size=SIZE)
    actor = vtkice.pyvista.add_ice(plotter, pv.Sphere(), number_of_cracks=5,
                                   IceColor=(0.8, 0.9, 1.0))
    assert actor.GetMapper().GetIceProperty().GetNumberOfCracks() == 5
    assert actor.GetMapper().GetIceProperty().GetIceColor() == pytest.approx((0.8, 0.9, 1.0))
    plotter.close()


def test_tone_mapping_compresses_the_light_and_keeps_the_ice():
    """A tone curve around the ice pass: the picture changes (the sky's brights compressed), the
    ice is still drawn, and PyVista's passes switched on afterwards keep both."""
    plain = plotter_with_scene(environment())
    vtkice.pyvista.add_ice(plain, pv.Sphere(radius=0.8), **CLEAN)
    before = shot(plain)
    plotter = plotter_with_scene(environment())
    vtkice.pyvista.add_ice(plotter, pv.Sphere(radius=0.8), **CLEAN)
    curves = vtkice.pyvista.tone_mapping(plotter, "filmic", exposure=-1)
    icepass = vtkice.pyvista.ice_pass(plotter)
    after = plotter.screenshot(return_img=True).astype(int)
    assert curves.GetDelegatePass() is icepass and icepass.GetNumberOfIceProps() == 1
    assert np.abs(after - before).max(axis=2).mean() > 5, "the curve changes the picture"
    assert after.max() < before.max(), "the brightest pixels are compressed"
    plotter.enable_ssao()
    plotter.screenshot(return_img=True)
    assert icepass.GetNumberOfIceProps() == 1
    plotter.close()


def test_tone_mapping_with_a_dynamic_cube_map_keeps_translucent_props():
    """A black square at opacity 0.12 over a white plane, ice elsewhere with a dynamic cube map,
    tone mapped: the square is as light in the first screenshot as without the cube map (it
    rendered black: the cube map's faces left blending off)."""
    def square(dynamic):
        plotter = pv.Plotter(off_screen=True, window_size=(200, 200))
        white = pv.Plane(i_size=4, j_size=4)
        black = pv.Plane(center=(0, 0, 0.1), i_size=1, j_size=1)
        plotter.add_mesh(white, color="white", lighting=False)
        plotter.add_mesh(black, color="black", opacity=0.12, lighting=False)
        vtkice.pyvista.add_ice(plotter, pv.Sphere(center=(1.5, 1.5, 0.5), radius=0.3),
                               dynamic_environment=dynamic)
        vtkice.pyvista.tone_mapping(plotter, "filmic")
        plotter.camera_position = [(0, 0, 6), (0, 0, 0), (0, 1, 0)]
        middle = int(plotter.screenshot(return_img=True)[100, 100, 0])
        plotter.close()
        return middle

    without = square(False)
    assert without > 150
    assert abs(square(True) - without) <= 2


def test_tone_mapping_refuses_an_unknown_curve():
    plotter = plotter_with_scene(environment())
    with pytest.raises(ValueError, match="one of none, reinhard, exponential, filmic, aces"):
        vtkice.pyvista.tone_mapping(plotter, "hable")
    plotter.close()
