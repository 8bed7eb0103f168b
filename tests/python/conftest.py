"""Shared fixtures: where the staged workbench and the sources are (set by CTest)."""
import os

import pytest


def sample(items):
    """One in FABGUIDE_SAMPLE of `items`, from the first (CI's Debian 13 run: 12; docs/decisions.md); all by default."""
    return list(items)[::int(os.environ.get("FABGUIDE_SAMPLE") or 1)]


@pytest.fixture(scope="session")
def mod_dir():
    """The workbench folder installed for the tests (Mod/FabGuide in a throw-away HOME)."""
    return os.environ["FABGUIDE_MOD_DIR"]


@pytest.fixture(scope="session")
def source_dir():
    return os.environ["FABGUIDE_SOURCE_DIR"]


@pytest.fixture(scope="session")
def fabguide_cli():
    """The command-line tool: $FABGUIDE_CLI (an installed one), else the build tree's."""
    path = os.environ.get("FABGUIDE_CLI") or os.path.join(os.environ["FABGUIDE_BUILD_DIR"], "fabguide")
    assert os.access(path, os.X_OK), path
    return path


@pytest.fixture(scope="session")
def benchmarks(source_dir):
    """../shared/benchmarks beside the clone; CI always has it, a user's clone may not."""
    path = os.path.join(os.path.dirname(source_dir), "shared", "benchmarks")
    if not os.path.isdir(path):
        if os.environ.get("CI"):
            pytest.fail("CI without ../shared/benchmarks beside the checkout")
        pytest.skip("../shared/benchmarks is not beside this checkout")
    return path
