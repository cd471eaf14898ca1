# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The web viewer's scene: a model as ice in a small landscape under vtkIceCubeMapSource's sky,
rendered off screen on the server (EGL without an X server), and the look's settings applied by
name through vtkice.vtkIceLook, the table ice-render's options and presets use.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkSkybox, vtkTexture,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401  (the remote view's trackball)
import vtkmodules.vtkRenderingFreeType  # noqa: F401
from vtkmodules.vtkRenderingOpenGL2 import vtkToneMappingPass

import vtkice

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = ("teapot", "block", "sphere")
UPLOAD_TYPES = (".stl", ".ply", ".obj")
Look = vtkice.vtkIceLook


def look_settings():
    """The look's settings as the table lists them, without the camera's (the view moves it) and
    without synonyms (eta: ior in other units)."""
    settings = []
    for i in range(Look.GetNumberOfSettings()):
        if Look.IsCameraSetting(i) or Look.GetSynonymOf(i):
            continue
        settings.append({
            "name": Look.GetName(i), "kind": Look.GetKind(i), "help": Look.GetHelp(i),
            "min": Look.GetMinimum(i), "max": Look.GetMaximum(i), "default": Look.GetDefault(i),
            "choices": [Look.GetChoice(i, j) for j in range(Look.GetNumberOfChoices(i))],
        })
    return settings


def presets():
    """The shipped looks by name (those of ice-render, in the vtkice package)."""
    return vtkice.presets()


def _mapper(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    return mapper


def _normalized(polydata):
    """Centred at the origin, largest extent 2 (as ice-render frames a model); None if flat."""
    bounds = polydata.GetBounds()
    extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    if not extent > 1e-12:
        return None
    transform = vtkTransform()
    transform.Scale(2.0 / extent, 2.0 / extent, 2.0 / extent)
    transform.Translate(-(bounds[0] + bounds[1]) / 2, -(bounds[2] + bounds[3]) / 2,
                        -(bounds[4] + bounds[5]) / 2)
    moved = vtkTransformFilter()
    moved.SetTransform(transform)
    moved.SetInputData(polydata)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(moved.GetOutputPort())
    normals.Update()
    return normals.GetOutput()


def builtin_model(name):
    source = {"teapot": vtkice.vtkIceTeapotSource, "block": vtkice.vtkIceBlockSource}.get(name)
    if source is None:
        source = vtkSphereSource  # about 960 triangles, the paper's sphere
    source = source()
    if name == "sphere":
        source.SetThetaResolution(32)
        source.SetPhiResolution(17)
    source.Update()
    return _normalized(source.GetOutput())


def read_model_file(path):
    """(polydata, "") or (None, the problem) for a model file, checked as ice-render checks it:
    the file's structure first (vtkIceModelFile), then the reader in a child process (a reader
    that crashes on a broken file takes only the child), then vtkIceMapper.CheckInput."""
    if os.path.splitext(path)[1].lower() not in UPLOAD_TYPES:
        return None, "not an STL, PLY or OBJ file"
    problem = vtkice.vtkIceModelFile.CheckFile(path)
    if problem:
        return None, problem
    with tempfile.TemporaryDirectory(prefix="ice-web-") as folder:
        out = os.path.join(folder, "model.vtp")
        child = subprocess.run([sys.executable, os.path.join(HERE, "ice_web_read.py"), path, out],
                               capture_output=True, text=True, timeout=120)
        if child.returncode != 0:
            lines = child.stdout.strip().splitlines()
            return None, (lines[-1] if child.returncode == 1 and lines else
                          "the reader crashed on it (exit status %d)" % child.returncode)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        polydata = reader.GetOutput()
    problem = vtkice.vtkIceMapper.CheckInput(polydata)
    if problem:
        return None, "cannot use it: " + problem
    normalized = _normalized(polydata)
    return (normalized, "") if normalized else (None, "its extent is too small to scale")


class IceScene:
    """A render window with the ice, its plain-surface twin and the landscape."""

    def __init__(self, size=(800, 600), preset=vtkice.DEFAULT_PRESET):
        """The scene with the look `preset` (ice-render's default, natural ice; None: the
        library's defaults)."""
        self.preset = None  # the shipped look the scene is in, as apply_preset left it
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(True)
        self.window.SetSize(*size)
        self.renderer = vtkRenderer()
        self.window.AddRenderer(self.renderer)
        self.pass_ = vtkice.vtkIcePass()
        self.cube_maps = vtkice.vtkIceCubeMapPass()
        self.pass_.SetCubeMapPass(self.cube_maps)  # the dynamic cube map, on as in ice-render
        self.renderer.SetPass(self.pass_)
        # Around the ice pass where the look asks for a tone curve (tone-mapping, exposure).
        self.tone_mapping = vtkToneMappingPass()
        Look.ResetToneMapping(self.tone_mapping)
        self.tone_mapping.SetDelegatePass(self.pass_)
        self._add_sky()
        self._add_landscape()
        self.mapper = vtkice.vtkIceMapper()
        self.plain_mapper = vtkPolyDataMapper()  # the same model as a plain surface
        self.actor = vtkActor()
        self.actor.SetMapper(self.mapper)
        self.renderer.AddActor(self.actor)
        self.set_model(builtin_model("teapot"))
        camera = self.renderer.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(2.1, 0.9, 3.9)  # ice-render's view of its default scene
        camera.SetViewAngle(32)
        self.renderer.ResetCameraClippingRange()
        if preset is not None:
            problem = self.apply_preset(preset)
            if problem:
                raise ValueError(problem)

    def _add_sky(self):
        self.sky = vtkice.vtkIceCubeMapSource()
        self.sky.SetFaceSize(256)
        self.environment = vtkTexture()
        self.sky.ConfigureTexture(self.environment)
        self.renderer.SetEnvironmentTexture(self.environment)
        skybox = vtkSkybox()
        skybox.SetTexture(self.environment)
        self.renderer.AddActor(skybox)

    def _add(self, source, position, color):
        actor = vtkActor()
        actor.SetMapper(_mapper(source))
        actor.SetPosition(*position)
        actor.GetProperty().SetColor(*color)
        actor.GetProperty().SetAmbient(0.35)
        self.renderer.AddActor(actor)
        return actor

    def _add_landscape(self):
        """What the dynamic cube map shows in the ice: checkered snow, rocks, pine trees, a sun."""
        squares = (np.add.outer(np.arange(256) * 48 // 256, np.arange(256) * 48 // 256) % 2)
        rgb = np.where(squares[..., None] == 0, [225, 230, 235], [80, 120, 75]).astype(np.uint8)
        image = vtkImageData()
        image.SetDimensions(256, 256, 1)
        image.GetPointData().SetScalars(numpy_to_vtk(rgb.reshape(-1, 3), deep=True))
        texture = vtkTexture()
        texture.SetInputData(image)
        texture.InterpolateOn()
        texture.MipmapOn()
        plane = vtkPlaneSource()
        plane.SetOrigin(-12, -1, 12)
        plane.SetPoint1(12, -1, 12)
        plane.SetPoint2(-12, -1, -12)
        self._add(plane, (0, 0, 0), (1, 1, 1)).SetTexture(texture)
        for x, z, size, seed in ((-3.5, -2, 1.4, 3), (3.8, -3.5, 2.2, 5), (-1.5, 4.5, 1.0, 8)):
            rock = vtkice.vtkIceBlockSource()
            rock.SetSeed(seed)
            rock.SetSize(size)
            rock.SetRoundness(0.6)
            rock.SetResolution(10)
            self._add(rock, (x, -1 + 0.3 * size, z), (0.55, 0.5, 0.45))
        for x, z, height in ((-2, -5.5, 3.0), (1, -7, 3.6), (6.5, -1, 2.6), (2.5, 5.5, 3.2)):
            crown = vtkConeSource()
            crown.SetRadius(0.35 * height)
            crown.SetHeight(0.8 * height)
            crown.SetDirection(0, 1, 0)
            crown.SetResolution(24)
            self._add(crown, (x, -1 + 0.6 * height, z), (0.12, 0.38, 0.18))
        sun = vtkLight()
        sun.SetLightTypeToSceneLight()
        sun.SetPosition(45, 55, -70)
        sun.SetFocalPoint(0, 0, 0)
        sun.SetIntensity(0.9)
        self.renderer.AddLight(sun)
        fill = vtkLight()  # soft light from the camera's side
        fill.SetLightTypeToHeadlight()
        fill.SetIntensity(0.35)
        self.renderer.AddLight(fill)

    def set_model(self, polydata):
        self.mapper.SetInputData(polydata)
        self.plain_mapper.SetInputData(polydata)

    def set_ice(self, on):
        """The model as ice, or as a plain surface (to see what the ice does)."""
        self.actor.SetMapper(self.mapper if on else self.plain_mapper)

    def apply(self, name, value):
        """Sets a look setting; returns "" or why the value is refused."""
        problem = Look.Apply(self.mapper, self.pass_, self.cube_maps,
                             self.renderer.GetActiveCamera(), self.tone_mapping, name, str(value))
        self._place_tone_mapping()
        self.preset = None  # the look is no longer exactly a preset's
        return problem

    def _place_tone_mapping(self):
        wanted = self.tone_mapping if Look.AsksForToneMapping(self.tone_mapping) else self.pass_
        if self.renderer.GetPass() is not wanted:
            self.renderer.SetPass(wanted)

    def value(self, name):
        return Look.GetValue(self.mapper, self.pass_, self.cube_maps,
                             self.renderer.GetActiveCamera(), self.tone_mapping, name)

    def apply_preset(self, name):
        """The look back to the defaults, then the preset (its camera settings move the view)."""
        for setting in look_settings():
            self.apply(setting["name"], setting["default"])
        problem = Look.ApplyPreset(self.mapper, self.pass_, self.cube_maps,
                                   self.renderer.GetActiveCamera(), self.tone_mapping,
                                   vtkice.preset_path(name))
        self._place_tone_mapping()
        self.preset = None if problem else name
        return problem

    def screenshot_png(self):
        """The current picture as PNG bytes."""
        self.window.Render()
        capture = vtkWindowToImageFilter()
        capture.SetInput(self.window)
        capture.ReadFrontBufferOff()
        writer = vtkPNGWriter()
        writer.WriteToMemoryOn()
        writer.SetInputConnection(capture.GetOutputPort())
        writer.Write()
        return bytes(memoryview(writer.GetResult()))
