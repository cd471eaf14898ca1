# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Render the ice teapot with two-sided refraction to ice_teapot.png.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 Examples/Python/ice_teapot.py
"""
import vtk
import vtkice


def main(out="ice_teapot.png"):
    sky = vtkice.vtkIceCubeMapSource()
    sky.SetFaceSize(512)
    environment = vtk.vtkTexture()
    sky.ConfigureTexture(environment)

    renderer = vtk.vtkRenderer()
    renderer.SetEnvironmentTexture(environment)
    skybox = vtk.vtkSkybox()
    skybox.SetTexture(environment)
    renderer.AddActor(skybox)

    teapot = vtkice.vtkIceTeapotSource()  # keep a reference: VTK's Python does not
    mapper = vtkice.vtkIceMapper()
    mapper.SetInputConnection(teapot.GetOutputPort())
    ice = vtk.vtkActor()
    ice.SetMapper(mapper)
    renderer.AddActor(ice)
    renderer.SetPass(vtkice.vtkIcePass())

    camera = renderer.GetActiveCamera()
    camera.SetPosition(2.1, 0.9, 3.9)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewAngle(32.0)
    renderer.ResetCameraClippingRange()

    window = vtk.vtkRenderWindow()
    window.SetSize(800, 600)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.Render()

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote", out)


if __name__ == "__main__":
    main()
