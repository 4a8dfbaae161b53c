# View providers (GUI only): icons in the tree, and a Cable's relaxed tube drawn like any Part.
import os

ICONS = os.path.join(os.path.dirname(os.path.dirname(__file__)), "Resources", "icons")


def icon(name):
    return os.path.join(ICONS, name + ".svg")


class CableViewProvider:
    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.ShapeColor = (0.85, 0.45, 0.10)

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon("cablefit_make_physical")

    def claimChildren(self):
        return []

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


class DiagnosisViewProvider:
    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon("cablefit_diagnose")

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None
