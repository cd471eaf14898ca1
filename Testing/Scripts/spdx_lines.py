# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every source file of the project names its licence in an SPDX line (LICENSE: BSD-3-Clause).

usage: spdx_lines.py SOURCE_DIR
Source files: C++, C and GLSL, Python, shell, CMake, ParaView's XML, the TOML and the scripts of
.ci/; build folders (build*, venvs) are not the project's."""
import os
import sys

LINE = "SPDX-License-Identifier: BSD-3-Clause"
SUFFIXES = (".cxx", ".h", ".c", ".glsl", ".py", ".sh", ".cmake", ".cmake.in", ".xml", ".xml.in",
            ".toml", ".supp")
NAMES = ("CMakeLists.txt", "requirements.txt", ".gitignore")


def is_source(folder, name):
    return (name.endswith(SUFFIXES) or name in NAMES
            or os.path.basename(folder) == ".ci")


def main(top):
    missing, checked = [], 0
    for folder, subfolders, names in os.walk(top):
        subfolders[:] = [s for s in subfolders
                         if not s.startswith(("build", "venv", "dist", ".git", ".gpu", ".gl"))]
        for name in names:
            if not is_source(folder, name):
                continue
            path = os.path.join(folder, name)
            checked += 1
            with open(path, encoding="utf-8", errors="replace") as f:
                head = "".join(f.readline() for _ in range(4))
            if LINE not in head:
                missing.append(os.path.relpath(path, top))
    for path in missing:
        print(f"FAIL {path}: no '{LINE}' in its first lines")
    print(f"{checked} source files, {len(missing)} without the SPDX line")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
