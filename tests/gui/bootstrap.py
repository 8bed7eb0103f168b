"""Run by FreeCAD's GUI in place of a test script (named by $FABGUIDE_GUI_TEST).

FreeCAD keeps running when a script given on its command line raises, so a test with an
error at import time would hang: here any such error ends FreeCAD with status 1. FreeCAD puts
this file's folder on sys.path, which makes `guitest` importable by the test scripts.
"""
import os
import runpy
import traceback

try:
    runpy.run_path(os.environ["FABGUIDE_GUI_TEST"], run_name="__main__")
except BaseException:
    traceback.print_exc()
    os._exit(1)
