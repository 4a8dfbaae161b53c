# The workbench in FreeCAD's GUI (run under Xvfb by CMakeLists.txt): the workbench activates with
# its seven commands in a toolbar and a menu, and the commands run as a user runs them (selection +
# Gui.runCommand; the file dialogs of Diagnose/Export report are bypassed by calling the methods
# they hand the chosen path to), with FreeCAD's progress indicator, the deviation colours and the
# legend. A failing solve must leave the document usable. Same environment as workbench_test.py.
import os
import sys
import traceback

ENV = os.environ
sys.path[:0] = [ENV["CABLEFIT_WORKBENCH_DIR"], ENV["CABLEFIT_MODULE_DIR"]]

import FreeCAD  # noqa: E402
import FreeCADGui  # noqa: E402
import Part  # noqa: E402
from PySide import QtCore, QtGui  # noqa: E402

NAMES = ["Cablefit_RelaxFile", "Cablefit_MakePhysical", "Cablefit_AddSupport", "Cablefit_RelaxHarness",
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
    check(all(n in FreeCADGui.listCommands() for n in NAMES), "all seven commands registered")
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

    # A failing solve: reported, the transaction undone, the last good shape kept.
    c.Material = "Section file"
    c.SectionFile = "/nonexistent/section.json"
    FreeCADGui.runCommand("Cablefit_RelaxHarness")
    check(c.Shape.Volume > 0 and doc.getObject(m.Name) is not None, "document intact")
    c.Material = "Default bundle"
    doc.recompute()
    check(c.Status == "relaxed", "recovers after the failure: " + c.Status)
    print("PASS gui")


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
