"""docs/formats.md names every key the tools write: a layout from `fabguide pack` (with saw cuts and a shared line),
the summary of `fabguide optimise`, a solve's report with a conflict and a print's report.json, read from real
runs on the bundled examples and compared with the keys the document's sections name in `code`."""
import json
import os
import re
import subprocess

import pytest


def section(source_dir, heading):
    """The text of docs/formats.md from the heading that starts with `heading` to the next heading."""
    with open(os.path.join(source_dir, "docs", "formats.md"), encoding="utf-8") as f:
        text = f.read()
    start = text.index("\n## " + heading)
    end = text.find("\n## ", start + 1)
    return text[start:end if end > 0 else len(text)]


def named(text):
    """The words the text names in `code` (`before: {layout, svg}` names three) or as "keys" of its JSON examples."""
    spans = re.findall(r"`([^`]*)`", text) + re.findall(r'"([a-z_][a-z_0-9]*)":', text)
    return {word for span in spans for word in re.findall(r"[a-z_][a-z_0-9]*", span)}


def keys(value, prefix=""):
    """Every key of a JSON value, nested ones too, as `name` (a list's items looked into)."""
    found = set()
    if isinstance(value, dict):
        for key, item in value.items():
            found.add(key)
            found |= keys(item)
    elif isinstance(value, list):
        for item in value:
            found |= keys(item)
    return found


def run(command):
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("cuts", ["free", "guillotine"])
def test_every_key_of_a_layout_is_in_formats_md(fabguide_cli, source_dir, tmp_path, cuts):
    with open(os.path.join(source_dir, "examples", "bookshelf.pack.json"), encoding="utf-8") as f:
        problem = json.load(f)
    problem["settings"].update(cuts=cuts, common_line=cuts == "free", spacing=0)
    (tmp_path / "job.json").write_text(json.dumps(problem))
    run([fabguide_cli, "pack", str(tmp_path / "job.json"), "-o", str(tmp_path / "layout.json"), "--time-limit", "1"])
    written = keys(json.loads((tmp_path / "layout.json").read_text()))
    assert written - named(section(source_dir, "Layout JSON")) == set()


def test_every_key_of_an_optimise_summary_is_in_formats_md(fabguide_cli, source_dir, tmp_path):
    run([fabguide_cli, "optimise", os.path.join(source_dir, "examples", "coffee-table.flatpack.json"), "-o",
         str(tmp_path), "--time-limit", "2", "--rounds", "1", "--seed", "1"])
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["suggestions"], "the coffee table has a suggestion to read the keys of"
    written = keys(summary)
    assert written - named(section(source_dir, "`*.flatpack.json`")) == set()
    # The binding gives the same figures under the same names (one serialiser, io::explorationFigures).
    from freecad.fabguide.core import fabguide_core

    with open(os.path.join(source_dir, "examples", "coffee-table.flatpack.json"), encoding="utf-8") as f:
        result = fabguide_core.optimise(json.load(f), time_limit=1, rounds=1)
    assert set(result) == set(summary)


def test_every_key_of_a_solve_report_with_a_conflict_is_in_formats_md(source_dir):
    from freecad.fabguide.core import fabguide_core

    def part(name, low, high):
        return {"name": name, "cuboids": [{"name": name, "min": low, "max": high}]}

    model = {"format": "fabguide.workslike", "version": 1, "locks": ["a.right", "b.left"],
             "parts": [part("a", [0, 0, 0], [10, 10, 10]), part("b", [8, 0, 0], [20, 10, 10])]}
    solved = fabguide_core.solve(model)
    assert solved["report"]["conflicts"], "two locked parts overlapping conflict"
    assert keys(solved["report"]) - named(section(source_dir, "`*.workslike.json`")) == set()
    kinds = {c["kind"] for c in solved["report"]["conflicts"]}
    assert kinds == {"lock", "no_overlap"} and kinds <= named(section(source_dir, "`*.workslike.json`"))


def test_every_key_of_a_printable_report_is_in_formats_md(source_dir, tmp_path):
    printer = os.path.join(os.environ["FABGUIDE_BUILD_DIR"], "fabguide-print")
    run([printer, "printable", os.path.join(source_dir, "examples", "box-with-lid.workslike.json"), "-o",
         str(tmp_path)])
    report = json.loads((tmp_path / "report.json").read_text())
    assert keys(report) - named(section(source_dir, "Print-in-place files")) == set()
