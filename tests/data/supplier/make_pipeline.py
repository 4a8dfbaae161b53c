# FreeCAD (freecadcmd) script: a pipeline drawn as an assembly of solids, exported to STEP with
# their names (pipeline.step): DN 50 pipes (60.3 mm, 52.5 mm bore) - pipe_A with a slip-on flange
# (8 bolt holes) at its start, welded to elbow_1 (90 degrees, 1.5 diameters bend radius); pipe_B
# between elbow_1 and elbow_2, no flange; pipe_C up from elbow_2 to a flange - and beside them a
# flexible hose of the same size, bent, between two flanges of its own, and a 6 mm sensor cable.
import math
import FreeCAD as App
import Import
import Part
from FreeCAD import Vector as V

doc = App.newDocument("pipeline")
OD, ID = 60.3, 52.5
FD, FT, BC, BH = 165.0, 20.0, 125.0, 18.0   # flange diameter, thickness, bolt circle, bolt hole
def pipe(p, d, L, od=OD, idi=ID):
    return Part.makeCylinder(od/2, L, p, d).cut(Part.makeCylinder(idi/2, L, p, d))
def flange(p, d):
    # slip-on flange at a pipe end: d points away from the pipe; hub over the pipe, bolt holes
    disc = Part.makeCylinder(FD/2, FT, p, d)
    hub = Part.makeCylinder(OD/2 + 8, 25, p - d*25, d)
    body = disc.fuse(hub)
    body = body.cut(Part.makeCylinder(ID/2, FT+25, p - d*25, d))
    body = body.cut(Part.makeCylinder(OD/2, 25, p - d*25, d))
    n = V(d); u = n.cross(V(0,0,1)) if abs(n.z) < 0.9 else n.cross(V(1,0,0)); u.normalize(); w = n.cross(u)
    for k in range(8):
        a = 2*math.pi*k/8 + math.pi/8
        body = body.cut(Part.makeCylinder(BH/2, FT, p + u*(BC/2*math.cos(a)) + w*(BC/2*math.sin(a)), d))
    return body.removeSplitter()
def elbow(start, d_in, d_out):
    R = 1.5*OD
    centre = start + d_out*R
    arc = Part.Wire([Part.Edge(Part.Arc(start, centre - d_out*R*math.cos(math.pi/4) + d_in*R*math.sin(math.pi/4), centre + d_in*R))])
    o = arc.makePipeShell([Part.Wire([Part.makeCircle(OD/2, start, d_in)])], True, True)
    i = arc.makePipeShell([Part.Wire([Part.makeCircle(ID/2, start, d_in)])], True, True)
    return o.cut(i), centre + d_in*R
X, Y, Z = V(1,0,0), V(0,1,0), V(0,0,1)
parts = []
# pipe A along +x, a flange at its start, an elbow welded at its end
A0 = V(0,0,0); LA = 1200
parts.append(("flange_A", flange(A0, -X)))
parts.append(("pipe_A", pipe(A0, X, LA)))
e1, e1_end = elbow(A0 + X*LA, X, Y)
parts.append(("elbow_1", e1))
# pipe B between two elbows, no flange
LB = 900
parts.append(("pipe_B", pipe(e1_end, Y, LB)))
e2, e2_end = elbow(e1_end + Y*LB, Y, Z)
parts.append(("elbow_2", e2))
# pipe C up from elbow 2, a flange at its top
LC = 700
parts.append(("pipe_C", pipe(e2_end, Z, LC)))
parts.append(("flange_C", flange(e2_end + Z*LC, Z)))
# a flexible hose (bent) between two flanges of its own, beside the pipeline
H0 = V(0, -400, 0)
hose_path = Part.Wire([Part.Edge(Part.BSplineCurve([H0, H0 + V(300, -150, 0), H0 + V(700, 100, -80), H0 + V(1000, 0, 0)]))])
e = hose_path.Edges[0]
t0 = e.tangentAt(e.FirstParameter); t1 = e.tangentAt(e.LastParameter)
hose = hose_path.makePipeShell([Part.Wire([Part.makeCircle(OD/2, H0, t0)])], True, True).cut(
       hose_path.makePipeShell([Part.Wire([Part.makeCircle(ID/2, H0, t0)])], True, True))
parts.append(("hose", hose))
parts.append(("flange_H1", flange(H0, -t0)))
parts.append(("flange_H2", flange(e.valueAt(e.LastParameter), t1)))
# a sensor cable clipped along the pipeline
wire_path = Part.Wire([Part.Edge(Part.BSplineCurve([V(100, 60, 40), V(500, 70, 60), V(900, 60, 40), V(1150, 120, 40)]))])
we = wire_path.Edges[0]
parts.append(("sensor_cable", wire_path.makePipeShell([Part.Wire([Part.makeCircle(3.0, we.valueAt(we.FirstParameter), we.tangentAt(we.FirstParameter))])], True, True)))
objs = []
for name, s in parts:
    o = doc.addObject("Part::Feature", name); o.Shape = s; objs.append(o)
Import.export(objs, "pipeline.step")
