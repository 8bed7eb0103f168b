"""FabGuide document objects.

FeaturePython objects that gather their inputs into plain core models, call `fabguide_core`
once on recompute and write the results back. No algorithm lives here (see docs/architecture in
README.md); everything here can be created and recomputed headless in `freecadcmd`.
"""
import fabguide_core

__version__ = fabguide_core.__version__
