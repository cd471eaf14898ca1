// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkice._headless: the project's render window back ends (Headless/IceHeadless.h) for Python,
// so that a script on a machine without an X display renders through EGL or OSMesa as
// ice-render does. vtkice.use_backend() is its public face (Wrapping/Python/__init__.py).
// A plain CPython extension: the back end is chosen by name, nothing VTK-typed crosses over.
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "IceHeadless.h"

#include <dlfcn.h>

#include <string>

namespace
{
// OSMesa needs VTK's GL imports bound to libIceHeadless, which a program gets by linking it
// before VTK; Python loaded VTK first, so only a preload does it (EGL needs nothing of this).
std::string PythonHint(const std::string& error)
{
  Dl_info self;
  if (error.find("libIceHeadless") == std::string::npos ||
    !dladdr(reinterpret_cast<void*>(&IceHeadless::InstalledDescription), &self) || !self.dli_fname)
  {
    return error;
  }
  return error + ". From Python use egl, or start python with LD_PRELOAD=" + self.dli_fname;
}

// install(name) -> description; ValueError for an unknown name, RuntimeError when no back end
// of those asked for works.
PyObject* Install(PyObject*, PyObject* args)
{
  const char* name = nullptr;
  if (!PyArg_ParseTuple(args, "s", &name))
  {
    return nullptr;
  }
  IceHeadless::Backend backend = IceHeadless::Backend::Auto;
  if (!IceHeadless::ParseBackend(name, backend))
  {
    PyErr_Format(PyExc_ValueError, "unknown back end '%s' (expected auto, x, egl or osmesa)", name);
    return nullptr;
  }
  const std::string error = IceHeadless::Install(backend);
  if (!error.empty())
  {
    PyErr_SetString(PyExc_RuntimeError, PythonHint(error).c_str());
    return nullptr;
  }
  return PyUnicode_FromString(IceHeadless::InstalledDescription().c_str());
}

PyMethodDef Methods[] = {
  { "install", Install, METH_VARARGS,
    "install(name) -> str: makes the named back end (auto, x, egl, osmesa) that of every "
    "vtkRenderWindow created from now on; returns what it found." },
  { nullptr, nullptr, 0, nullptr }
};

PyModuleDef Module = { PyModuleDef_HEAD_INIT, "_headless",
  "VTK Ice's render window back ends (X, EGL, OSMesa).", -1, Methods, nullptr, nullptr, nullptr,
  nullptr };
}

PyMODINIT_FUNC PyInit__headless()
{
  return PyModule_Create(&Module);
}
