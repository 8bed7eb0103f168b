"""Adding FeaturePython properties idempotently, so documents saved by an older FabGuide gain new
properties when they are opened (call `add` again from onDocumentRestored)."""


def add(obj, kind, name, group, doc, value=None, mode=0):
    """Adds property `name` if missing and sets `value` on creation; mode 1 = read-only, 2 = hidden."""
    if name in obj.PropertiesList:
        return
    obj.addProperty(kind, name, group, doc)
    if value is not None:
        setattr(obj, name, value)
    if mode:
        obj.setEditorMode(name, mode)


class Proxy:
    """Base of FabGuide's FeaturePython proxies: they hold no state of their own (everything lives in
    properties), so saving stores nothing and restoring re-adds any property a newer version defines.
    Subclasses list their properties in `define(obj)` with `add`."""

    def __init__(self, obj):
        obj.Proxy = self
        self.define(obj)

    def onDocumentRestored(self, obj):
        self.define(obj)

    def __getstate__(self):  # FreeCAD 0.20
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):  # FreeCAD 0.21 and later
        return None

    def loads(self, state):
        return None
