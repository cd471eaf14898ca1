# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""VTK Ice in the browser: a trame app that renders the ice on the server (through EGL, no X
server) and streams its images to the page (trame-vtk's remote view).

    ./ice.sh web [--port N]          (serves http://127.0.0.1:N/, default port 8080)

The page: a model (teapot, block, sphere or an uploaded STL/PLY/OBJ file), the presets, the ice or
the same model as a plain surface, a control for every setting of the look (vtkice.vtkIceLook:
the table of ice-render's options, with its ranges, choices and help), a screenshot button.
"""
import argparse
import math
import os
import tempfile

import vtkice

vtkice.use_backend("egl")  # before the first render window: no X server needed

from trame.app import get_server  # noqa: E402
from trame.app.file_upload import ClientFile  # noqa: E402
from trame.ui.vuetify3 import SinglePageWithDrawerLayout  # noqa: E402
from trame.widgets import vtk as vtk_widgets, vuetify3 as v3  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderWindowInteractor  # noqa: E402

import ice_web_scene  # noqa: E402

UPLOADED = "uploaded file"
# Integer settings wider than this (the seeds) get a text field: a slider could not pick one value.
SLIDER_STEPS = 1000


def state_key(name):
    return "look_" + name.replace("-", "_")


def state_value(setting, text):
    """A setting's text value (vtkIceLook) as the page's control holds it."""
    kind = setting["kind"]
    if kind == "switch":
        return text == "on"
    if kind == "number" and not math.isinf(setting["max"]):
        return float(text)
    if kind == "integer":
        return int(float(text))
    return text


def setting_text(setting, value):
    """The page's value as vtkIceLook takes it."""
    kind = setting["kind"]
    if kind == "switch":
        return "on" if value else "off"
    if kind == "integer" and isinstance(value, (int, float)):
        return str(int(value))
    return str(value)  # typed text: vtkIceLook refuses what is not a value


class IceWebApp:
    def __init__(self, server=None):
        self.server = server or get_server(client_type="vue3")
        self.scene = ice_web_scene.IceScene()
        self.interactor = vtkRenderWindowInteractor()
        self.interactor.SetRenderWindow(self.scene.window)
        self.interactor.GetInteractorStyle().SetCurrentStyleToTrackballCamera()
        self.settings = ice_web_scene.look_settings()
        self.uploaded = None
        state = self.server.state
        state.update({"model": "teapot", "models": list(ice_web_scene.MODELS),
                      "preset": vtkice.DEFAULT_PRESET, "presets": ice_web_scene.presets(),
                      "ice": True,
                      "message": "", "message_type": "info", "upload": None})
        for setting in self.settings:
            state[state_key(setting["name"])] = state_value(
                setting, self.scene.value(setting["name"]))
            state.change(state_key(setting["name"]))(self._on_setting(setting))
        state.change("model")(self.on_model)
        state.change("preset")(self.on_preset)
        state.change("ice")(self.on_ice)
        state.change("upload")(self.on_upload)
        self.server.controller.trigger("screenshot")(self.screenshot)
        self.server.controller.on_server_bind.add(self._answer_launcher)
        self._layout()

    @staticmethod
    def _answer_launcher(wslink_server):
        """trame's page first asks a session launcher at ./paraview/ where its websocket is (a POST
        the plain server refuses, an error in the browser's console): this server is its own."""
        from aiohttp import web

        async def launcher(_request):
            return web.json_response({"sessionURL": "ws://USE_HOST/ws"})

        wslink_server.app.router.add_post("/paraview/", launcher)

    # --- what the page changes -------------------------------------------------------------
    def _on_setting(self, setting):
        name, key = setting["name"], state_key(setting["name"])

        def changed(**kwargs):
            problem = self.scene.apply(name, setting_text(setting, kwargs[key]))
            if problem:
                self.say(problem, "error")
            # A refused value goes back; a synonym (ior, eta) follows the one that changed.
            self.sync_settings()
            self.update()

        return changed

    def on_model(self, model, **_):
        if model == UPLOADED:
            polydata = self.uploaded
        elif model in ice_web_scene.MODELS:
            polydata = ice_web_scene.builtin_model(model)
        else:
            return
        self.scene.set_model(polydata)
        self.update()

    def on_preset(self, preset, **_):
        # The page's first state names the preset the scene opened on: not applied twice.
        if not preset or preset == self.scene.preset:
            return
        problem = self.scene.apply_preset(preset)
        self.say(problem or "preset %s" % preset, "error" if problem else "info")
        self.sync_settings()
        self.update()

    def on_ice(self, ice, **_):
        self.scene.set_ice(bool(ice))
        self.update()

    def on_upload(self, upload, **_):
        if not upload:
            return
        upload = upload[0] if isinstance(upload, list) else upload
        file = ClientFile(upload)
        name = os.path.basename(file.name or "model")
        with tempfile.TemporaryDirectory(prefix="ice-web-upload-") as folder:
            # The user's name only for its extension: the path is ours.
            path = os.path.join(folder, "upload" + os.path.splitext(name)[1].lower())
            with open(path, "wb") as out:
                out.write(file.content or b"")
            polydata, problem = ice_web_scene.read_model_file(path)
        shown = vtkice.vtkIceModelFile.Printable(name, 80)
        if polydata is None:
            self.say("cannot use %s: %s" % (shown, problem.replace(path, shown)), "error")
            return
        self.uploaded = polydata
        models = list(ice_web_scene.MODELS) + [UPLOADED]
        self.server.state.update({"models": models, "model": UPLOADED})
        self.say("%s: %d triangles" % (shown, polydata.GetNumberOfPolys()), "success")
        self.on_model(UPLOADED)

    def screenshot(self):
        return self.server.protocol.addAttachment(self.scene.screenshot_png())

    # --- helpers ---------------------------------------------------------------------------
    def say(self, message, kind="info"):
        self.server.state.update({"message": message, "message_type": kind})

    def sync_settings(self):
        """The page's controls from the scene, without applying them again."""
        state = self.server.state
        keys = [state_key(setting["name"]) for setting in self.settings]
        with state.suppress_change_listeners(*keys):
            for key, setting in zip(keys, self.settings):
                state[key] = state_value(setting, self.scene.value(setting["name"]))
            state.flush()

    def update(self):
        self.server.controller.view_update()

    # --- the page --------------------------------------------------------------------------
    def _control(self, setting):
        key, name, kind = state_key(setting["name"]), setting["name"], setting["kind"]
        common = dict(label=name, hide_details=True, density="compact",
                      classes="ice-setting ice-setting-" + name, title=setting["help"])
        if kind == "switch":
            v3.VSwitch(v_model=(key,), color="primary", **common)
        elif kind == "choice":
            v3.VSelect(v_model=(key,), items=(key + "_choices", setting["choices"]), **common)
        elif kind == "vector" or (kind == "integer" and
                                  setting["max"] - setting["min"] > SLIDER_STEPS) or \
                math.isinf(setting["max"]):
            # An unbounded number (attenuation-distance up to inf) is typed: "inf" or a value.
            v3.VTextField(v_model_lazy=(key,), **common)
        else:
            step = 1 if kind == "integer" else (setting["max"] - setting["min"]) / 200
            v3.VSlider(v_model=(key,), min=setting["min"], max=setting["max"], step=step,
                       thumb_label=True, **common)

    def _layout(self):
        with SinglePageWithDrawerLayout(self.server) as layout:
            layout.title.set_text("VTK Ice")
            with layout.toolbar:
                v3.VSpacer()
                v3.VSwitch(v_model=("ice",), label="ice", color="primary", hide_details=True,
                           density="compact",
                           classes="ice-switch flex-grow-0 mx-2",
                           title="off: the same model as a plain surface")
                v3.VBtn("screenshot", classes="ice-screenshot", prepend_icon="mdi-camera",
                        click="utils.download('ice.png', trigger('screenshot'), 'image/png')")
            with layout.drawer as drawer:
                drawer.width = 340
                with v3.VContainer(classes="pa-2"):
                    v3.VSelect(v_model=("model",), items=("models",), label="model",
                               hide_details=True, density="compact", classes="ice-model")
                    v3.VFileInput(v_model=("upload",), label="upload STL, PLY or OBJ",
                                  accept=".stl,.ply,.obj", hide_details=True, density="compact",
                                  classes="ice-upload mt-2")
                    v3.VSelect(v_model=("preset",), items=("presets",), label="preset",
                               hide_details=True, density="compact", classes="ice-preset mt-2")
                    v3.VAlert(v_if=("message",), text=("message",), type=("message_type",),
                              density="compact", classes="ice-message mt-2")
                    for setting in self.settings:
                        self._control(setting)
            with layout.content:
                with v3.VContainer(fluid=True, classes="pa-0 fill-height"):
                    view = vtk_widgets.VtkRemoteView(self.scene.window, interactive_ratio=1,
                                                     interactive_quality=80,
                                                     classes="ice-view")
                    self.server.controller.view_update = view.update


def main():
    parser = argparse.ArgumentParser(description="VTK Ice in the browser (trame)")
    parser.add_argument("--port", type=int, default=8080, help="port on 127.0.0.1 (0: any)")
    args, _ = parser.parse_known_args()
    app = IceWebApp()
    # 127.0.0.1 only: the viewer reads files users upload.
    app.server.start(host="127.0.0.1", port=args.port, open_browser=False)


if __name__ == "__main__":
    main()
