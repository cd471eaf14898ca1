# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""pytest's checks here are assert statements, which python -O removes: refuse to run that way
rather than pass without checking anything (the ctest Python tests use ice_test_helpers.check,
which -O keeps)."""
import sys

import pytest


def pytest_configure(config):
    if sys.flags.optimize:
        raise pytest.UsageError(
            "Testing/Wheel checks with assert statements, which python -O removes: run pytest "
            "without -O (PYTHONOPTIMIZE unset)")
