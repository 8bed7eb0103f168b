"""Shared fixtures: where the staged workbench and the sources are (set by CTest)."""
import os

import pytest


@pytest.fixture(scope="session")
def mod_dir():
    """The workbench folder installed for the tests (Mod/FabGuide in a throw-away HOME)."""
    return os.environ["FABGUIDE_MOD_DIR"]


@pytest.fixture(scope="session")
def source_dir():
    return os.environ["FABGUIDE_SOURCE_DIR"]
