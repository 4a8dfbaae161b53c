# FreeCAD (freecadcmd) script: a multi-core cable of 10 cores (2 in the middle, 8 around), each
# core a 1 mm conductor and its 1.6 mm insulation drawn as two solids that touch (the conductor's
# surface is the insulation's bore), along 150 mm straight, a 60 mm-radius quarter bend and
# 120 mm straight; exported to IGES as FreeCAD writes it (each solid as its trimmed surfaces, in a
# group of its own): multicore_insulated.igs.
import math
import Part
from FreeCAD import Vector as V

d, rc = 1.6, 0.5
R = 60.0
path = Part.Wire([Part.LineSegment(V(0, 0, 0), V(150, 0, 0)).toShape(),
                  Part.ArcOfCircle(Part.Circle(V(150, R, 0), V(0, 0, 1), R), -math.pi / 2, 0).toShape(),
                  Part.LineSegment(V(150 + R, R, 0), V(150 + R, R + 120, 0)).toShape()])
centres = [(0.8, 0.0), (-0.8, 0.0)] + [(2.6 * math.cos(2 * math.pi * k / 8), 2.6 * math.sin(2 * math.pi * k / 8))
                                      for k in range(8)]
bodies = []
for (y, z) in centres:
    c = V(0, y, z)
    conductor = path.makePipeShell([Part.Wire([Part.makeCircle(rc, c, V(1, 0, 0))])], True, False)
    insulation = path.makePipeShell([Part.Wire([Part.makeCircle(d / 2, c, V(1, 0, 0))])], True, False)
    bodies += [conductor, insulation.cut(conductor)]
Part.Compound(bodies).exportIges("multicore_insulated.igs")
