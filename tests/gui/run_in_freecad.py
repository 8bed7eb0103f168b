"""Runs one GUI test script inside the real FreeCAD under Xvfb and judges it.

Usage: run_in_freecad.py TEST_SCRIPT

The test script uses `guitest.run(...)`, which reports through FreeCAD's exit status. This
runner fails the test as well when FreeCAD printed a Python traceback or any error, so a
workbench that loads with errors in the report view does not pass.
"""
import os
import re
import subprocess
import sys

# What FreeCAD prints when Python code fails while it loads workbenches or runs commands.
TIMEOUT = 240  # seconds; FreeCAD starts in about 5

PROBLEM = re.compile(r"Traceback|Error|Exception|failed", re.IGNORECASE)


def problems(output):
    return [line for line in output.splitlines() if PROBLEM.search(line)]


def main(script):
    env = dict(os.environ, QTWEBENGINE_DISABLE_SANDBOX="1", FABGUIDE_GUI_TEST=os.path.abspath(script))
    bootstrap = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bootstrap.py")
    try:
        run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad", bootstrap],
                             env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=TIMEOUT)
    except subprocess.TimeoutExpired as timeout:
        print((timeout.output or b"").decode(errors="replace"))
        print("FAILED: FreeCAD did not finish {} within {} s".format(script, timeout.timeout))
        return 1
    print(run.stdout)
    bad = problems(run.stdout)
    if bad:
        print("FAILED: FreeCAD reported errors:\n  " + "\n  ".join(bad))
        return 1
    if run.returncode != 0:
        print("FAILED: FreeCAD exited with status {}".format(run.returncode))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
