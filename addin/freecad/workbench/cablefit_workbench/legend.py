# The colour legend of the deviation colours (GUI only): a vertical colour bar with its range and
# label drawn over the 3D view (a Coin annotation under its own orthographic camera, so it stays
# in the corner whatever the view does).
import FreeCADGui
from pivy import coin

from . import engine

_NODE_NAME = "cablefit_legend"
STEPS = 32


def _remove(root):
    for i in reversed(range(root.getNumChildren())):
        if root.getChild(i).getName() == _NODE_NAME:
            root.removeChild(i)


def _text(x, y, text):
    sep = coin.SoSeparator()
    t = coin.SoTranslation()
    t.translation = (x, y, 0)
    colour = coin.SoBaseColor()
    colour.rgb = (0.1, 0.1, 0.1)
    label = coin.SoText2()
    label.string = text
    sep.addChild(t)
    sep.addChild(colour)
    sep.addChild(label)
    return sep


def show(scale, title, view=None):
    """Replaces the legend of `view` (the active one by default) with one for `scale`."""
    view = view or FreeCADGui.ActiveDocument.ActiveView
    root = view.getSceneGraph()
    _remove(root)
    lo, hi = scale
    hud = coin.SoAnnotation()
    hud.setName(_NODE_NAME)
    cam = coin.SoOrthographicCamera()
    cam.height = 2.0
    cam.viewportMapping = coin.SoCamera.LEAVE_ALONE
    hud.addChild(cam)
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    hud.addChild(light)
    font = coin.SoFont()
    font.size = 14
    hud.addChild(font)
    x0, x1, y0, y1 = 0.76, 0.81, -0.6, 0.6  # right side; the view spans -1..1 both ways
    for k in range(STEPS):
        v = lo + (hi - lo) * (k + 0.5) / STEPS
        sep = coin.SoSeparator()
        colour = coin.SoBaseColor()
        colour.rgb = tuple(engine.native().deviation_colour(v, lo, hi))
        coords = coin.SoCoordinate3()
        ya = y0 + (y1 - y0) * k / STEPS
        yb = y0 + (y1 - y0) * (k + 1) / STEPS
        coords.point.setValues(0, 4, [(x0, ya, 0), (x1, ya, 0), (x1, yb, 0), (x0, yb, 0)])
        face = coin.SoFaceSet()
        face.numVertices.setValue(4)
        sep.addChild(colour)
        sep.addChild(coords)
        sep.addChild(face)
        hud.addChild(sep)
    hud.addChild(_text(x0 - 0.04, y1 + 0.08, title))
    hud.addChild(_text(x1 + 0.01, y1 - 0.02, "%.3g" % hi))
    hud.addChild(_text(x1 + 0.01, (y0 + y1) / 2, "%.3g" % ((lo + hi) / 2)))
    hud.addChild(_text(x1 + 0.01, y0, "%.3g" % lo))
    root.addChild(hud)
    return hud


def hide(view=None):
    view = view or FreeCADGui.ActiveDocument.ActiveView
    _remove(view.getSceneGraph())
