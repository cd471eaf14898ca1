# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The web viewer (Examples/Web, ./ice.sh web) in a real browser: Debian's Chromium, headless,
driven through Debian's chromedriver (nothing is downloaded). The server renders through EGL
without an X server and listens on 127.0.0.1 only, on a free port. The tests run in order on
one page, as a user would use it.
"""
import io
import os
import pathlib
import socket
import subprocess
import sys
import time
import urllib.request

import numpy as np
import pytest
from PIL import Image

ROOT = pathlib.Path(__file__).resolve().parents[2]
APP = ROOT / "Examples" / "Web" / "ice_web.py"
CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"

webdriver = pytest.importorskip("selenium.webdriver")
if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
    pytest.skip("Debian's chromium and chromium-driver: .ci/install-deps.sh web",
                allow_module_level=True)
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

WAIT = 120  # seconds: llvmpipe renders the first frames slowly on a busy machine


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(condition, what):
    end = time.monotonic() + WAIT
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.25)
    raise AssertionError("timed out waiting for " + what)


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    port = free_port()
    log = open(tmp_path_factory.mktemp("web") / "server.log", "w+")
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    process = subprocess.Popen([sys.executable, str(APP), "--port", str(port)], env=env,
                               stdout=log, stderr=subprocess.STDOUT)
    url = "http://127.0.0.1:%d/" % port

    def up():
        try:
            return urllib.request.urlopen(url, timeout=2).status == 200
        except OSError:
            assert process.poll() is None, "the server stopped"
            return False

    wait_for(up, "the server")
    yield process, url
    process.terminate()
    process.wait(timeout=30)
    log.seek(0)
    print(log.read())


@pytest.fixture(scope="module")
def page(server):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                     "--window-size=1280,900"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(executable_path=CHROMEDRIVER), options=options)
    driver.get(server[1])
    yield driver
    driver.quit()


def view_pixels(driver):
    """The remote view's pixels as the page shows them (RGB, float)."""
    view = wait_for(lambda: driver.find_elements(By.CSS_SELECTOR, ".ice-view"), "the view")[0]
    image = Image.open(io.BytesIO(view.screenshot_as_png)).convert("RGB")
    return np.asarray(image, dtype=float)


def centre(pixels):
    """The middle of the view, where the model is."""
    h, w = pixels.shape[:2]
    return pixels[h // 4: 3 * h // 4, w // 3: 2 * w // 3]


def shown(pixels):
    """Whether an image has arrived: an empty view is one colour."""
    return pixels.std() > 10.0


def changed_from(driver, before):
    """Waits until the view shows a picture other than `before`; returns it."""
    def differs():
        now = view_pixels(driver)
        # `before` has settled (two frames alike to the bit): any difference is a new frame.
        if now.shape == before.shape and np.abs(centre(now) - centre(before)).mean() > 0.02:
            return [now]
        return None
    return wait_for(differs, "the picture to change")[0]


def settled(driver):
    """The picture once it has stopped changing (a frame still on its way would count as the
    next test's change)."""
    previous = [view_pixels(driver)]

    def same():
        time.sleep(1.0)
        now = view_pixels(driver)
        stable = now.shape == previous[0].shape and np.abs(now - previous[0]).max() == 0
        previous[0] = now
        return [now] if stable else None
    return wait_for(same, "the picture to settle")[0]


def test_first_image_arrives(page):
    assert shown(wait_for(lambda: [p for p in [view_pixels(page)] if shown(p)],
                          "the first image")[0])
    # Documentation/web.png: VTKICE_WEB_PICTURE=PATH saves the page once its picture settles.
    picture = os.environ.get("VTKICE_WEB_PICTURE")
    if picture:
        settled(page)
        page.save_screenshot(picture)


def test_ice_differs_from_a_plain_surface(page):
    wait_for(lambda: shown(view_pixels(page)), "the first image")
    ice = settled(page)
    page.find_element(By.CSS_SELECTOR, ".ice-switch input").click()
    # Settled after the change: the view shows each picture at interactive quality first, and
    # the traced look's full-quality frame can arrive after a second.
    changed_from(page, ice)
    plain = settled(page)
    difference = np.abs(centre(ice) - centre(plain)).max(axis=2)
    assert (difference > 40).mean() > 0.05, "the ice's pixels must differ from a plain surface"
    page.find_element(By.CSS_SELECTOR, ".ice-switch input").click()
    changed_from(page, plain)
    settled(page)


def test_slider_changes_the_image(page):
    before = settled(page)
    thumb = page.find_element(By.CSS_SELECTOR, ".ice-setting-cracks .v-slider-thumb")
    cracks = float(thumb.get_attribute("aria-valuenow"))
    thumb.send_keys(Keys.ARROW_RIGHT * 3)  # the slider's keyboard: three steps
    changed_from(page, before)
    assert float(thumb.get_attribute("aria-valuenow")) == cracks + 3


def test_broken_upload_gives_a_message(page, tmp_path):
    broken = tmp_path / "broken.stl"
    broken.write_bytes(b"\0" * 80 + (1000).to_bytes(4, "little") + b"\1" * 60)
    page.find_element(By.CSS_SELECTOR, ".ice-upload input[type=file]").send_keys(str(broken))
    message = wait_for(lambda: [e.text for e in page.find_elements(
        By.CSS_SELECTOR, ".ice-message") if "cannot use" in e.text], "the message")[0]
    assert "broken.stl" in message and "header" in message, message


def test_server_keeps_running_after_the_broken_upload(page, server):
    before = settled(page)
    page.find_element(By.CSS_SELECTOR, ".ice-model").click()
    wait_for(lambda: [e for e in page.find_elements(By.CSS_SELECTOR, ".v-list-item")
                      if e.text.strip() == "block"], "the model list")[0].click()
    changed_from(page, before)
    assert server[0].poll() is None


def test_no_console_error(page):
    errors = [entry for entry in page.get_log("browser") if entry["level"] == "SEVERE"]
    assert errors == []
