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


def blur(image, sigma):
    """`image` blurred by a Gaussian of `sigma` texels (separable, the border repeating)."""
    radius = max(1, int(3.0 * sigma))
    x = numpy.arange(-radius, radius + 1)
    kernel = numpy.exp(-0.5 * (x / sigma) ** 2)
    kernel /= kernel.sum()
    for axis in (0, 1):
        padded = numpy.pad(image, [(radius, radius) if a == axis else (0, 0) for a in (0, 1)],
                           mode="edge")
        image = numpy.apply_along_axis(lambda row: numpy.convolve(row, kernel, "valid"), axis,
                                       padded)
    return image


def contact_shadow(mesh, floor_y, texels=256):
    """A square of ground around `mesh`'s foot, darkened where the mesh comes near the ground: a
    tight shadow along the line where it touches and a wide faint one (the sky it hides), lighter
    under the foot, where clear ice lets the light through. Black with the shadow as alpha, laid
    just above the ground: a translucent decal."""
    xmin, xmax, _, ymax, zmin, zmax = mesh.bounds
    extent = max(xmax - xmin, ymax - floor_y, zmax - zmin)
    centre = ((xmin + xmax) / 2, (zmin + zmax) / 2)
    half = 0.5 * (max(xmax - xmin, zmax - zmin) + 1.6 * extent)
    texel = 2.0 * half / texels
    # The footprint: per texel, how near the surface above it comes to the ground (its points,
    # dense on these meshes, splatted; the blurs close the gaps between them).
    points = mesh.points
    i = ((points[:, 0] - centre[0] + half) / texel).astype(int)
    j = ((points[:, 2] - centre[1] + half) / texel).astype(int)
    near = numpy.exp(-numpy.maximum(points[:, 1] - floor_y, 0.0) / (0.12 * extent))
    cover = numpy.zeros((texels, texels))
    inside = (i >= 0) & (i < texels) & (j >= 0) & (j < texels)
    numpy.maximum.at(cover, (j[inside], i[inside]), near[inside])
    cover = blur(cover, 0.03 * extent / texel) * 2.0
    tight = numpy.clip(blur(cover, 0.02 * extent / texel), 0.0, 1.0)
    wide = numpy.clip(blur(cover, 0.25 * extent / texel), 0.0, 1.0)
    t = numpy.clip((tight - 0.93) / 0.06, 0.0, 1.0)
    under = t * t * (3.0 - 2.0 * t)
    outline = numpy.minimum(1.0, 4.0 * tight * (1.0 - tight))
    shadow = (0.55 * numpy.maximum(outline, tight) + 0.45 * wide) * (1.0 - 0.6 * under)
    rgba = numpy.zeros((texels, texels, 4), numpy.uint8)
    rgba[..., 3] = (numpy.clip(0.45 * shadow, 0.0, 1.0) * 255.0).astype(numpy.uint8)
    # Rows of a texture run with the plane's second axis (j_size), here z.
    decal = pv.Plane(center=(centre[0], floor_y + 0.002, centre[1]), direction=(0, 1, 0),
                     i_size=2 * half, j_size=2 * half)
    return decal, pv.Texture(rgba)


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
    # Each cube's contact shadow, so that they stand on the ground.
    decals = [contact_shadow(mesh, -1.0) for mesh in (cube, small)]
    for decal, shade in decals:
        plotter.add_mesh(decal, texture=shade, lighting=False)
    if photographed:
        # The panorama is brighter than white: the filmic curve maps it to the screen.
        vtkice.pyvista.tone_mapping(plotter, "filmic")

    plotter.camera_position = [(1.6, 0.3, 4.6), (0.0, -0.45, -0.3), (0.0, 1.0, 0.0)]
    plotter.screenshot(out)
    plotter.close()
    print("wrote", out)


if __name__ == "__main__":
    main()
