# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""The vtkice package installed by `pip install .` beside the vtk wheel (./ice.sh wheel runs these
under pytest in build-wheel/venv, without an X server: VTK >= 9.4 renders through EGL then)."""
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PYTHON_TESTS = sorted((ROOT / "Testing" / "Python").glob("TestIce*Python.py"))


def loaded_libraries():
    with open("/proc/self/maps") as maps:
        return {line.split()[-1] for line in maps if ".so" in line}


def test_imports_the_installed_package_beside_the_wheel():
    import vtkmodules
    import vtkice

    site = pathlib.Path(vtkmodules.__file__).resolve().parent.parent
    assert pathlib.Path(vtkice.__file__).resolve().parent == site / "vtkice"
    assert vtkice._BUILT_AGAINST == vtkmodules.vtkCommonCore.vtkVersion.GetVTKVersion()


def test_loads_one_libvtk_the_wheels():
    import vtkmodules
    import vtkice

    vtkice.vtkIceMapper()
    wheel = pathlib.Path(vtkmodules.__file__).resolve().parent
    cores = {pathlib.Path(p).resolve() for p in loaded_libraries() if "libvtkCommonCore" in p}
    assert cores == {wheel / "libvtkCommonCore.so"}
    assert not any("/usr/lib" in p and "libvtk" in p for p in loaded_libraries())


def test_mapper_is_a_vtk_opengl_mapper():
    import vtkice

    mapper = vtkice.vtkIceMapper()
    assert mapper.IsA("vtkOpenGLPolyDataMapper")
    assert vtkice.vtkIcePass().IsA("vtkOpenGLRenderPass")


@pytest.mark.parametrize("script", PYTHON_TESTS, ids=[p.stem for p in PYTHON_TESTS])
def test_python_suite_on_the_installed_package(script):
    """The project's Python tests, importing the pip-installed vtkice (not the build tree)."""
    env = dict(os.environ, PYTHONPATH=str(script.parent))
    env.pop("DISPLAY", None)
    run = subprocess.run([sys.executable, str(script)], env=env, capture_output=True, text=True,
                         timeout=600)
    output = run.stdout + run.stderr
    assert run.returncode == 0, output
    assert "Traceback" not in output and "ERROR:" not in output, output


@pytest.mark.parametrize("example", ["ice_teapot", "ice_pyvista"])
def test_python_example_writes_its_picture(tmp_path, example):
    run = subprocess.run([sys.executable, str(ROOT / "Examples" / "Python" / (example + ".py"))],
                         cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "Traceback" not in run.stderr and "ERROR:" not in run.stderr, run.stderr
    assert (tmp_path / (example + ".png")).stat().st_size > 10000
