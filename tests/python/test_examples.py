"""The bundled FreeCAD examples open, recompute without errors and lay out the same parts as their
*.pack.json twins used by the command line."""
import json
import os

import FreeCAD
import pytest

from freecad.fabguide import properties
from freecad.fabguide.material import layout


@pytest.mark.parametrize("name", ["bookshelf", "coffee-table"])
def test_example_document_recomputes_to_a_layout(source_dir, name):
    doc = FreeCAD.openDocument(os.path.join(source_dir, "examples", name + ".FCStd"))
    try:
        for obj in doc.Objects:
            obj.touch()
        doc.recompute()
        assert [o.Label for o in doc.Objects if properties.failed(o)] == []
        lay = next(o for o in doc.Objects if layout.is_layout(o))
        assert lay.Connectors, "the boards are joined"
        lay.Joints = "None"  # the *.pack.json twin lists the parts as modelled, without joints
        doc.recompute()
        twin = json.load(open(os.path.join(source_dir, "examples", name + ".pack.json")))
        def sizes(parts):
            return sorted(tuple(sorted((round(p["width"], 6), round(p["height"], 6)))) for p in parts)
        assert sizes(json.loads(lay.LayoutJson)["placements"]) == \
            sizes(p for p in twin["parts"] for _ in range(p.get("quantity", 1)))
        assert lay.Kerf.Value == twin["settings"]["kerf"] and lay.Trim.Value == twin["settings"]["trim"]
        assert lay.SheetCount == 1 and lay.Usage > 0.85
    finally:
        FreeCAD.closeDocument(doc.Name)
