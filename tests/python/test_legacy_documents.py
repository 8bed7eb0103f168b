"""Documents saved by an earlier FabGuide open, recompute to what they held and are saved in today's form
(docs/decisions.md, "Documents carry their version"). tests/data/legacy/README.md says how each file was made."""
import glob
import json
import os
import re
import zipfile

import FreeCAD
import pytest
from freecad import fabguide
from freecad.fabguide.function import configuration, mechanism, printable, relationships
from freecad.fabguide.material import design

FREECAD = tuple(int(v) for v in FreeCAD.Version()[:2])


def legacy(source_dir, kind):
    """The saved files of `kind` this FreeCAD can open: those written by this FreeCAD version or an older one."""
    files = sorted(glob.glob(os.path.join(source_dir, "tests", "data", "legacy", kind + "-*.FCStd")))
    readable = [f for f in files if written_by(f) <= FREECAD]
    assert readable, "no legacy {} document for FreeCAD {}".format(kind, FREECAD)
    return readable


def written_by(path):
    """The FreeCAD version (major, minor) a file's name says wrote it: function-0.1.0-fc020 is 0.20, fc10 is 1.0."""
    digits = re.search(r"-fc(\d+)\.FCStd$", path).group(1)
    return int(digits[0]), int(digits[1:])


def modules_named(path):
    with zipfile.ZipFile(path) as saved:
        return set(re.findall(r'module="([^"]+)"', saved.read("Document.xml").decode()))


def reopened(path, tmp_path):
    """Opened, recomputed, saved and opened again: what the user has after one session with the new version."""
    doc = FreeCAD.openDocument(path)
    for obj in doc.Objects:
        obj.touch()  # everything computed again by today's FabGuide, not only what the file held
    doc.recompute()
    copy = str(tmp_path / os.path.basename(path))
    doc.saveAs(copy)
    FreeCAD.closeDocument(doc.Name)
    assert modules_named(copy) and all(m.startswith("freecad.fabguide.") for m in modules_named(copy))
    return FreeCAD.openDocument(copy)


def fabguide_objects(doc):
    return [obj for obj in doc.Objects if type(getattr(obj, "Proxy", None)).__module__.startswith("freecad.fabguide")]


@pytest.mark.parametrize("kind", ["function", "material"])
def test_files_were_written_with_the_old_module_names(source_dir, kind):
    for path in legacy(source_dir, kind):
        assert modules_named(path) and all(m.startswith("fabguide.") for m in modules_named(path)), path


def test_works_like_document_opens_solves_and_prints(source_dir, tmp_path):
    for path in legacy(source_dir, "function"):
        doc = reopened(path, tmp_path)
        objects = fabguide_objects(doc)
        assert len(objects) == len([o for o in doc.Objects if hasattr(o, "Proxy") and o.Proxy is not None])
        assert all(obj.FabGuideVersion == fabguide.__version__ for obj in objects)
        mech = next(obj for obj in objects if mechanism.is_mechanism(obj))
        assert mech.Status == "Solved", mech.Status
        rels = mechanism.members(mech, relationships.is_relationship)
        assert rels and not [rel.Label for rel in rels if "Conflict" in rel.Status or not rel.Status]
        made = next(obj for obj in objects if printable.is_printable(obj))
        assert "Invalid" not in made.State and len(made.Group) > 1 and made.MinimumClearance.Value > 0
        # migration 4: the lists of angles and offsets became a property per joint, in units, the poses kept
        posed = [obj for obj in objects if configuration.is_configuration(obj)]
        with open(os.path.join(source_dir, "examples", "box-with-lid.workslike.json")) as example:
            assert [configuration.as_dict(c) for c in posed] == json.load(example)["configurations"]
        assert not {"Angles", "Offsets"} & set(posed[0].PropertiesList)
        assert posed[0].getTypeIdOfProperty(posed[0].Joints[0].Name + "Angle") == "App::PropertyAngle"
        FreeCAD.closeDocument(doc.Name)


def test_flatpack_design_opens_and_lays_out(source_dir, tmp_path):
    for path in legacy(source_dir, "material"):
        doc = reopened(path, tmp_path)
        table = next(obj for obj in doc.Objects if design.is_design(obj))
        assert table.FabGuideVersion == fabguide.__version__
        assert table.Status.startswith("Usage") and table.Usage > 0.5, table.Status
        assert [c for c in table.Group if design.is_constraint(c)]
        FreeCAD.closeDocument(doc.Name)
