"""The GUI test runner fails when FreeCAD reports an error, even if the test script exits 0."""
import os
import subprocess
import sys


def run(source_dir, tmp_path, body):
    script = tmp_path / "gui_probe.py"
    script.write_text("import guitest\n" + body)
    runner = os.path.join(source_dir, "tests", "gui", "run_in_freecad.py")
    return subprocess.run([sys.executable, runner, str(script)], capture_output=True, text=True, timeout=300)


def test_error_printed_by_freecad_fails_the_test(source_dir, tmp_path):
    result = run(source_dir, tmp_path, "import FreeCAD\n"
                 "def report_error():\n    FreeCAD.Console.PrintError('workbench broke\\n')\n"
                 "guitest.run([report_error])\n")
    assert result.returncode == 1
    assert "FreeCAD reported errors" in result.stdout and "workbench broke" in result.stdout


def test_failing_step_fails_the_test(source_dir, tmp_path):
    result = run(source_dir, tmp_path, "def broken_step():\n    assert 1 == 2\nguitest.run([broken_step])\n")
    assert result.returncode == 1
    assert "AssertionError" in result.stdout


def test_a_clean_step_passes(source_dir, tmp_path):
    """FreeCAD's own start-up messages (on 0.20 and 1.0) are not taken for the workbench's errors."""
    result = run(source_dir, tmp_path, "import FreeCAD\n"
                 "def fine():\n    FreeCAD.Console.PrintMessage('all good\\n')\nguitest.run([fine])\n")
    assert result.returncode == 0, result.stdout
    assert "all good" in result.stdout  # the log's messages are shown: 1.0 prints them nowhere else
