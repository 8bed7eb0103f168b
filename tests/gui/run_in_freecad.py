"""Runs one GUI test script inside the real FreeCAD under Xvfb and judges it.

Usage: run_in_freecad.py TEST_SCRIPT

The test script uses `guitest.run(...)`, which reports through FreeCAD's exit status. This
runner fails the test as well when FreeCAD logged an error (an `Err:` line of its --log-file:
a Python traceback, Console.PrintError), so a workbench that loads or runs with errors in the
report view does not pass; a user's mistake a journey makes on purpose is said in one plain line,
which its script names in a line `# expects error: TEXT`. A traceback fails it always. The log is read rather than stdout because FreeCAD 1.0's GUI sends
print() and Console messages to the report view only.
"""
import os
import subprocess
import sys
import tempfile

TIMEOUT = 240  # seconds; FreeCAD starts in about 5

# FreeCAD's own complaints about its installation, not about the workbench under test.
FREECAD_NOISE = (
    "failed to load font file",  # Debian 13's FreeCAD lacks TechDraw's Y14.5 fonts
)


def problems(log, expected=()):
    return [line for line in log.splitlines() if "Traceback" in line or
            line.startswith("Err:") and not any(text in line for text in FREECAD_NOISE + tuple(expected))]


def expected_errors(script):
    with open(script, encoding="utf-8") as f:
        return [line.split(":", 1)[1].strip() for line in f if line.startswith("# expects error:")]


def main(script):
    env = dict(os.environ, QTWEBENGINE_DISABLE_SANDBOX="1", FABGUIDE_GUI_TEST=os.path.abspath(script))
    bootstrap = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bootstrap.py")
    with tempfile.TemporaryDirectory() as folder:
        log_file = os.path.join(folder, "freecad.log")
        # FreeCAD 0.20's GUI takes its own options only after the file to run. Each test has its own user settings
        # (FreeCAD writes them when it quits, and when a preferences page is accepted): tests running at once in
        # one HOME would otherwise see each other's. And its own cache, where FreeCAD 1.0 keeps documents' recovery
        # files: one left by a FreeCAD that was killed would open the document recovery dialog in the next test.
        env["XDG_CACHE_HOME"] = os.path.join(folder, "cache")
        command = ["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", "freecad", bootstrap, "--log-file", log_file,
                   "--user-cfg", os.path.join(folder, "user.cfg")]
        try:
            run = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=TIMEOUT)
        except subprocess.TimeoutExpired as timeout:
            print((timeout.output or b"").decode(errors="replace"))
            print("FAILED: FreeCAD did not finish {} within {} s".format(script, timeout.timeout))
            return 1
        log = open(log_file, encoding="utf-8", errors="replace").read() if os.path.exists(log_file) else ""
    print(run.stdout)
    print("".join(line + "\n" for line in log.splitlines() if line[:4] in ("Err:", "Wrn:", "Msg:")))
    bad = problems(log, expected_errors(script))
    if bad:
        print("FAILED: FreeCAD reported errors:\n  " + "\n  ".join(bad))
        return 1
    if run.returncode != 0:
        print("FAILED: FreeCAD exited with status {}".format(run.returncode))
        return 1
    if not log:
        print("FAILED: FreeCAD wrote no log (was --log-file refused?)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
