# FreeCAD (freecadcmd) script: a slender bent tube (8 mm, 120 mm straight, a 40 mm-radius quarter
# bend, 200 mm straight) drawn only as surfaces: each piece's wall as two half-surfaces, each a
# polynomial (non-rational) B-spline approximated through points on the exact surface, no end
# faces, no solid. Written to tube_surfaces_grouped.igs; flatten_iges then writes each face as a
# root entity of its own (tube_surfaces.igs), as exporters that write no groups do.
import math
import Part
from FreeCAD import Vector as V

r, L1, R, L2 = 4.0, 120.0, 40.0, 200.0

def point(s, a):
    # s: arc length along the route, a: angle round it
    if s <= L1:
        c, t, n = V(s, 0, 0), V(1, 0, 0), V(0, 1, 0)
    elif s <= L1 + R * math.pi / 2:
        th = (s - L1) / R
        c = V(L1 + R * math.sin(th), R * (1 - math.cos(th)), 0)
        t, n = V(math.cos(th), math.sin(th), 0), V(-math.sin(th), math.cos(th), 0)
    else:
        c, t, n = V(L1 + R, R + s - L1 - R * math.pi / 2, 0), V(0, 1, 0), V(-1, 0, 0)
    b = t.cross(n)
    return c + n * (r * math.cos(a)) + b * (r * math.sin(a))

def half(s0, s1, a0, rows=25, cols=9):
    pts = [[point(s0 + (s1 - s0) * i / (rows - 1), a0 + math.pi * j / (cols - 1)) for j in range(cols)]
           for i in range(rows)]
    surface = Part.BSplineSurface()
    surface.approximate(Points=pts, DegMin=2, DegMax=3, Continuity=1, Tolerance=0.01)
    return surface.toShape()

pieces = [(0, L1), (L1, L1 + R * math.pi / 2), (L1 + R * math.pi / 2, L1 + R * math.pi / 2 + L2)]
faces = [half(s0, s1, a0) for s0, s1 in pieces for a0 in (0.0, math.pi)]
Part.Compound(faces).exportIges("tube_surfaces_grouped.igs")  # then: flatten_iges tube_surfaces_grouped.igs tube_surfaces.igs
