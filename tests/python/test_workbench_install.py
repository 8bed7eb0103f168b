"""The installed workbench folder is complete and the core module loads from it."""
import glob
import os
import subprocess

import FreeCAD
import Part
import pytest
from freecad.fabguide.core import fabguide_core
from freecad.fabguide.gui import about, resources


def test_install_holds_everything_freecad_loads(mod_dir):
    for relative in ["package.xml", "LICENSE", "Resources/icons/FabGuide.svg", "freecad/fabguide/__init__.py",
                     "freecad/fabguide/init_gui.py", "freecad/fabguide/gui/workbench.py",
                     "freecad/fabguide/gui/commands.py"]:
        assert os.path.isfile(os.path.join(mod_dir, relative)), relative
    assert installed_core(mod_dir)


def installed_core(mod_dir):
    """The core the installation holds: in the workbench's package (`make install`), else for the system Python
    (the Debian package)."""
    return (glob.glob(os.path.join(mod_dir, "freecad", "fabguide", "fabguide_core.*.so")) or
            glob.glob("/usr/lib/python3/dist-packages/fabguide_core.*.so"))


def test_core_module_is_the_installed_one(mod_dir):
    assert os.path.realpath(fabguide_core.__file__) == os.path.realpath(installed_core(mod_dir)[0])


def test_core_reports_its_version_and_libraries():
    assert fabguide_core.__version__.count(".") == 2
    libraries = dict(fabguide_core.dependency_versions())
    assert set(libraries) == {"Eigen", "OpenCASCADE", "Clipper", "nlohmann-json"}
    assert libraries["OpenCASCADE"].startswith("7.")


def test_freecad_and_part_work_beside_the_core():
    box = Part.makeBox(10, 20, 30)
    assert abs(box.Volume - 6000) < 1e-9
    assert FreeCAD.Version()[0] in ("0", "1")


def test_freecad_loads_the_tested_workbench(mod_dir):
    """The user's Mod/FabGuide, else the system's (the Debian package's): FreeCAD keys Mod folders by name."""
    user = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "FabGuide")
    loaded = user if os.path.isdir(user) else os.path.join(FreeCAD.getResourceDir(), "Mod", "FabGuide")
    assert os.path.realpath(loaded) == os.path.realpath(mod_dir)


def test_freecadcmd_imports_the_core_from_the_user_mod_dir(mod_dir):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # only FreeCAD's own Mod search
    run = subprocess.run(["freecadcmd", "-c", "from freecad.fabguide.core import fabguide_core; print('core', "
                          "fabguide_core.__version__, fabguide_core.__file__)"], env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    line = [l for l in run.stdout.splitlines() if l.startswith("core ")][-1]
    _, version, path = line.split(" ", 2)
    assert version == fabguide_core.__version__
    assert os.path.realpath(path) == os.path.realpath(installed_core(mod_dir)[0])


def test_about_report_names_every_version():
    lines = about.report().splitlines()
    assert lines[0] == "FabGuide " + fabguide_core.__version__
    assert lines[1].startswith("FreeCAD 0.") or lines[1].startswith("FreeCAD 1.")
    assert len(lines) == 2 + len(fabguide_core.dependency_versions())


def test_workbench_icon_is_installed():
    assert os.path.isfile(resources.icon("FabGuide.svg"))


def test_core_solves_a_works_like_model_from_python(source_dir):
    import json

    model = json.load(open(os.path.join(source_dir, "examples", "box-with-lid.workslike.json")))
    solved = fabguide_core.solve(model)
    assert solved["report"]["solved"] and solved["report"]["violation"] < 1e-6
    model["locks"].append("lid.top")
    model["relationships"].append({"type": "flush", "name": "lid top level with body top",
                                   "faces": ["lid.top", "body.top"]})
    report = fabguide_core.solve(model)["report"]
    assert not report["solved"] and "lid top level with body top" in report["conflict"]
    with pytest.raises(fabguide_core.FormatError) as raised:  # a ValueError carrying the field it names
        fabguide_core.solve({"parts": [{"name": "a", "cuboids": []}]})
    assert isinstance(raised.value, ValueError) and raised.value.field == "parts[0].cuboids"
    assert "a part needs at least one cuboid" in str(raised.value)
