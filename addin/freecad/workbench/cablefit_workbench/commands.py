# The workbench's GUI commands. Each one only collects the selection / a file name and calls the
# non-GUI function the headless tests call too (cable.py, colours.py, diagnose.py, engine.py);
# every failure goes to the report view, never out of Activated (FreeCAD would only print a
# traceback and the user would see nothing happen).
import os

import FreeCAD
import FreeCADGui

from . import cable, colours, diagnose, engine, gui_progress
from .view_providers import icon


def _guarded(title, fn):
    FreeCAD.ActiveDocument.openTransaction(title)
    try:
        fn()
        FreeCAD.ActiveDocument.commitTransaction()
    except engine.Cancelled:
        FreeCAD.ActiveDocument.abortTransaction()
        FreeCAD.Console.PrintWarning("cablefit: %s cancelled\n" % title)
    except Exception as e:  # noqa: BLE001 - reported, the document stays usable
        FreeCAD.ActiveDocument.abortTransaction()
        FreeCAD.Console.PrintError("cablefit: %s: %s\n" % (title, e))


def _selected_cables():
    return [o for o in FreeCADGui.Selection.getSelection() if cable.is_cable(o)]


def _has_doc():
    return FreeCAD.ActiveDocument is not None


class MakePhysical:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_make_physical"), "MenuText": "Make physical",
                "ToolTip": "Turn the selected edges, wires or tube solids into Cable objects "
                           "relaxed under gravity (properties: diameter, material, supports, "
                           "gravity; recomputed on change)"}

    def IsActive(self):
        return _has_doc() and bool(FreeCADGui.Selection.getSelectionEx())

    def Activated(self):
        def run():
            for sel in FreeCADGui.Selection.getSelectionEx():
                if cable.is_cable(sel.Object):
                    continue
                subs = [n for n in sel.SubElementNames if n.startswith("Edge")]
                cable.make_cable(sel.Object, subs)
        _guarded("Make physical", run)


class AddSupport:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_add_support"), "MenuText": "Add support",
                "ToolTip": "Select a Cable and either a solid it passes through (clip there) or "
                           "a picked point (clamp, clip or pin at the nearest route point)"}

    def IsActive(self):
        return _has_doc() and bool(_selected_cables())

    def Activated(self):
        def run():
            from PySide import QtGui
            target = _selected_cables()[0]
            for sel in FreeCADGui.Selection.getSelectionEx():
                if sel.Object == target:
                    continue
                if sel.Object.isDerivedFrom("Part::Feature") and sel.Object.Shape.Solids:
                    cable.add_support(target, "clip", solid=sel.Object)
                    return
                if sel.PickedPoints:
                    kind, ok = QtGui.QInputDialog.getItem(
                        None, "Add support", "Support kind", cable.SUPPORT_KINDS, 1, False)
                    if ok:
                        cable.add_support(target, kind, point=sel.PickedPoints[-1])
                    return
            raise ValueError("select a solid the cable passes through or pick a point as well")
        _guarded("Add support", run)


class RelaxHarness:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_relax"), "MenuText": "Relax harness",
                "ToolTip": "Relax every Cable of the document together (ends that meet form "
                           "a junction). Esc cancels; problems go to the report view"}

    def IsActive(self):
        return _has_doc() and bool(cable.cables_of(FreeCAD.ActiveDocument))

    def Activated(self):
        def run():
            bar = gui_progress.ProgressBar("cablefit: relax harness")
            try:
                r = cable.relax_harness(FreeCAD.ActiveDocument, bar)
            finally:
                bar.close()
            for c in r.cables:
                if c.ok:
                    FreeCAD.Console.PrintMessage(
                        "cablefit: %s: sag %.3f mm, min bend radius %.1f mm, %.0f ms\n" %
                        (c.name, c.max_deviation * 1e3, c.min_bend_radius * 1e3, c.seconds * 1e3))
                else:
                    FreeCAD.Console.PrintError("cablefit: %s: %s\n" % (c.name, c.error))
            FreeCAD.ActiveDocument.recompute()
        _guarded("Relax harness", run)


class DeviationColours:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_deviation"), "MenuText": "Deviation colours",
                "ToolTip": "Colour the selected (or all) relaxed cables by their distance to "
                           "the drawn route, with a legend"}

    def IsActive(self):
        return _has_doc() and bool(cable.cables_of(FreeCAD.ActiveDocument))

    def Activated(self):
        def run():
            colours.colour_cables(_selected_cables() or cable.cables_of(FreeCAD.ActiveDocument))
            FreeCAD.ActiveDocument.recompute()
        _guarded("Deviation colours", run)


class DiagnoseRecording:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_diagnose"), "MenuText": "Diagnose recording",
                "ToolTip": "Load a recording case.json: show scan points, nominal and fitted "
                           "cables and the diagnosis (as `cablefit diagnose`)"}

    def IsActive(self):
        return True

    def Activated(self):
        from PySide import QtGui
        path, _ = QtGui.QFileDialog.getOpenFileName(None, "Recording case", "", "case.json (*.json)")
        if path:
            self.diagnose(path, os.path.join(os.path.dirname(path), "cablefit-diagnosis"))

    def diagnose(self, path, report_dir):
        """Everything after the file dialog (the GUI test calls this)."""
        if not _has_doc():
            FreeCAD.newDocument()

        def run():
            bar = gui_progress.ProgressBar("cablefit: diagnose")
            try:
                diagnose.diagnose_recording(path, FreeCAD.ActiveDocument, report_dir, bar)
            finally:
                bar.close()
            FreeCADGui.SendMsgToActiveView("ViewFit")
        _guarded("Diagnose recording", run)


class ExportReport:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_report"), "MenuText": "Export report",
                "ToolTip": "Write the relax report of the selected (or all) cables to a folder: "
                           "report.html, STEP, JSON and picture, as `cablefit relax --out`"}

    def IsActive(self):
        return _has_doc() and bool(cable.cables_of(FreeCAD.ActiveDocument))

    def Activated(self):
        from PySide import QtCore, QtGui
        folder = QtGui.QFileDialog.getExistingDirectory(None, "Report folder")
        report = self.export(folder) if folder else None
        if report:
            QtGui.QDesktopServices.openUrl(QtCore.QUrl.fromLocalFile(report))

    def export(self, folder):
        """Everything after the folder dialog; returns report.html's path, None on failure."""
        written = []

        def run():
            cables = _selected_cables() or cable.cables_of(FreeCAD.ActiveDocument)
            bar = gui_progress.ProgressBar("cablefit: report")
            try:
                written.append(engine.export_report(cables, folder, True, bar))
            finally:
                bar.close()
            FreeCAD.Console.PrintMessage("cablefit: report written to %s\n" % written[0])
        _guarded("Export report", run)
        return written[0] if written else None


class RelaxFile:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_relax"), "MenuText": "Relax a harness file",
                "ToolTip": "Relax every cable of a STEP, IGES, KBL (VDA 4964) or mesh file as "
                           "`cablefit relax` does and add the relaxed cables to the document"}

    def IsActive(self):
        return True

    def Activated(self):
        from PySide import QtGui
        path, _ = QtGui.QFileDialog.getOpenFileName(
            None, "Harness file", "",
            "Harness files (*.step *.stp *.igs *.iges *.kbl *.stl *.obj *.ply *.gltf *.glb)")
        if not path:
            return

        def run():
            doc = FreeCAD.ActiveDocument or FreeCAD.newDocument("Harness")
            bar = gui_progress.ProgressBar("cablefit: relax " + path)
            try:
                relaxation, _ = engine.relax_file(path, doc, "", bar)
            finally:
                bar.close()
            failed = [r.name for r in relaxation.cables if not r.ok]
            FreeCAD.Console.PrintMessage("cablefit: %s: %d cables, %d failed\n" % (
                path, len(relaxation.cables), len(failed)))
            FreeCADGui.SendMsgToActiveView("ViewFit")
        _guarded("Relax a harness file", run)


class SweepMotion:
    def GetResources(self):
        return {"Pixmap": icon("cablefit_motion"), "MenuText": "Sweep motion",
                "ToolTip": "Relax a harness file with a harness.json that has a \"motion\" (a "
                           "door, a seat rail) and sweep it as `cablefit relax` does; a panel "
                           "shows the cables at every pose (slider, Play) with bend radius, "
                           "tension, stability and clearance"}

    def IsActive(self):
        return True

    def Activated(self):
        from PySide import QtGui
        path, _ = QtGui.QFileDialog.getOpenFileName(
            None, "Harness file", "",
            "Harness files (*.step *.stp *.igs *.iges *.kbl *.stl *.obj *.ply *.gltf *.glb)")
        if not path:
            return
        config, _ = QtGui.QFileDialog.getOpenFileName(
            None, "harness.json with a motion", os.path.dirname(path), "harness.json (*.json)")
        if config:
            self.sweep(path, config)

    def sweep(self, path, config):
        """Everything after the file dialogs (the GUI test calls this). Returns the task panel,
        None on failure."""
        from . import motion, motion_panel
        if not _has_doc():
            FreeCAD.newDocument("Harness")
        panels = []

        def run():
            bar = gui_progress.ProgressBar("cablefit: relax and sweep " + path)
            try:
                sweep = motion.sweep_file(path, config, FreeCAD.ActiveDocument, bar)
            finally:
                bar.close()
            for swept in sweep.motion.cables:
                FreeCAD.Console.PrintMessage(
                    "cablefit: motion '%s': %s: %d poses, %s, %.3f s\n" % (
                        sweep.motion.name, swept.name, len(swept.poses),
                        "completed" if swept.completed else "STOPPED: " + swept.message,
                        swept.seconds))
            if FreeCADGui.Control.activeDialog():
                FreeCADGui.Control.closeDialog()
            panels.append(motion_panel.MotionPanel(sweep))
            FreeCADGui.Control.showDialog(panels[0])
            FreeCADGui.SendMsgToActiveView("ViewFit")
        _guarded("Sweep motion", run)
        return panels[0] if panels else None


COMMANDS = [("Cablefit_RelaxFile", RelaxFile()), ("Cablefit_SweepMotion", SweepMotion()),
            ("Cablefit_MakePhysical", MakePhysical()), ("Cablefit_AddSupport", AddSupport()),
            ("Cablefit_RelaxHarness", RelaxHarness()),
            ("Cablefit_DeviationColours", DeviationColours()),
            ("Cablefit_DiagnoseRecording", DiagnoseRecording()),
            ("Cablefit_ExportReport", ExportReport())]


def register():
    for name, command in COMMANDS:
        FreeCADGui.addCommand(name, command)
    return [name for name, _ in COMMANDS]
