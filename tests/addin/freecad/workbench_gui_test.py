# The workbench in FreeCAD's GUI (run under Xvfb by CMakeLists.txt): the workbench activates with
# its eight commands in a toolbar and a menu, and the commands run as a user runs them (selection +
# Gui.runCommand; the file dialogs of Diagnose/Export report/Sweep motion are bypassed by calling
# the methods they hand the chosen paths to), with FreeCAD's progress indicator, the deviation
# colours and the legend, and the motion panel's slider. A failing solve must leave the document
# usable. Same environment as workbench_test.py.
import math
import os
import sys
import time
import traceback

ENV = os.environ
sys.path[:0] = [ENV["CABLEFIT_WORKBENCH_DIR"], ENV["CABLEFIT_MODULE_DIR"]]

import FreeCAD  # noqa: E402
import FreeCADGui  # noqa: E402
import Part  # noqa: E402
from PySide import QtCore, QtGui  # noqa: E402

NAMES = ["Cablefit_RelaxFile", "Cablefit_SweepMotion", "Cablefit_MakePhysical",
         "Cablefit_AddSupport", "Cablefit_RelaxHarness",
         "Cablefit_DeviationColours", "Cablefit_DiagnoseRecording", "Cablefit_ExportReport"]


def check(condition, what):
    if not condition:
        raise AssertionError(what)


def run():
    if "CablefitWorkbench" not in FreeCADGui.listWorkbenches():
        # Not installed for this user: register it from the source tree as FreeCAD would.
        exec(open(os.path.join(ENV["CABLEFIT_WORKBENCH_DIR"], "InitGui.py")).read(),
             {"__name__": "InitGui"})
    FreeCADGui.activateWorkbench("CablefitWorkbench")
    from cablefit_workbench import cable, commands
    check(all(n in FreeCADGui.listCommands() for n in NAMES), "all eight commands registered")
    mw = FreeCADGui.getMainWindow()
    bar = [t for t in mw.findChildren(QtGui.QToolBar) if t.windowTitle() == "Cablefit"]
    check(bar and len([a for a in bar[0].actions() if not a.isSeparator()]) == len(NAMES),
          "Cablefit toolbar with a button per command")
    check(all(not a.icon().isNull() and a.toolTip() for a in bar[0].actions()),
          "every button has an icon and a tooltip")
    check(any(m.title() == "Cablefit" for m in mw.menuBar().findChildren(QtGui.QMenu)),
          "Cablefit menu")

    doc = FreeCAD.newDocument("gui")
    s = Part.BSplineCurve()
    s.interpolate([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(150, 40, 20),
                   FreeCAD.Vector(300, 0, 30), FreeCAD.Vector(450, -30, 0)])
    route = doc.addObject("Part::Feature", "Route")
    route.Shape = s.toShape()
    clip = doc.addObject("Part::Box", "Clip")
    clip.Length, clip.Width, clip.Height = 20, 30, 30
    clip.Placement.Base = s.value(s.parameter(FreeCAD.Vector(230, 20, 28))) - \
        FreeCAD.Vector(10, 15, 15)
    doc.recompute()
    FreeCADGui.Selection.addSelection(doc.Name, route.Name, "Edge1")
    FreeCADGui.runCommand("Cablefit_MakePhysical")
    cables = cable.cables_of(doc)
    check(len(cables) == 1 and cables[0].Status == "relaxed", "Make physical on a picked edge")
    c = cables[0]
    check(list(c.Route[1]) == ["Edge1"], "the picked edge is the route")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(c)
    FreeCADGui.Selection.addSelection(clip)
    FreeCADGui.runCommand("Cablefit_AddSupport")
    check(any("clip 'Clip'" in x for x in c.SupportsUsed), "Add support with a solid")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand("Cablefit_RelaxHarness")
    check(c.Status == "relaxed" and c.Sag.Value > 0, "Relax harness")
    FreeCADGui.runCommand("Cablefit_DeviationColours")
    m = doc.getObject(c.Name + "_deviation")
    check(m is not None and len(m.ViewObject.DiffuseColor) == len(m.Shape.Faces),
          "deviation map coloured face by face")
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    check(any(root.getChild(i).getName() == "cablefit_legend"
              for i in range(root.getNumChildren())), "legend shown")

    out = ENV["CABLEFIT_TEST_OUT"]
    report = commands.ExportReport().export(os.path.join(out, "gui-report"))
    check(report and os.path.exists(report), "Export report wrote %s" % report)
    case = os.path.join(ENV["CABLEFIT_SHARED_DIR"], "cases", "public", "sample-none", "case.json")
    n = len(doc.Objects)
    commands.DiagnoseRecording().diagnose(case, os.path.join(out, "gui-diagnosis"))
    groups = [o for o in doc.Objects if o.TypeId == "App::DocumentObjectGroup"]
    check(len(doc.Objects) > n and groups and groups[0].Effect, "Diagnose recording")
    check(os.path.exists(os.path.join(out, "gui-diagnosis", "report.html")), "diagnosis report")

    check_motion_panel(commands)

    # A failing solve: reported, the transaction undone, the last good shape kept.
    c.Material = "Section file"
    c.SectionFile = "/nonexistent/section.json"
    FreeCADGui.runCommand("Cablefit_RelaxHarness")
    check(c.Shape.Volume > 0 and doc.getObject(m.Name) is not None, "document intact")
    c.Material = "Default bundle"
    doc.recompute()
    check(c.Status == "relaxed", "recovers after the failure: " + c.Status)
    print("PASS gui")


def check_motion_panel(commands):
    """Sweep motion on the door-hinge sample: the panel opens over the 31 poses, and the slider
    at pose k puts pose k's centreline into the cable's tube (its end vertices one radius from
    the centreline's ends, its seam one radius from the centreline all along)."""
    import numpy
    samples = os.path.normpath(os.path.join(ENV["CABLEFIT_SHARED_DIR"], "..", "..", "samples",
                                            "harness"))
    panel = commands.SweepMotion().sweep(os.path.join(samples, "door_hinge.stl"),
                                         os.path.join(samples, "door_hinge.json"))
    check(panel is not None and FreeCADGui.Control.activeDialog(), "Sweep motion opens its panel")
    sweep = panel.sweep
    check(panel.slider.minimum() == 0 and panel.slider.maximum() == 30, "a slider over 31 poses")
    swept = sweep.motion.cables[0]
    obj = sweep.objects[0]
    radius = obj.Diameter.Value / 2
    for k in (15, 7, 0):
        panel.slider.setValue(k)
        QtGui.QApplication.processEvents()
        check("%.1f deg" % math.degrees(sweep.motion.q[k]) in panel.label.text(),
              "the label shows pose %d's angle: %s" % (k, panel.label.text()))
        centre = swept.poses[k].centreline * 1e3  # m -> mm, as the workbench draws
        ends = [FreeCAD.Vector(*centre[:, 0]), FreeCAD.Vector(*centre[:, -1])]
        for v in obj.Shape.Vertexes:
            off = min(abs((v.Point - e).Length - radius) for e in ends)
            check(off < 1e-3, "pose %d: tube vertex %s is %.3g mm off one radius from the "
                  "centreline's ends" % (k, v.Point, off))
        poly = Part.makePolygon([FreeCAD.Vector(*p) for p in centre.T])
        seam = [e for e in obj.Shape.Edges if not e.isClosed()][0]
        worst = max(abs(poly.distToShape(Part.Vertex(p))[0] - radius)
                    for p in seam.discretize(25))
        check(worst < 0.01, "pose %d: the tube's seam is one radius from pose %d's centreline "
              "within %.3g mm" % (k, k, worst))
    check("75.0 deg" not in panel.label.text(), "the label follows the slider")
    far = (FreeCAD.Vector(*(swept.poses[15].centreline[:, -1] * 1e3)) -
           FreeCAD.Vector(*(swept.poses[0].centreline[:, -1] * 1e3))).Length
    check(far > 50, "the open door's pose is another shape (ends %.1f mm apart)" % far)
    panel.slider.setValue(28)
    panel.toggle_play()
    deadline = time.time() + 30
    while panel.timer.isActive() and time.time() < deadline:
        QtGui.QApplication.processEvents()
        time.sleep(0.01)
    check(panel.slider.value() == 30 and not panel.timer.isActive(),
          "Play steps to the last pose and stops: at %d" % panel.slider.value())
    panel.slider.setValue(15)  # the door open: far from the relaxed shape
    open_ends = [v.Point for v in obj.Shape.Vertexes]
    panel.reject()
    check(not FreeCADGui.Control.activeDialog(), "Close closes the panel")
    relaxed = sweep.relaxation.cables[swept.cable].relaxed * 1e3
    back = [min((v.Point - FreeCAD.Vector(*relaxed[:, j])).Length for j in (0, -1))
            for v in obj.Shape.Vertexes]
    check(all(abs(d - radius) < 1e-3 for d in back) and
          max((v.Point - p).Length for v, p in zip(obj.Shape.Vertexes, open_ends)) > 50,
          "closing puts the relaxed tube back: vertices %.3g mm off" % max(back))


def finish():
    code = 1
    try:
        run()
        code = 0
    except Exception:
        traceback.print_exc()
        print("FAIL gui")
    sys.stdout.flush()
    os._exit(code)


QtCore.QTimer.singleShot(200, finish)
