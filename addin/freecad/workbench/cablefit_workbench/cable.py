# The parametric Cable object: a drawn route (edges, a wire or a tube solid) made physical.
# Inputs are ordinary properties (diameter, material, supports, gravity ...), so they survive
# save/reload; recomputing relaxes the cable through engine.relax and stores the relaxed tube as
# the object's Shape and the measures as read-only output properties.
import FreeCAD

from . import engine

END_KINDS = ["clamp", "clip", "pin", "free"]
SUPPORT_KINDS = ["clamp", "clip", "pin"]
MATERIALS = ["Default bundle", "Stiffness", "Section file"]

# (type, name, group, tooltip, default); defaults are the CLI's (harness.json absent).
_INPUTS = [
    ("App::PropertyLinkSub", "Route", "Cable", "Drawn route: edges, a wire or a tube solid", None),
    ("App::PropertyLength", "Diameter", "Cable",
     "Bundle diameter; 0 = as drawn (tube) or the default 8 mm", 0.0),
    ("App::PropertyEnumeration", "Material", "Material",
     "Default bundle: E = 75 MPa, 2000 kg/m^3 disc of the diameter; Stiffness: the three values "
     "below; Section file: a cablefit section.json", MATERIALS),
    ("App::PropertyFloat", "BendingStiffness", "Material", "EI [N m^2] (Material = Stiffness)",
     0.05),
    ("App::PropertyFloat", "TorsionalStiffness", "Material", "GJ [N m^2] (Material = Stiffness)",
     0.04),
    ("App::PropertyFloat", "LinearDensity", "Material", "Mass per length [kg/m]", 0.1),
    ("App::PropertyFile", "SectionFile", "Material", "section.json (Material = Section file)", ""),
    ("App::PropertyEnumeration", "StartSupport", "Supports",
     "How the start of the route is held (at its drawn pose)", END_KINDS),
    ("App::PropertyEnumeration", "EndSupport", "Supports",
     "How the end of the route is held (at its drawn pose)", END_KINDS),
    ("App::PropertyLinkList", "Supports", "Supports",
     "Solids (clips, grommets, rings) the cable is held by where it passes through them", []),
    ("App::PropertyVectorList", "SupportPoints", "Supports",
     "Extra supports at the route point nearest each point [mm]", []),
    ("App::PropertyStringList", "SupportKinds", "Supports",
     "clamp / clip / pin for each of SupportPoints", []),
    ("App::PropertyBool", "AutoClips", "Supports",
     "Also clip where the route passes through any of Supports' solids (else only points)", True),
    ("App::PropertyVector", "Gravity", "Loads", "Gravity [m/s^2] in the document frame",
     FreeCAD.Vector(0, 0, -9.81)),
    ("App::PropertyFloat", "Accuracy", "Solver", "Requested accuracy of the relaxed shape [m]",
     1e-6),
    ("App::PropertyFloat", "Timeout", "Solver",
     "Seconds a solve may take before it is reported as failed (0 = no limit)", 60.0),
    ("App::PropertyFloat", "MinBendRadiusFactor", "Solver",
     "Flag bends tighter than this many diameters", 5.0),
]

# Outputs: read-only in the editor, not triggering a recompute when written.
_OUTPUTS = [
    ("App::PropertyString", "Status", "Result", "relaxed, or the one-line failure"),
    ("App::PropertyLength", "Length", "Result", "Length of the drawn route"),
    ("App::PropertyLength", "DiameterUsed", "Result", "Diameter the solve used"),
    ("App::PropertyLength", "Sag", "Result",
     "Largest distance of the relaxed centreline from the drawn route"),
    ("App::PropertyLength", "RmsDeviation", "Result", "RMS distance to the drawn route"),
    ("App::PropertyLength", "MinBendRadius", "Result", "Tightest bend radius of the relaxed cable"),
    ("App::PropertyBool", "BendTooTight", "Result", "Min bend radius < factor x diameter"),
    ("App::PropertyBool", "Stable", "Result", "The equilibrium is stable"),
    ("App::PropertyFloat", "SolveSeconds", "Result", "Wall time of the solve [s]"),
    ("App::PropertyString", "MaterialUsed", "Result", "Material source and values"),
    ("App::PropertyStringList", "SupportsUsed", "Result", "Supports the solver used"),
    ("App::PropertyVectorList", "RelaxedPoints", "Result", "Relaxed centreline samples [mm]"),
    ("App::PropertyFloatList", "Deviations", "Result",
     "Distance of each relaxed sample to the drawn route [mm]"),
]


class CableFeature:
    """Proxy of a Part::FeaturePython 'Cable'."""

    def __init__(self, obj):
        obj.Proxy = self
        self.ensure_properties(obj)

    @staticmethod
    def ensure_properties(obj):
        for kind, name, group, tip, default in _INPUTS:
            if name in obj.PropertiesList:
                continue
            obj.addProperty(kind, name, group, tip)
            if kind == "App::PropertyEnumeration":
                setattr(obj, name, default)
                setattr(obj, name, default[0])
            elif default is not None:
                setattr(obj, name, default)
        for kind, name, group, tip in _OUTPUTS:
            if name in obj.PropertiesList:
                continue
            obj.addProperty(kind, name, group, tip)
            obj.setEditorMode(name, 1)  # read-only
            obj.setPropertyStatus(name, "Output")

    def onDocumentRestored(self, obj):
        self.ensure_properties(obj)  # documents saved by an older workbench

    def execute(self, obj):
        """Relaxes this cable alone. A failure is reported, never raised: the document keeps
        its last good shape and stays usable."""
        try:
            engine.relax([obj], progress_for(obj.Label))
        except engine.Cancelled:
            obj.Status = "cancelled"
            FreeCAD.Console.PrintWarning("cablefit: %s: relax cancelled\n" % obj.Label)
        except Exception as e:  # noqa: BLE001 - every problem goes to the report view
            obj.Status = "failed: %s" % e
            FreeCAD.Console.PrintError("cablefit: %s: %s\n" % (obj.Label, e))

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


def progress_for(label):
    """A progress callable for the C++ solve: FreeCAD's progress indicator (Esc cancels) in the
    GUI, None headless."""
    if not FreeCAD.GuiUp:
        return None
    from . import gui_progress
    return gui_progress.ProgressBar("cablefit: relax " + label)


def make_cable(route_obj, subelements=(), doc=None, name="Cable"):
    """Creates a Cable for `route_obj` (its `subelements` edges, or its whole shape) and
    recomputes it. Returns the new object."""
    doc = doc or FreeCAD.ActiveDocument
    obj = doc.addObject("Part::FeaturePython", name)
    CableFeature(obj)
    obj.Route = (route_obj, list(subelements))
    if FreeCAD.GuiUp:
        from . import view_providers
        view_providers.CableViewProvider(obj.ViewObject)
        route_obj.ViewObject.Visibility = False
    obj.recompute()
    return obj


def add_support(cable, kind="clip", point=None, solid=None):
    """Adds a support: a clamp/clip/pin at the route point nearest `point` (FreeCAD.Vector, mm),
    or the clip where the route passes through `solid`. Recomputes the cable."""
    if kind not in SUPPORT_KINDS:
        raise ValueError("support kind must be one of %s, got %r" % (SUPPORT_KINDS, kind))
    if (point is None) == (solid is None):
        raise ValueError("add_support needs exactly one of point or solid")
    if solid is not None:
        if solid not in cable.Supports:
            cable.Supports = list(cable.Supports) + [solid]
        cable.AutoClips = True
    else:
        cable.SupportPoints = list(cable.SupportPoints) + [FreeCAD.Vector(point)]
        cable.SupportKinds = list(cable.SupportKinds) + [kind]
    cable.recompute()


def is_cable(obj):
    return obj is not None and getattr(obj, "Proxy", None).__class__.__name__ == "CableFeature"


def cables_of(doc):
    return [o for o in doc.Objects if is_cable(o)]


def relax_harness(doc, progress=None):
    """Relaxes every Cable of `doc` together, in one relax input: ends that meet become one
    junction (branched bundles when the core solves them). Returns the relaxation."""
    cables = cables_of(doc)
    if not cables:
        raise ValueError("the document has no Cable: use Make physical first")
    relaxation, _ = engine.relax(cables, progress)
    for c in cables:
        c.purgeTouched()  # results are current: no second solve on the next recompute
    return relaxation
