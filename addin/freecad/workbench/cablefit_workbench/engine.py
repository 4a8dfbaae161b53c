# The non-GUI code path of every command: the drawn cables and their support solids are written
# to a STEP file plus a harness.json (the same two inputs `cablefit relax INPUT --config` takes),
# relaxed by the C++ module `cablefit_native` (the CLI's own code, in-process), and the results
# written back into FreeCAD shapes and properties. FreeCAD works in millimetres, cablefit in
# metres: every conversion happens in this file.
import json
import os
import shutil
import tempfile

import FreeCAD
import Part

MM = 1000.0  # millimetres per metre

_native = None


def native():
    """The C++ module, imported on first use so the workbench loads even when it is missing."""
    global _native
    if _native is None:
        try:
            import cablefit_native
        except ImportError as e:
            raise RuntimeError(
                "cablefit_native is not installed: build it (cmake --build BUILD --target "
                "cablefit_native) and run tools/install-freecad-workbench.sh BUILD (%s)" % e)
        _native = cablefit_native
    return _native


class Cancelled(Exception):
    """The user stopped a long solve."""


def route_shape(cable):
    """The drawn route of a Cable object: the linked edges/wire, or the linked tube solid."""
    link = cable.Route
    if link is None:
        raise ValueError("%s: no drawn route linked" % cable.Label)
    obj, subs = link[0], [s for s in link[1] if s]
    if subs:
        edges = [obj.getSubObject(s) for s in subs]
        edges = [e for e in edges if isinstance(e, Part.Edge)]
        if not edges:
            raise ValueError("%s: the linked sub-elements of %s are not edges" %
                             (cable.Label, obj.Label))
        return Part.Wire(Part.__sortEdges__(edges)) if len(edges) > 1 else edges[0]
    shape = obj.Shape
    if shape.isNull():
        raise ValueError("%s: %s has no shape" % (cable.Label, obj.Label))
    return shape.copy()


def _material(cable):
    kind = cable.Material
    if kind == "Stiffness":
        return {"bending_stiffness": cable.BendingStiffness,
                "torsional_stiffness": cable.TorsionalStiffness,
                "linear_density": cable.LinearDensity}
    if kind == "Section file":
        if not cable.SectionFile:
            raise ValueError("%s: Material is 'Section file' but SectionFile is empty" %
                             cable.Label)
        return {"section": os.path.abspath(cable.SectionFile)}
    return None  # the CLI's default bundle estimate


def cable_config(cable):
    """The harness.json entry (cablefit-harness/1, metres) of one Cable object."""
    entry = {"auto_clips": bool(cable.AutoClips)}
    if cable.Diameter.Value > 0:
        entry["diameter"] = cable.Diameter.Value / MM
    material = _material(cable)
    if material:
        entry["material"] = material
    g = cable.Gravity
    entry["gravity"] = [g.x, g.y, g.z]
    entry["start"] = cable.StartSupport
    entry["end"] = cable.EndSupport
    kinds = list(cable.SupportKinds)
    supports = []
    for i, p in enumerate(cable.SupportPoints):
        kind = kinds[i] if i < len(kinds) else "clip"
        supports.append({"kind": kind, "point": [p.x / MM, p.y / MM, p.z / MM]})
    if supports:
        entry["supports"] = supports
    return entry


def _unique_labels(cables):
    names = {}
    for c in cables:
        if c.Label in names.values():
            raise ValueError("two cables are labelled '%s': labels name the cables in the relax "
                             "input, rename one" % c.Label)
        names[c.Name] = c.Label
    return names


def write_relax_input(cables, folder):
    """Writes folder/harness.step (the drawn routes named by the cables' labels, plus every
    support solid) and folder/harness.json. Returns (step path, config path)."""
    _unique_labels(cables)
    doc = FreeCAD.newDocument("cablefit_export", hidden=True, temp=True)
    try:
        objs = []
        for c in cables:
            o = doc.addObject("Part::Feature", "Route")
            o.Shape = route_shape(c)
            o.Label = c.Label
            objs.append(o)
        seen = set()
        for c in cables:
            for s in c.Supports:
                if s.Name in seen:
                    continue
                seen.add(s.Name)
                o = doc.addObject("Part::Feature", "Solid")
                o.Shape = s.Shape.copy()
                o.Label = s.Label
                objs.append(o)
        step = os.path.join(folder, "harness.step")
        import Import
        Import.export(objs, step)
    finally:
        FreeCAD.closeDocument(doc.Name)
    config = {"format": "cablefit-harness/1",
              "note": "written by the FreeCAD workbench from the Cable objects' properties",
              "cables": {c.Label: cable_config(c) for c in cables}}
    if cables:
        config["min_bend_radius_factor"] = cables[0].MinBendRadiusFactor
    path = os.path.join(folder, "harness.json")
    with open(path + ".tmp", "w") as f:
        json.dump(config, f, indent=1)
    os.replace(path + ".tmp", path)
    return step, path


def _match(result_cables, label):
    """Index of the relaxed cable drawn for `label` (a shape with k routes gives label#1..k:
    the first is the one the Cable object owns)."""
    for i, r in enumerate(result_cables):
        if r.name == label:
            return i
    for i, r in enumerate(result_cables):
        if r.name.split("#")[0] == label:
            return i
    return -1


def relax(cables, progress=None, keep_folder=None):
    """Relaxes `cables` (Cable objects) together, as `cablefit relax` relaxes one file, and stores
    each result in its object. Returns (relaxation, {cable Name: index in relaxation.cables}).
    `progress(fraction, stage)` returning False cancels. With `keep_folder` the input files
    (harness.step, harness.json) are written there and kept."""
    scratch = tempfile.mkdtemp(prefix="cablefit-")
    try:
        step, config = write_relax_input(cables, keep_folder or scratch)
        accuracy = min(c.Accuracy for c in cables) if cables else 1e-6
        timeout = max(c.Timeout for c in cables) if cables else 0.0
        relaxation = native().relax(step, config, accuracy, "mm", progress, timeout)
        index = {}
        for c in cables:
            i = _match(relaxation.cables, c.Label)
            if i < 0:
                raise ValueError("%s: the relax input held no cable of that name (found %s)" %
                                 (c.Label, ", ".join(r.name for r in relaxation.cables)))
            index[c.Name] = i
            store(c, relaxation.cables[i], tube_shape(relaxation, i, scratch))
        return relaxation, index
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def relax_file(path, doc, config="", progress=None):
    """Relaxes a harness file as `cablefit relax PATH --config CONFIG` does (STEP, IGES, KBL or
    a mesh in mm) and adds its cables to `doc` in a group named after the file: each relaxed
    cable as its tube, labelled with its name, with its largest deviation and status; a failed
    one as its drawn route. Returns (relaxation, group)."""
    relaxation = native().relax(path, config, 0.0, "mm", progress)  # the CLI's default accuracy
    stem = os.path.splitext(os.path.basename(path))[0]
    group = doc.addObject("App::DocumentObjectGroup", "Harness")
    group.Label = stem
    scratch = tempfile.mkdtemp(prefix="cablefit-")
    try:
        for i, r in enumerate(relaxation.cables):
            o = doc.addObject("Part::Feature", "Relaxed")
            o.Label = r.name
            o.addProperty("App::PropertyString", "Status", "Cablefit", "relaxed, or why not")
            o.addProperty("App::PropertyLength", "MaxDeviation", "Cablefit",
                          "Largest distance of the relaxed cable to its drawn route")
            o.addProperty("App::PropertyLength", "Diameter", "Cablefit", "Diameter used")
            o.Status = "relaxed" if r.ok else "failed: " + r.error
            o.Diameter = r.diameter * MM
            if r.ok:
                o.Shape = tube_shape(relaxation, i, scratch)
                o.MaxDeviation = r.max_deviation * MM
            elif r.drawn.shape[1] >= 2:
                o.Shape = polyline_shape(r.drawn)
            group.addObject(o)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    doc.recompute()
    return relaxation, group


def tube_shape(relaxation, i, folder, pose=-1):
    """Cable `i` of `relaxation` as a FreeCAD shape (mm): its tube swept by cablefit's own STEP
    writer, the one `cablefit relax` writes, along the relaxed centreline or, with `pose` >= 0,
    along that pose's centreline of the motion. `folder` holds the intermediate STEP file."""
    name = "tube-%d.step" % i if pose < 0 else "tube-%d-pose-%d.step" % (i, pose)
    tube = os.path.join(folder, name)
    relaxation.write_step(tube, False, i, pose)
    return Part.read(tube)


def polyline_shape(points):
    """A centreline (numpy 3 x n, metres) as a FreeCAD polyline (mm): a cable with no tube."""
    return Part.makePolygon([FreeCAD.Vector(*(MM * p)) for p in points.T])


def store(cable, r, tube):
    """Writes one relaxed cable into the object's output properties (kept in the .FCStd, so a
    reloaded document shows and colours it without solving again)."""
    cable.Status = "relaxed" if r.ok else "failed: " + r.error
    cable.Length = r.length * MM
    cable.Shape = tube
    if not r.ok:
        cable.RelaxedPoints = []
        cable.Deviations = []
        return
    cable.DiameterUsed = r.diameter * MM
    cable.Sag = r.max_deviation * MM
    cable.RmsDeviation = r.rms_deviation * MM
    cable.MinBendRadius = min(r.min_bend_radius * MM, 1e12)
    cable.BendTooTight = bool(r.bend_flag)
    cable.Stable = bool(r.stable)
    cable.SolveSeconds = r.seconds
    cable.RelaxedPoints = [FreeCAD.Vector(*(MM * p)) for p in r.relaxed.T]
    cable.Deviations = [float(d) * MM for d in r.deviation]
    cable.SupportsUsed = ["%s (%s) at s=%.1f mm" % (s.kind, s.origin, s.s * MM)
                          for s in r.supports]
    cable.MaterialUsed = "%s: EI=%.4g N m^2, %.4g kg/m" % (
        r.material_source, r.bending_stiffness, r.linear_density)


def export_report(cables, folder, pictures=True, progress=None):
    """Relaxes `cables` and writes what `cablefit relax harness.step --config harness.json
    --out FOLDER` writes (plus those two inputs). Returns the report.html path."""
    os.makedirs(folder, exist_ok=True)
    relaxation, _ = relax(cables, progress, keep_folder=folder)
    return relaxation.write_report(folder, pictures)


def export_step(objects, path):
    """Exports document objects (cables as their relaxed tubes) to STEP through FreeCAD."""
    import Import
    Import.export(list(objects), path)
