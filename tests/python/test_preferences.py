"""The preferences page (Resources/ui/Preferences.ui) stores what preferences.py reads, and new layouts, master
boards and printables start with the user's values."""
import os
import xml.etree.ElementTree as ET

import FreeCAD
import pytest
from freecad.fabguide import preferences
from freecad.fabguide.function import printable, workslike_file
from freecad.fabguide.material import layout, master_board


@pytest.fixture
def chosen():
    """Sets preferences for one test, then removes them (FreeCAD keeps them in the test home's user.cfg)."""
    group = FreeCAD.ParamGet(preferences.PATH)
    set_names = []

    def choose(**values):
        for name, value in values.items():
            group.SetFloat(name, value)
            set_names.append(name)

    yield choose
    for name in set_names:
        group.RemFloat(name)


def test_the_page_stores_every_preference_under_the_path_read(source_dir):
    root = ET.parse(os.path.join(source_dir, "Resources", "ui", "Preferences.ui")).getroot()
    boxes = root.findall(".//widget[@class='Gui::PrefDoubleSpinBox']")
    entries = {box.find("property[@name='prefEntry']/cstring").text: box for box in boxes}
    assert set(entries) == set(preferences.DEFAULTS)
    for name, box in entries.items():
        assert "User parameter:BaseApp/Preferences/" + box.find("property[@name='prefPath']/cstring").text == \
            preferences.PATH
        assert float(box.find("property[@name='value']/double").text) == preferences.DEFAULTS[name], name


def test_new_objects_start_with_the_preferences(chosen, source_dir):
    chosen(Kerf=0.15, Spacing=1.5, Trim=8, LayoutTimeLimit=20, SheetWidth=1525, SheetHeight=1525,
           SheetThickness=12, Gap=0.25, BuildVolumeX=180, BuildVolumeY=180, BuildVolumeZ=180)
    doc = FreeCAD.newDocument("Preferences")
    try:
        sheet = master_board.create(doc)
        assert (sheet.Width.Value, sheet.Height.Value, sheet.Thickness.Value) == (1525, 1525, 12)
        lay = layout.create(doc, [], [sheet])
        assert (lay.Kerf.Value, lay.Spacing.Value, lay.Trim.Value, lay.TimeLimit) == (0.15, 1.5, 8, 20)
        mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "box-with-lid.workslike.json"))
        made = printable.create(doc, mech)
        assert made.Printer == "Custom" and made.Gap.Value == 0.25 and tuple(made.BuildVolume) == (180, 180, 180)
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_without_preferences_the_defaults_hold_and_nonsense_is_not_used(chosen, source_dir):
    chosen(SheetWidth=-3)  # a value no page would store, written by hand
    doc = FreeCAD.newDocument("Defaults")
    try:
        sheet = master_board.create(doc)
        assert (sheet.Width.Value, sheet.Height.Value, sheet.Thickness.Value) == (2440, 1220, 18)
        mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "box-with-lid.workslike.json"))
        made = printable.create(doc, mech)
        assert made.Printer.startswith("FDM") and made.Gap.Value == 0.4
    finally:
        FreeCAD.closeDocument(doc.Name)
