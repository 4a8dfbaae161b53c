# Headless tests of the FreeCAD workbench, run by `freecadcmd` (see CMakeLists.txt): a document
# with a spline cable and a clip solid goes through the same functions the GUI commands call, and
# the results are checked against the `cablefit` CLI run on the same input files.
# Environment: CABLEFIT_FC_CASE (which test), CABLEFIT_CLI, CABLEFIT_MODULE_DIR,
# CABLEFIT_WORKBENCH_DIR, CABLEFIT_SHARED_DIR (the repository's tests/data), CABLEFIT_TEST_OUT.
# freecadcmd prints a script's exception but exits 0: every failure ends in sys.exit(1).
import json
import math
import os
import shutil
import subprocess
import sys
import time
import traceback

ENV = os.environ
sys.path[:0] = [ENV["CABLEFIT_WORKBENCH_DIR"], ENV["CABLEFIT_MODULE_DIR"]]

import FreeCAD  # noqa: E402
import Part  # noqa: E402

from cablefit_workbench import cable, colours, diagnose, engine, motion  # noqa: E402

SAG_TOLERANCE = 1e-9  # [m] workbench vs CLI: the same code on the same input


class Failure(Exception):
    pass


def check(condition, what):
    if not condition:
        raise Failure(what)


def out_dir(name):
    d = os.path.join(ENV["CABLEFIT_TEST_OUT"], name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def build_document(name):
    """A 450 mm spline cable drawn through a 20 x 30 x 30 mm clip box near its middle."""
    doc = FreeCAD.newDocument(name)
    pts = [FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(150, 40, 20), FreeCAD.Vector(300, 0, 30),
           FreeCAD.Vector(450, -30, 0)]
    spline = Part.BSplineCurve()
    spline.interpolate(pts)
    route = doc.addObject("Part::Feature", "Route")
    route.Shape = spline.toShape()
    route.Label = "main_route"
    clip = doc.addObject("Part::Box", "Clip")
    clip.Length, clip.Width, clip.Height = 20, 30, 30
    at = spline.value(spline.parameter(FreeCAD.Vector(230, 20, 28)))
    clip.Placement.Base = at - FreeCAD.Vector(10, 15, 15)
    doc.recompute()
    c = cable.make_cable(route, [], doc)
    c.Label = "main_cable"
    c.Diameter = 6.0
    cable.add_support(c, "clip", solid=clip)
    check(c.Status == "relaxed", "cable relaxed: " + c.Status)
    check(any("clip 'Clip'" in s for s in c.SupportsUsed),
          "the clip solid holds the cable: %s" % list(c.SupportsUsed))
    return doc, c, clip


def run_cli(*args):
    cli = ENV["CABLEFIT_CLI"]
    t0 = time.time()
    p = subprocess.run([cli] + list(args), capture_output=True, text=True)
    check(p.returncode == 0, "cablefit %s exited %d: %s" % (" ".join(args), p.returncode, p.stderr))
    return time.time() - t0


def cli_relax(cables, folder):
    """Relax input files written by the workbench, relaxed by the CLI. Returns its JSON."""
    os.makedirs(folder, exist_ok=True)
    engine.write_relax_input(cables, folder)
    seconds = run_cli("relax", os.path.join(folder, "harness.step"), "--config",
                      os.path.join(folder, "harness.json"), "--out", os.path.join(folder, "cli"),
                      "--no-pictures")
    print("cablefit relax (CLI process): %.3f s" % seconds)
    with open(os.path.join(folder, "cli", "harness.json")) as f:
        return json.load(f)


def compare_with_cli(c, cli_cable):
    sag = c.Sag.Value / 1e3
    cli_sag = cli_cable["deviation"]["max"]
    check(abs(sag - cli_sag) <= SAG_TOLERANCE, "sag %.12g m vs CLI %.12g m" % (sag, cli_sag))
    rows = cli_cable["relaxed_centreline"]["rows"]
    check(len(rows) == len(c.RelaxedPoints), "sample count %d vs CLI %d" %
          (len(c.RelaxedPoints), len(rows)))
    worst = max(max(abs(p.x / 1e3 - r[1]), abs(p.y / 1e3 - r[2]), abs(p.z / 1e3 - r[3]))
                for p, r in zip(c.RelaxedPoints, rows))
    check(worst <= SAG_TOLERANCE, "relaxed centreline differs from the CLI's by %.3g m" % worst)
    lowest = min(p.z for p in c.RelaxedPoints) / 1e3
    cli_lowest = min(r[3] for r in rows)
    check(abs(lowest - cli_lowest) <= SAG_TOLERANCE, "lowest point %.12g vs %.12g m" %
          (lowest, cli_lowest))
    print("%s: sag %.9f mm (CLI %.9f mm, |diff| %.3g m), centreline |diff| <= %.3g m" %
          (c.Label, c.Sag.Value, cli_sag * 1e3, abs(sag - cli_sag), worst))


def test_relax_vs_cli():
    doc, c, clip = build_document("relax_vs_cli")
    check(c.Sag.Value > 0.1, "the cable sags under gravity: %s" % c.Sag)
    check(abs(c.Length.Value - c.Route[0].Shape.Length) < 0.05,
          "length %s vs drawn %.4f mm" % (c.Length, c.Route[0].Shape.Length))
    folder = out_dir("relax_vs_cli")
    cli = cli_relax([c], folder)
    compare_with_cli(c, cli["cables"][0])
    t0 = time.time()
    c.touch()
    doc.recompute()
    print("recompute in FreeCAD (write STEP, relax in-process, read tube): %.3f s, solve %.3f s" %
          (time.time() - t0, c.SolveSeconds))

    # Add support at a picked point: a pin halfway along the route holds the cable up there.
    sag_before = c.Sag.Value
    mid = c.Route[0].Shape.valueAt(c.Route[0].Shape.FirstParameter + 0.25 * (
        c.Route[0].Shape.LastParameter - c.Route[0].Shape.FirstParameter))
    cable.add_support(c, "pin", point=mid)
    check(any(s.startswith("pin (harness.json)") for s in c.SupportsUsed),
          "pin support used: %s" % list(c.SupportsUsed))
    check(c.Sag.Value < sag_before, "an extra pin reduces the sag: %.4f -> %.4f mm" %
          (sag_before, c.Sag.Value))
    compare_with_cli(c, cli_relax([c], out_dir("relax_vs_cli_pin"))["cables"][0])

    # Relax harness: a second cable, both relaxed together in one input.
    spline = Part.BSplineCurve()
    spline.interpolate([FreeCAD.Vector(0, 100, 0), FreeCAD.Vector(200, 150, -20),
                        FreeCAD.Vector(400, 100, 0)])
    route2 = doc.addObject("Part::Feature", "Route2")
    route2.Shape = spline.toShape()
    c2 = cable.make_cable(route2, [], doc)
    c2.Label = "second_cable"
    c2.Material = "Stiffness"
    c2.BendingStiffness, c2.TorsionalStiffness, c2.LinearDensity = 0.02, 0.015, 0.08
    alone = {}
    for x in (c, c2):
        x.recompute()
        alone[x.Name] = list(x.RelaxedPoints)
    relaxation = cable.relax_harness(doc)
    check(len(relaxation.cables) == 2 and all(r.ok for r in relaxation.cables),
          "both cables relaxed together")
    for x in (c, c2):
        # Together, a cable near the other's clip may be solved with contact by the network
        # solver: the same equilibrium to the requested accuracy, not to round-off.
        worst = max((p - q).Length for p, q in zip(alone[x.Name], x.RelaxedPoints))
        check(worst < x.Accuracy * 1e3, "%s: harness relax = single relax (%.3g mm)" %
              (x.Label, worst))
    cli = cli_relax([c, c2], out_dir("relax_harness"))
    for x in (c, c2):
        compare_with_cli(x, next(j for j in cli["cables"] if j["name"] == x.Label))
    check("EI=0.02 " in c2.MaterialUsed, "material property used: " + c2.MaterialUsed)


def test_save_reload_step():
    doc, c, clip = build_document("save_reload")
    folder = out_dir("save_reload")
    sag, points, volume = c.Sag.Value, list(c.RelaxedPoints), c.Shape.Volume
    name, clip_name = c.Name, clip.Name
    path = os.path.join(folder, "harness.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    c, clip = doc.getObject(name), doc.getObject(clip_name)
    check(cable.is_cable(c), "the Cable proxy is restored")
    check(c.Sag.Value == sag and list(c.RelaxedPoints) == points, "outputs survive reload")
    check([s.Name for s in c.Supports] == ["Clip"] and c.Diameter.Value == 6.0,
          "inputs survive reload")
    check(abs(c.Shape.Volume - volume) < 1e-9 * volume, "shape survives reload")
    c.touch()
    doc.recompute()
    check(c.Status == "relaxed", "recomputed after reload: " + c.Status)
    check(abs(c.Sag.Value - sag) < 1e-9, "same sag after reload + recompute: %.12g vs %.12g mm" %
          (c.Sag.Value, sag))

    # STEP export through FreeCAD and read back: the tube of `cablefit relax`.
    step = os.path.join(folder, "cable.step")
    engine.export_step([c, clip], step)
    back = Part.read(step)
    check(len(back.Solids) == 2, "STEP holds the tube and the clip: %d solids" % len(back.Solids))
    tube = max(back.Solids, key=lambda s: s.Length)
    check(abs(tube.Volume - volume) < 1e-6 * volume, "tube volume %.6f vs %.6f mm^3" %
          (tube.Volume, volume))
    cli = cli_relax([c], os.path.join(folder, "cli_input"))
    cli_shape = Part.read(os.path.join(folder, "cli_input", "cli", "harness.step"))
    cli_tube = max(cli_shape.Solids, key=lambda s: s.Length)
    check(abs(cli_tube.Volume - tube.Volume) < 1e-6 * volume, "tube volume vs CLI STEP's")
    check(tube.BoundBox.isInside(cli_tube.BoundBox.Center) and
          max(abs(a - b) for a, b in zip(
              (tube.BoundBox.XMin, tube.BoundBox.YMin, tube.BoundBox.ZMin, tube.BoundBox.XMax,
               tube.BoundBox.YMax, tube.BoundBox.ZMax),
              (cli_tube.BoundBox.XMin, cli_tube.BoundBox.YMin, cli_tube.BoundBox.ZMin,
               cli_tube.BoundBox.XMax, cli_tube.BoundBox.YMax, cli_tube.BoundBox.ZMax))) < 1e-4,
          "same tube bounding box as the CLI's STEP")
    # The exported tube read by cablefit itself: its recovered centreline is the relaxed one.
    r = engine.native().relax(step, "", 1e-6, "mm", None)
    recovered = [x for x in r.cables if abs(x.diameter - 0.006) < 1e-4]
    check(len(recovered) == 1, "cablefit reads the exported tube back as a 6 mm cable: %s" %
          [(x.name, x.diameter) for x in r.cables])
    drawn = recovered[0].drawn.T * 1e3
    relaxed_line = Part.makePolygon(points)
    worst = max(relaxed_line.distToShape(Part.Vertex(FreeCAD.Vector(*p)))[0] for p in drawn)
    check(worst < 0.1, "recovered centreline within %.4f mm of the relaxed one" % worst)
    print("STEP round trip: recovered centreline within %.4f mm" % worst)


def test_colours():
    doc, c, clip = build_document("colours")
    maps = colours.colour_cables([c])
    m = maps[0]
    name, face_colours = m.Name, list(m.FaceColours)
    check(len(m.FaceColours) == len(m.Shape.Faces) > 0, "one colour per face")
    check(abs(m.ScaleMax - max(c.Deviations)) < 1e-12 and m.ScaleMin == 0, "scale 0 .. max")
    top = engine.native().deviation_colour(m.ScaleMax, 0, m.ScaleMax)
    bottom = engine.native().deviation_colour(0, 0, m.ScaleMax)
    check(sum(top) > sum(bottom) + 0.5, "viridis: the top of the scale is the bright end")
    values = list(m.SegmentDeviations)
    check(max(values) <= m.ScaleMax + 1e-12 and min(values) >= 0, "segment values on the scale")
    check(values[0] < 0.2 * max(values), "the clamped start barely deviates")
    # Tight boxes (a rational pipe surface's control net, FreeCAD's default box, reaches about 0.4
    # radii beyond the tube). The map is no shorter than the cable, and longer by at most its
    # round end segments' spheres (1.02 radii beyond each flat cap).
    d = c.DiameterUsed.Value
    longer = m.Shape.optimalBoundingBox().XLength - c.Shape.optimalBoundingBox().XLength
    check(-0.2 * d < longer < 1.02 * d + 0.2 * d,
          "the deviation map covers the cable (%.3f mm longer)" % longer)
    path = os.path.join(out_dir("colours"), "colours.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    check(list(doc.getObject(name).FaceColours) == face_colours,
          "colours survive reload")


def test_diagnose():
    doc = FreeCAD.newDocument("diagnose")
    case_dir = os.path.join(ENV["CABLEFIT_SHARED_DIR"], "cases", "public",
                            "sample-intrinsic_curvature")
    folder = out_dir("diagnose")
    t0 = time.time()
    g = diagnose.diagnose_recording(os.path.join(case_dir, "case.json"), doc, folder)
    print("diagnose in FreeCAD: %.1f s" % (time.time() - t0))
    with open(os.path.join(case_dir, "truth.json")) as f:
        truth = json.load(f)
    check(g.Effect == truth["effect"], "effect %s vs truth %s" % (g.Effect, truth["effect"]))
    with open(os.path.join(folder, "diagnosis.json")) as f:
        written = json.load(f)
    check(written["effect"] == g.Effect and abs(written["confidence"] - g.Confidence) < 1e-12,
          "diagnosis.json written by the CLI's writer agrees")
    check(os.path.exists(g.Report), "report.html written")
    names = sorted(o.Name for o in g.Group)
    check(names == ["Fitted", "Nominal", "Observation", "ScanPoints"], "shown objects %s" % names)
    check(len(doc.getObject("ScanPoints").Shape.Vertexes) > 100, "scan points shown")
    check(doc.getObject("Fitted").Shape.Length > 100, "fitted cable shown (mm)")

    # The same diagnosis.json as `cablefit diagnose` (a quick case: the CLI runs it again).
    case_dir = os.path.join(ENV["CABLEFIT_SHARED_DIR"], "cases", "public", "sample-none")
    diagnose.diagnose_recording(os.path.join(case_dir, "case.json"), doc,
                                os.path.join(folder, "mine"))
    run_cli("diagnose", case_dir, "--out", os.path.join(folder, "cli"))
    with open(os.path.join(folder, "mine", "diagnosis.json")) as f:
        mine = json.load(f)
    with open(os.path.join(folder, "cli", "sample-none", "diagnosis.json")) as f:
        cli = json.load(f)
    # Two runs differ only in when and by which command line they were made.
    for d in (mine, cli):
        for key in ("date", "command_line"):
            d["provenance"].pop(key)
    check(mine == cli, "diagnosis.json equals the CLI's (but for its date and command line)")


def test_report():
    doc, c, clip = build_document("report")
    folder = out_dir("report")
    report = engine.export_report([c], folder, pictures=True)
    check(os.path.exists(report) and os.path.getsize(report) > 1000, "report.html written")
    for f in ("harness.step", "harness.json", "harness-deviation.png"):
        check(os.path.exists(os.path.join(folder, f)), f + " written")
    with open(os.path.join(folder, "harness.json")) as f:
        mine = json.load(f)
    check(mine["format"] == "cablefit-relax/1", "relax JSON written")
    compare_with_cli(c, mine["cables"][0])
    html = open(report).read()
    check("main_cable" in html and "harness-deviation.png" in html, "report names cable + picture")


def test_errors():
    doc, c, clip = build_document("errors")
    sag = c.Sag.Value
    c.Material = "Section file"
    c.SectionFile = "/nonexistent/section.json"
    doc.recompute()  # must not raise: the problem goes to the report view
    check(c.Status.startswith("failed: ") and "section.json" in c.Status,
          "a bad section file is reported on the cable: " + c.Status)
    check(c.Sag.Value == sag and c.Shape.Volume > 0, "the last good shape is kept")
    c.Material = "Default bundle"
    doc.recompute()
    check(c.Status == "relaxed", "recovers once fixed: " + c.Status)
    try:
        engine.native().relax("/nonexistent/h.step")
        check(False, "a missing file raises")
    except engine.native().Error as e:
        check("/nonexistent/h.step" in str(e) and "\n" not in str(e), "one line naming the file")
    step = os.path.join(out_dir("errors"), "h.step")
    engine.export_step([c.Route[0], clip], step)
    stages = []
    r = engine.native().relax(step, "", 1e-6, "mm", lambda f, s: stages.append(s) or False)
    check(not r.cables[0].ok and r.cables[0].error == "cancelled", "progress False cancels")
    r = engine.native().relax(step, "", 1e-6, "mm", None, 1e-9)
    check(not r.cables[0].ok and "timed out" in r.cables[0].error,
          "a solve past its timeout fails: %r" % r.cables[0].error)

    def boom(f, s):
        raise KeyError("user pressed Esc")
    try:
        engine.native().relax(step, "", 1e-6, "mm", boom)
        check(False, "an exception in progress propagates")
    except KeyError:
        pass
    from cablefit_workbench import gui_progress
    bar = gui_progress.ProgressBar("test")  # FreeCAD's progress indicator, as the GUI uses it
    r = engine.native().relax(step, "", 1e-6, "mm", bar)
    check(r.cables[0].ok and not bar._open, "FreeCAD's progress indicator drives a relax")
    seen = []
    r = engine.native().relax(step, "", 1e-6, "mm", lambda f, s: seen.append(f) or True)
    check(r.cables[0].ok and seen[0] == 0.0 and seen[-1] == 1.0 and seen == sorted(seen),
          "progress runs 0 -> 1 monotonically")


def test_tube_source():
    """Make physical on a tube solid (a circle swept along a spline): cablefit recovers its
    centreline and diameter, and the relax equals the CLI's on the same file."""
    doc = FreeCAD.newDocument("tube")
    s = Part.BSplineCurve()
    s.interpolate([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(150, 40, 20),
                   FreeCAD.Vector(300, 0, 30), FreeCAD.Vector(450, -30, 0)])
    circle = Part.Wire(Part.makeCircle(4, s.value(s.FirstParameter), s.tangent(s.FirstParameter)[0]))
    tube = doc.addObject("Part::Feature", "Tube")
    tube.Shape = Part.Wire(s.toShape()).makePipeShell([circle], True, True)
    c = cable.make_cable(tube, [], doc)
    c.Label = "hose"
    doc.recompute()
    check(c.Status == "relaxed", "tube cable relaxed: " + c.Status)
    check(abs(c.DiameterUsed.Value - 8.0) < 0.01, "diameter recovered: %s" % c.DiameterUsed)
    check(abs(c.Length.Value - s.length()) < 0.5, "centreline length %s vs %.3f mm" %
          (c.Length, s.length()))
    compare_with_cli(c, cli_relax([c], out_dir("tube_source"))["cables"][0])


def test_kbl_file():
    """A KBL harness relaxed in FreeCAD as the CLI relaxes it: every segment a tube in the
    document, the same largest deviations as `cablefit relax`."""
    path = os.path.join(ENV["CABLEFIT_SHARED_DIR"], "kbl",
                        "kblxml_2.3sr-1_000971619_ltgs_movo_170718.kbl")
    doc = FreeCAD.newDocument("kbl")
    relaxation, group = engine.relax_file(path, doc)
    check(len(relaxation.cables) == 30, "30 segments: %d" % len(relaxation.cables))
    failed = [r.name for r in relaxation.cables if not r.ok]
    check(not failed, "every segment relaxed: failed %s" % failed)
    check(len(group.Group) == 30, "30 objects in the group: %d" % len(group.Group))
    check(all(o.Shape.Solids for o in group.Group), "every cable is a tube")
    folder = out_dir("kbl_file")
    run_cli("relax", path, "--out", folder, "--no-pictures", "--quiet")
    with open(os.path.join(folder, os.path.splitext(os.path.basename(path))[0] + ".json")) as f:
        cli = {c["name"]: c for c in json.load(f)["cables"]}
    worst = max(abs(r.max_deviation - cli[r.name]["deviation"]["max"]) for r in relaxation.cables)
    check(worst < 1e-9, "largest deviations as the CLI's within %.3g m" % worst)
    print("KBL in FreeCAD: 30 tubes, deviations as the CLI's within %.3g m" % worst)


def sample_lagrange(s, points, at):
    """`points` (3 x n, m) at arc lengths `s` (n) resampled at `at` by cubic Lagrange through the
    four samples around each point: the rule of SampleCenterline (core/solver), by which the CLI
    thins every pose's centreline for its JSON."""
    import numpy
    n = len(s)
    out = numpy.zeros((3, len(at)))
    for k, x in enumerate(at):
        x = min(max(x, s[0]), s[n - 1])
        i = min(max(int(numpy.searchsorted(s, x, side="right")) - 1, 0), n - 2)
        lo = min(max(i - 1, 0), max(0, n - 4))
        hi = min(n - 1, lo + 3)
        for a in range(lo, hi + 1):
            w = 1.0
            for b in range(lo, hi + 1):
                if b != a:
                    w *= (x - s[b]) / (s[a] - s[b])
            out[:, k] += w * points[:, a]
    return out


def test_motion_vs_cli():
    """The door-hinge sample relaxed and swept in FreeCAD: the same poses, bend radii and shapes
    as `cablefit relax --config door_hinge.json` writes, there and back to the start shape, and
    each pose shown on the cable's object as its tube at that pose."""
    import numpy
    samples = os.path.normpath(os.path.join(ENV["CABLEFIT_SHARED_DIR"], "..", "..", "samples",
                                            "harness"))
    path = os.path.join(samples, "door_hinge.stl")
    config = os.path.join(samples, "door_hinge.json")
    doc = FreeCAD.newDocument("motion")
    t0 = time.time()
    sweep = motion.sweep_file(path, config, doc)
    seconds = time.time() - t0
    m = sweep.motion
    folder = out_dir("motion_vs_cli")
    run_cli("relax", path, "--config", config, "--out", folder, "--no-pictures", "--quiet")
    with open(os.path.join(folder, "door_hinge.json")) as f:
        cli = json.load(f)
    cli_motion = cli["motion"]
    check(m.kind == "rotation" and m.unit == "rad", "a rotation in rad: %s %s" % (m.kind, m.unit))
    check(len(m.q) == 31 and len(m.q) == len(cli_motion["parameters"]),
          "15 steps there and back: %d poses, CLI %d" % (len(m.q), len(cli_motion["parameters"])))
    worst_q = max(abs(math.degrees(q) - c) for q, c in zip(m.q, cli_motion["parameters"]))
    check(worst_q < 1e-9, "pose parameters as the CLI's within %.3g deg" % worst_q)
    check(abs(math.degrees(m.q[15]) - 75) < 1e-9 and m.q[0] == 0 and m.q[-1] == 0,
          "0 -> 75 -> 0 deg: %s" % [math.degrees(q) for q in m.q])
    check(not m.problems, "no motion problems: %s" % list(m.problems))
    check([c.name for c in m.cables] == cli_motion["cables"] == ["door_hinge#1"],
          "the door cable is swept: %s (CLI %s)" % ([c.name for c in m.cables],
                                                    cli_motion["cables"]))
    swept = m.cables[0]
    cli_cable = [c for c in cli["cables"] if c["name"] == swept.name][0]["motion"]
    check(swept.completed and cli_cable["completed"], "sweep completed: %s" % swept.message)
    check(len(swept.poses) == len(cli_cable["poses"]) == 31, "31 poses solved")
    worst_bend = worst_shape = 0.0
    for k, (p, c) in enumerate(zip(swept.poses, cli_cable["poses"])):
        check(p.converged == c["converged"] and p.stable == c["stable"] and
              p.branch_lost == c["branch_lost"], "pose %d: flags as the CLI's" % k)
        worst_bend = max(worst_bend, abs(p.min_bend_radius - c["min_bend_radius"]["radius"]))
        check(p.bend_flag == c["min_bend_radius"]["flag"], "pose %d: bend flag" % k)
        rows = numpy.array(c["centreline"]["rows"])
        mine = sample_lagrange(p.s, p.centreline, rows[:, 0])
        worst_shape = max(worst_shape, float(numpy.abs(mine - rows[:, 1:].T).max()))
        check(p.clearance_to == c["clearance"]["to"] and
              abs(p.clearance - c["clearance"]["clearance"]) <= SAG_TOLERANCE,
              "pose %d: least clearance %.9g m to %s, CLI %s" % (k, p.clearance, p.clearance_to,
                                                                 c["clearance"]))
    check(worst_bend <= SAG_TOLERANCE, "min bend radii differ from the CLI's by %.3g m" %
          worst_bend)
    check(worst_shape <= SAG_TOLERANCE, "pose centrelines differ from the CLI's by %.3g m" %
          worst_shape)
    # The door moves the cable: a pose that did not follow it would pass the CLI comparison only
    # if the CLI did not follow either.
    opened = float(numpy.abs(swept.poses[15].centreline - swept.poses[0].centreline).max())
    check(opened > 0.05, "the open door moves the cable by %.3f m" % opened)
    back = float(numpy.abs(swept.poses[-1].centreline - swept.poses[0].centreline).max())
    check(back <= SAG_TOLERANCE and swept.back_to_start <= SAG_TOLERANCE,
          "closed again, the cable is back at its start shape: %.3g m (back_to_start %.3g m)" %
          (back, swept.back_to_start))
    # Each pose on the object: the tube around that pose's centreline (mm), and not around the
    # others' (the open door's cable leaves the closed door's tube).
    obj = sweep.objects[0]
    for k in (0, 15, 30):
        t0 = time.time()
        sweep.show(k)
        shown = time.time() - t0
        centre = swept.poses[k].centreline * engine.MM
        outside = [j for j in range(0, centre.shape[1], 10)
                   if not obj.Shape.isInside(FreeCAD.Vector(*centre[:, j]), 1e-3, True)]
        check(not outside, "pose %d: centreline samples %s outside the shown tube" % (k, outside))
        other = swept.poses[15 if k != 15 else 0].centreline * engine.MM
        mid = FreeCAD.Vector(*other[:, other.shape[1] // 2])
        check(not obj.Shape.isInside(mid, 1e-3, True), "pose %d: the tube is that pose's" % k)
        print("pose %d shown in %.3f s: %s" % (k, shown, sweep.describe(k).replace("\n", " | ")))
    sweep.show(15)
    open_box = obj.Shape.BoundBox
    sweep.restore()
    check(obj.Shape.BoundBox.XMax != open_box.XMax, "restore puts the relaxed tube back")
    print("motion in FreeCAD: relax + sweep %.3f s (sweep %.3f s), 31 poses; bend radii within "
          "%.3g m, centrelines within %.3g m of the CLI's; back to start %.3g m" %
          (seconds, m.seconds, worst_bend, worst_shape, back))


TESTS = {"kbl_file": test_kbl_file, "motion_vs_cli": test_motion_vs_cli,
         "relax_vs_cli": test_relax_vs_cli, "save_reload_step": test_save_reload_step,
         "colours": test_colours, "diagnose": test_diagnose, "report": test_report,
         "errors": test_errors, "tube_source": test_tube_source}


def main():
    name = ENV.get("CABLEFIT_FC_CASE", "")
    if name not in TESTS:
        print("CABLEFIT_FC_CASE must be one of %s" % sorted(TESTS))
        sys.exit(2)
    try:
        t0 = time.time()
        TESTS[name]()
        print("PASS %s (%.1f s)" % (name, time.time() - t0))
    except Exception:
        traceback.print_exc()
        print("FAIL %s" % name)
        sys.stdout.flush()
        os._exit(1)
    sys.stdout.flush()
    os._exit(0)


main()
