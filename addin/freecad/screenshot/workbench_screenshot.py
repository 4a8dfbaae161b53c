# FreeCAD GUI macro behind docs/freecad-workbench.png: draws a spline cable through a clip and a
# second, softer cable, runs the workbench's commands as a user would (Make physical on the
# selection, Add support with the clip, Relax harness, Deviation colours) and saves the window.
# Run: xvfb-run -a -s "-screen 0 1400x900x24" freecad addin/freecad/screenshot/workbench_screenshot.py
# with CABLEFIT_SCREENSHOT=<png> (the workbench installed by tools/install-freecad-workbench.sh).
import os
import traceback

import FreeCAD
import FreeCADGui
import Part
from PySide import QtCore, QtGui

OUT = os.environ.get("CABLEFIT_SCREENSHOT", "freecad-workbench.png")


def spline(doc, name, points):
    s = Part.BSplineCurve()
    s.interpolate([FreeCAD.Vector(*p) for p in points])
    o = doc.addObject("Part::Feature", name)
    o.Shape = s.toShape()
    return o


def run():
    FreeCADGui.activateWorkbench("CablefitWorkbench")
    doc = FreeCAD.newDocument("harness")
    r1 = spline(doc, "Route", [(0, 0, 0), (150, 40, 20), (300, 0, 30), (450, -30, 0)])
    r2 = spline(doc, "Route2", [(0, 80, 10), (160, 160, -10), (320, 120, 40), (430, 60, 20)])
    clip = doc.addObject("Part::Box", "Clip")
    clip.Length, clip.Width, clip.Height = 20, 36, 36
    clip.Placement.Base = r1.Shape.Curve.value(r1.Shape.Curve.parameter(
        FreeCAD.Vector(230, 20, 28))) - FreeCAD.Vector(10, 18, 18)
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(r1)
    FreeCADGui.Selection.addSelection(r2)
    FreeCADGui.runCommand("Cablefit_MakePhysical")
    cables = [o for o in doc.Objects if o.Name.startswith("Cable")]
    cables[0].Label, cables[1].Label = "main_cable", "sensor_cable"
    cables[0].Diameter, cables[1].Diameter = 8.0, 5.0
    cables[1].Material = "Stiffness"
    cables[1].BendingStiffness, cables[1].TorsionalStiffness = 0.004, 0.003
    cables[1].LinearDensity = 0.05
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(cables[0])
    FreeCADGui.Selection.addSelection(clip)
    FreeCADGui.runCommand("Cablefit_AddSupport")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand("Cablefit_RelaxHarness")
    FreeCADGui.runCommand("Cablefit_DeviationColours")
    clip.ViewObject.Transparency = 60
    for r in (r1, r2):  # the drawn routes as thin grey ghosts next to the relaxed cables
        r.ViewObject.Visibility = True
        r.ViewObject.LineColor = (0.55, 0.55, 0.55)
        r.ViewObject.LineWidth = 1
    for c in cables:
        FreeCAD.Console.PrintMessage("%s: %s, sag %s\n" % (c.Label, c.Status, c.Sag))
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    FreeCADGui.updateGui()
    mw = FreeCADGui.getMainWindow()
    mw.resize(1400, 860)
    FreeCADGui.updateGui()
    mdi = mw.findChild(QtGui.QMdiArea)
    sub = mdi.activeSubWindow() or mdi.subWindowList()[-1]
    mdi.setActiveSubWindow(sub)
    sub.showMaximized()
    FreeCADGui.updateGui()
    # Under Xvfb the OpenGL viewport grabs blank: the window is grabbed, and the viewport's own
    # off-screen rendering (saveImage, the same scene at the same size) painted into its place.
    widget = sub.widget()
    rect = QtCore.QRect(widget.mapTo(mw, QtCore.QPoint(0, 0)), widget.size())
    view_png = OUT.replace(".png", "-view.png")
    view.saveImage(view_png, rect.width(), rect.height(), "White")
    window = mw.grab()
    painter = QtGui.QPainter(window)
    painter.drawImage(rect.topLeft(), QtGui.QImage(view_png))
    painter.end()
    os.remove(view_png)
    window.save(OUT)
    FreeCAD.Console.PrintMessage("screenshot: %s\n" % OUT)


def finish():
    try:
        run()
    except Exception:
        traceback.print_exc()
    os._exit(0)


QtCore.QTimer.singleShot(500, finish)
