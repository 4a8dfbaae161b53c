# Deviation colours: a relaxed cable shown as a chain of short tube segments, each coloured by the
# distance of the relaxed centreline to the drawn route there, on the colour scale of the
# `cablefit relax` pictures (viridis, 0 .. the largest deviation of the coloured cables). The
# segments form a separate 'DeviationMap' object (the Cable's own Shape stays the one exported
# tube); the colour list and the scale are properties, so a reloaded document keeps them.
import FreeCAD
import Part

from . import engine

SEGMENTS = 64


def _segment_values(deviations, segments):
    """Mean deviation of each of `segments` equal runs of samples [same unit]."""
    n = len(deviations)
    out = []
    for k in range(segments):
        a = k * (n - 1) // segments
        b = max(a + 1, (k + 1) * (n - 1) // segments)
        run = deviations[a:b + 1]
        out.append(sum(run) / len(run))
    return out


def segmented_tube(points, diameter, segments):
    """`segments` cylinders along the polyline `points` (FreeCAD.Vector, mm), each over an equal
    share of the samples (a cylinder per sample step), with balls at the joints so bends show no gaps. Returns
    (compound, faces per segment)."""
    n = len(points)
    solids, faces = [], []
    r = diameter / 2
    for k in range(segments):
        a = k * (n - 1) // segments
        b = max(a + 1, (k + 1) * (n - 1) // segments)
        parts = []
        for i in range(a, b):
            d = points[i + 1] - points[i]
            if d.Length > 1e-9:
                parts.append(Part.makeCylinder(r, d.Length, points[i], d))
        parts.append(Part.makeSphere(r, points[b]))
        seg = Part.makeCompound(parts)  # a boolean fuse would cost seconds and show nothing
        solids.append(seg)
        faces.append(len(seg.Faces))
    return Part.makeCompound(solids), faces


def deviation_scale(cables):
    """(lo, hi) [mm] of the colour scale shared by `cables`."""
    hi = max((max(c.Deviations) for c in cables if c.Deviations), default=0.0)
    return 0.0, max(hi, 1e-6)


def make_deviation_map(cable, scale=None, segments=SEGMENTS, doc=None):
    """Creates (or updates) the DeviationMap of a relaxed Cable. Returns the map object, with
    FaceColours (one RGB per face of its Shape), ScaleMin/ScaleMax [mm] and SegmentDeviations."""
    if not cable.Deviations or len(cable.RelaxedPoints) < 2:
        raise ValueError("%s is not relaxed (%s): recompute it first" % (cable.Label, cable.Status))
    doc = doc or cable.Document
    lo, hi = scale or deviation_scale([cable])
    name = cable.Name + "_deviation"
    m = doc.getObject(name)
    if m is None:
        m = doc.addObject("Part::Feature", name)
        m.addProperty("App::PropertyLink", "Cable", "Deviation", "The coloured cable")
        m.addProperty("App::PropertyFloat", "ScaleMin", "Deviation", "Bottom of the scale [mm]")
        m.addProperty("App::PropertyFloat", "ScaleMax", "Deviation", "Top of the scale [mm]")
        m.addProperty("App::PropertyFloatList", "SegmentDeviations", "Deviation",
                      "Mean deviation of each segment [mm]")
        m.addProperty("App::PropertyStringList", "FaceColours", "Deviation",
                      "r g b (0..1) of each face of the Shape")
    m.Label = cable.Label + " deviation"
    m.Cable = cable
    points = list(cable.RelaxedPoints)
    segments = max(1, min(segments, len(points) - 1))
    values = _segment_values(list(cable.Deviations), segments)
    shape, faces = segmented_tube(points, cable.DiameterUsed.Value * 1.02, segments)
    colours = []
    for v, nf in zip(values, faces):
        rgb = engine.native().deviation_colour(v, lo, hi)
        colours += [tuple(rgb)] * nf
    m.Shape = shape
    m.ScaleMin, m.ScaleMax = lo, hi
    m.SegmentDeviations = values
    m.FaceColours = ["%.6f %.6f %.6f" % c for c in colours]
    if FreeCAD.GuiUp:
        apply_colours(m)
        cable.ViewObject.Visibility = False
    return m


def apply_colours(deviation_map):
    vo = deviation_map.ViewObject
    vo.DisplayMode = "Shaded"  # the segments' seam and joint edges would hide the colours
    colours = [tuple(float(x) for x in s.split()) for s in deviation_map.FaceColours]
    if len(colours) == len(deviation_map.Shape.Faces):
        vo.DiffuseColor = colours


def colour_cables(cables):
    """Deviation maps of `cables` on one shared scale; returns them and shows the legend."""
    relaxed = [c for c in cables if c.Deviations]
    if not relaxed:
        raise ValueError("no relaxed cable to colour: recompute or Relax harness first")
    scale = deviation_scale(relaxed)
    maps = [make_deviation_map(c, scale) for c in relaxed]
    if FreeCAD.GuiUp:
        from . import legend
        legend.show(scale, "deviation [mm]")
    for c in relaxed:
        FreeCAD.Console.PrintMessage("cablefit: %s: max deviation %.3f mm, rms %.3f mm\n" %
                                     (c.Label, c.Sag.Value, c.RmsDeviation.Value))
    return maps
