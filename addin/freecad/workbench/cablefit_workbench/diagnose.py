# Diagnose recording: a recording case.json diagnosed by the CLI's own code (cablefit_native),
# shown as a group of plain Part objects (scan points, the centre points the fit saw, nominal and
# fitted cables) whose properties carry the verdict and the explanation, so a saved document
# keeps them without the C++ module.
import FreeCAD
import Part

from . import engine

MM = engine.MM


def _points(matrix):
    """FreeCAD vectors [mm] of a (3, n) array [m]."""
    return [FreeCAD.Vector(*(MM * p)) for p in matrix.T] if matrix.size else []


def _polyline(points):
    pts = [p for i, p in enumerate(points) if i == 0 or (p - points[i - 1]).Length > 1e-9]
    return Part.makePolygon(pts) if len(pts) > 1 else Part.Shape()


def _cloud(points):
    return Part.makeCompound([Part.Vertex(p) for p in points]) if points else Part.Shape()


def _add_shape(doc, group, name, label, shape, colour=None, point_size=None):
    o = doc.addObject("Part::Feature", name)
    o.Label = label
    o.Shape = shape
    group.addObject(o)
    if FreeCAD.GuiUp and colour:
        o.ViewObject.LineColor = colour
        o.ViewObject.PointColor = colour
        o.ViewObject.LineWidth = 3
        if point_size:
            o.ViewObject.PointSize = point_size
    return o


def summary_text(d):
    found = " + ".join(e for e, _ in d.effects) if len(d.effects) > 1 else d.effect
    lines = ["%s (%s case): %s, confidence %.2f" % (d.name, d.kind, found, d.confidence)]
    if len(d.effects) > 1:
        lines.append("  shares of the mismatch: " +
                     ", ".join("%s %.0f %%" % (e, 100.0 * s) for e, s in d.effects))
    if d.interval:
        lines.append("  interval s = %.3f .. %.3f m" % d.interval)
    for k, v in sorted(d.parameters.items()):
        lines.append("  %s = %.6g" % (k, v))
    lines.append("  max deviation: nominal %.4g %s, fitted %.4g %s" %
                 (d.baseline_max, d.deviation_unit, d.fitted_max, d.deviation_unit))
    if d.explanation:
        lines.append("  " + d.explanation)
    for n in d.notes:
        lines.append("  note: " + n)
    return "\n".join(lines)


def diagnose_recording(case_file, doc=None, report_dir="", progress=None):
    """Diagnoses `case_file` and adds a group 'Diagnosis <name>' to `doc`. With `report_dir`,
    diagnosis.json, the model curves and report.html are written there as by the CLI.
    Returns the group."""
    doc = doc or FreeCAD.ActiveDocument
    d = engine.native().diagnose(case_file, report_dir or "", progress)
    group = doc.addObject("App::DocumentObjectGroup", "Diagnosis")
    group.Label = "Diagnosis " + d.name
    for kind, name, tip in [("App::PropertyFile", "CaseFile", "The recording case.json"),
                            ("App::PropertyString", "Effect", "Diagnosed effect"),
                            ("App::PropertyFloat", "Confidence", "0..1"),
                            ("App::PropertyStringList", "Explanation", "The diagnosis text"),
                            ("App::PropertyFile", "Report", "report.html, when written"),
                            ("App::PropertyFloat", "Seconds", "Diagnosis wall time [s]")]:
        group.addProperty(kind, name, "Diagnosis", tip)
    group.CaseFile = case_file
    group.Effect = d.effect
    group.Confidence = d.confidence
    text = summary_text(d)
    group.Explanation = text.split("\n")
    group.Report = d.report
    group.Seconds = d.seconds
    if d.scan_points.size:
        _add_shape(doc, group, "ScanPoints", "scan points", _cloud(_points(d.scan_points)),
                   (0.6, 0.6, 0.6), 2)
    if d.observation.size:
        _add_shape(doc, group, "Observation", "observed centre (" + d.observation_source + ")",
                   _cloud(_points(d.observation)), (0.1, 0.1, 0.1), 4)
    if d.nominal.size:
        _add_shape(doc, group, "Nominal", "nominal cable", _polyline(_points(d.nominal)),
                   (0.2, 0.4, 0.9))
    if d.fitted.size:
        _add_shape(doc, group, "Fitted", "fitted cable (%s)" % d.effect,
                   _polyline(_points(d.fitted)), (0.9, 0.3, 0.1))
    FreeCAD.Console.PrintMessage("cablefit: " + text + "\n")
    if d.report:
        FreeCAD.Console.PrintMessage("cablefit: report written to %s\n" % d.report)
    doc.recompute()
    return group
