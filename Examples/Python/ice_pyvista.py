# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""An ice sphere and an ice block among PyVista's own objects, written to ice_pyvista.png.

    venv/bin/python Examples/Python/ice_pyvista.py        (after pip install ., README.md)

No X server is needed: with VTK >= 9.4 an off-screen plotter renders through EGL.
"""
import pyvista as pv
from vtkmodules.vtkRenderingCore import vtkSkybox

import vtkice
import vtkice.pyvista


def main(out="ice_pyvista.png"):
    plotter = pv.Plotter(off_screen=True, window_size=(800, 600))

    # The world the ice reflects and refracts: a cube map, shown around the scene as a skybox.
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(512)
    environment = pv.Texture()
    sky.ConfigureTexture(environment)
    plotter.renderer.SetEnvironmentTexture(environment)
    skybox = vtkSkybox()
    skybox.SetTexture(environment)
    plotter.add_actor(skybox)

    # PyVista's own objects, seen through the ice (kept in variables: PyVista names an actor
    # after its mesh's address, which a freed temporary mesh hands on to the next one).
    cone = pv.Cone(center=(-1.2, 0.1, -2.0), direction=(0, 1, 0), height=2.0, radius=0.7,
                   resolution=64)
    floor = pv.Plane(center=(0, -1.0, 0), direction=(0, 1, 0), i_size=12, j_size=12)
    plotter.add_mesh(cone, color="darkorange")
    plotter.add_mesh(floor, color="white")

    # The ice: any mesh. It starts from ice-render's natural look (the "ice-cube" preset:
    # Fresnel's equations, faintly blue where thick, the light traced through it so a flat face
    # mirrors the others inside, a barely frosted surface, a cloudy core of small bubbles); the
    # look's parameters by name change it.
    sphere = pv.Sphere(radius=0.8, center=(0.9, 0.0, 0.0), theta_resolution=96,
                       phi_resolution=96)
    # dynamic_environment: the cone and the floor show in the ice, not only the sky. The sphere
    # has a smaller, fainter core than the block.
    vtkice.pyvista.add_ice(plotter, sphere, dynamic_environment=True, MilkyCoreRadius=0.35,
                           Milkiness=0.3)
    source = vtkice.vtkIceBlockSource()
    source.Update()
    block = pv.wrap(source.GetOutput()).scale(0.5).translate((-0.9, -0.4, 0.4))
    vtkice.pyvista.add_ice(plotter, block)

    plotter.camera_position = [(1.5, 1.4, 5.0), (0.0, -0.1, -0.3), (0.0, 1.0, 0.0)]
    plotter.screenshot(out)
    plotter.close()
    print("wrote", out)


if __name__ == "__main__":
    main()
