"""package.xml passes FreeCAD's own metadata reader with the fields the Addon Manager needs."""
import datetime
import os
import xml.etree.ElementTree as ET

import FreeCAD
from freecad.fabguide.core import fabguide_core
import pytest

NS = {"p": "https://wiki.freecad.org/Package_Metadata"}


@pytest.fixture(scope="module")
def path(source_dir):
    return os.path.join(source_dir, "package.xml")


@pytest.fixture(scope="module")
def metadata(path):
    return FreeCAD.Metadata(path)


def test_identity(metadata):
    assert metadata.Name == "FabGuide"
    assert metadata.Version == fabguide_core.__version__, "package.xml and CMakeLists.txt versions differ"
    assert len(metadata.Description) > 40


def test_date_is_iso(path):
    date = ET.parse(path).getroot().find("p:date", NS).text
    datetime.date.fromisoformat(date)


def test_maintainer_has_email(metadata):
    assert metadata.Maintainer and "@" in metadata.Maintainer[0]["email"]


def test_license_is_gpl3_or_later_with_file(metadata, source_dir):
    assert metadata.License == [{"name": "GPL-3.0-or-later", "file": "LICENSE"}]
    with open(os.path.join(source_dir, "LICENSE")) as text:
        assert "GNU GENERAL PUBLIC LICENSE" in text.read(200)


def test_repository_url_names_its_branch(metadata):
    repository = [url for url in metadata.Urls if url["type"] == "repository"]
    assert repository and repository[0]["branch"] == "main"
    assert repository[0]["location"].startswith("https://")


def test_icon_exists(metadata, source_dir):
    assert os.path.isfile(os.path.join(source_dir, metadata.Icon))


def test_supported_freecad(metadata):
    assert metadata.FreeCADMin == "0.20.0"
    assert metadata.supportsCurrentFreeCAD()


def test_urls_the_addon_manager_shows(metadata):
    types = {url["type"] for url in metadata.Urls}
    assert {"repository", "bugtracker", "readme", "documentation"} <= types


def test_python_minimum_is_debian_12s(metadata, path):
    assert ET.parse(path).getroot().find("p:pythonmin", NS).text == "3.11"


def test_workbench_content(metadata, path, source_dir):
    workbench = metadata.Content["workbench"][0]
    assert workbench.Classname == "FabGuideWorkbench"
    assert workbench.Subdirectory == "./"  # the clone's root goes on sys.path: its freecad/ namespace package
    assert os.path.isfile(os.path.join(source_dir, "freecad", "fabguide", "init_gui.py"))
    assert not os.path.exists(os.path.join(source_dir, "freecad", "__init__.py"))  # FreeCAD's own, never ours
    depends = ET.parse(path).getroot().findall("p:content/p:workbench/p:depend", NS)
    assert depends and all(d.get("type") == "internal" and d.text == d.text.lower() for d in depends)
    assert "part" in [d.text for d in depends]
    assert workbench.Tag and workbench.Icon


def test_workbench_class_is_the_one_init_gui_registers(metadata, source_dir):
    with open(os.path.join(source_dir, "freecad", "fabguide", "init_gui.py")) as init_gui:
        assert "addWorkbench({}())".format(metadata.Content["workbench"][0].Classname) in init_gui.read()
