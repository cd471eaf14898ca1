# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Two ice cubes among PyVista's own objects, written to ice_pyvista.png.

    venv/bin/python Examples/Python/ice_pyvista.py        (after pip install ., README.md)

They stand on the ground in Debian's forest panorama (blender-data's photographed HDR light,
tone mapped) where the package is installed, else in VTK Ice's procedural sky. No X server is
needed: with VTK >= 9.4 an off-screen plotter renders through EGL.
"""
import os

import numpy
import pyvista as pv
from vtkmodules.vtkRenderingCore import vtkSkybox

import vtkice
import vtkice.pyvista

FOREST = "/usr/share/blender/datafiles/studiolights/world/forest.exr"


def environment():
    """The world the ice reflects and refracts, as a cube-map texture, and whether it holds a
    photographed panorama's HDR light."""
    texture = pv.Texture()
    if os.path.exists(FOREST):
        reader = vtkice.vtkIceEnvironmentReader()
        reader.SetFileName(FOREST)
        reader.ConfigureTexture(texture)
        return texture, True
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(512)
    sky.ConfigureTexture(texture)
    return texture, False


def stone(colour, texels=512, seed=7):
    """A stone ground's texture: `colour` with a mottle, so the ice has something to refract."""
    rng = numpy.random.default_rng(seed)
    mottle = numpy.zeros((texels, texels))
    for size in (4, 16, 64):  # value noise at three scales, bilinearly enlarged, tiling
        coarse = rng.random((size + 1, size + 1))
        coarse[-1, :] = coarse[0, :]
        coarse[:, -1] = coarse[:, 0]
        x = numpy.linspace(0, size, texels)
        i = numpy.minimum(x.astype(int), size - 1)
        f = x - i
        rows = coarse[i] * (1 - f)[:, None] + coarse[i + 1] * f[:, None]
        mottle += (rows[:, i] * (1 - f) + rows[:, i + 1] * f) * 16.0 / size
    mottle = 0.75 + 0.5 * (mottle - mottle.min()) / numpy.ptp(mottle)
    image = mottle[..., None] * numpy.array(colour)
    return pv.Texture((numpy.clip(image, 0.0, 1.0) * 255.0).astype(numpy.uint8))


def main(out="ice_pyvista.png"):
    plotter = pv.Plotter(off_screen=True, window_size=(800, 600))

    # The environment, shown around the scene as a skybox (the HDR panorama's linear light
    # gamma-corrected, as the skybox needs it).
    texture, photographed = environment()
    plotter.renderer.SetEnvironmentTexture(texture)
    skybox = vtkSkybox()
    skybox.SetTexture(texture)
    skybox.SetGammaCorrect(photographed)
    plotter.add_actor(skybox)

    # PyVista's own objects, seen through the ice (kept in variables: PyVista names an actor
    # after its mesh's address, which a freed temporary mesh hands on to the next one). The
    # ground is unlit stone, as ice-render's: the panorama's light is in its colour; it reaches
    # the panorama's horizon.
    cone = pv.Cone(center=(-2.6, 0.0, -2.6), direction=(0, 1, 0), height=2.0, radius=0.6,
                   resolution=64)
    floor = pv.Plane(center=(0, -1.0, 0), direction=(0, 1, 0), i_size=400, j_size=400)
    floor.active_texture_coordinates = floor.active_texture_coordinates * 50.0  # 8 units a tile
    plotter.add_mesh(cone, color="darkorange")
    if photographed:
        plotter.add_mesh(floor, texture=stone((0.33, 0.29, 0.24)), lighting=False)
    else:
        plotter.add_mesh(floor, color="white")

    # The ice: any mesh. It starts from ice-render's natural look (the "ice-cube" preset:
    # Fresnel's equations, faintly blue where thick, the light traced through it so a flat face
    # mirrors the others inside, a barely frosted surface, a cloudy core of small bubbles); the
    # look's parameters by name change it. dynamic_environment: the cone and the ground show in
    # the ice, not only the panorama. The cubes are ice-render's: flat faces, melted round edges;
    # the smaller one turned, with a smaller, fainter core. Both stand in their melt water
    # (WetBase): their bases show the ground instead of mirroring their insides.
    source = vtkice.vtkIceBlockSource()
    source.SetResolution(48)
    source.SetRoundness(0.22)
    source.SetDisplacement(0.03)
    source.SetSeed(3)
    source.Update()
    cube = pv.wrap(source.GetOutput()).scale(0.5).translate((-0.45, -0.5, 0.3))
    vtkice.pyvista.add_ice(plotter, cube, dynamic_environment=True, WetBase=True)
    source.SetSeed(5)
    source.Update()
    small = pv.wrap(source.GetOutput()).scale(0.35).rotate_y(35.0).translate((0.85, -0.65, -0.2))
    vtkice.pyvista.add_ice(plotter, small, MilkyCoreRadius=0.35, Milkiness=0.3, WetBase=True)
    if photographed:
        # The panorama is brighter than white: the filmic curve maps it to the screen.
        vtkice.pyvista.tone_mapping(plotter, "filmic")

    plotter.camera_position = [(1.6, 0.3, 4.6), (0.0, -0.45, -0.3), (0.0, 1.0, 0.0)]
    plotter.screenshot(out)
    plotter.close()
    print("wrote", out)


if __name__ == "__main__":
    main()
