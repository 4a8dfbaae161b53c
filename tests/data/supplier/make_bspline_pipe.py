# FreeCAD (freecadcmd) script: a 6 mm pipe swept along a B-spline as some CAD systems export one:
# a single non-rational B-spline surface, cubic and periodic round the pipe (6 poles on a ring per
# pole of the spine, so its sections are round only to 1.5e-3 of the radius), capped by two
# planar faces; written to bspline_pipe.step.
import math
import Part
from FreeCAD import Vector as V

r = 3.0
spine = Part.BSplineCurve()
spine.interpolate([V(0, 0, 0), V(80, 10, 0), V(160, 60, -20), V(220, 140, -30), V(240, 240, -30)])
# Poles close enough that the section's frame turns little from one to the next.
k0, k1 = spine.FirstParameter, spine.LastParameter
for k in range(1, 48):
    spine.insertKnot(k0 + (k1 - k0) * k / 48, 1, 1e-9)
spine_poles = spine.getPoles()
ring = 6
# A periodic uniform cubic on a ring of 6 poles of radius rho is round to 1.5e-3 of its radius;
# rho is scaled so that its mean radius is r.
unit = Part.BSplineCurve()
unit.buildFromPolesMultsKnots([V(math.cos(2 * math.pi * k / ring), math.sin(2 * math.pi * k / ring), 0)
                               for k in range(ring)], [1] * (ring + 1), [float(k) for k in range(ring + 1)],
                              True, 3)
mean = sum(unit.value(unit.FirstParameter + (unit.LastParameter - unit.FirstParameter) * k / 240).Length
           for k in range(240)) / 240
rho = r / mean
# frames at the spine poles' Greville points, rotation minimising (double reflection)
knots = spine.KnotSequence
deg = spine.Degree
greville = [sum(knots[i + 1:i + deg + 1]) / deg for i in range(len(spine_poles))]
frames = []
prev_x = spine.value(greville[0]); t = spine.tangent(greville[0])[0]
n = V(0, 0, 1) - t * t.dot(V(0, 0, 1)); n.normalize()
for g in greville:
    x = spine.value(g); t1 = spine.tangent(g)[0]
    v1 = x - prev_x; c1 = v1.dot(v1)
    if c1 > 0:
        nl = n - v1 * (2 / c1 * v1.dot(n)); tl = t - v1 * (2 / c1 * v1.dot(t))
    else:
        nl, tl = n, t
    v2 = t1 - tl; c2 = v2.dot(v2)
    if c2 > 0: nl = nl - v2 * (2 / c2 * v2.dot(nl))
    nl = nl - t1 * nl.dot(t1); nl.normalize()
    n, t, prev_x = nl, t1, x
    frames.append((n, t.cross(n)))
poles = []
for p, (nn, bb) in zip(spine_poles, frames):
    poles.append([p + nn * (rho * math.cos(2 * math.pi * k / ring)) + bb * (rho * math.sin(2 * math.pi * k / ring))
                  for k in range(ring)])
mults = spine.getMultiplicities()
surface = Part.BSplineSurface()
surface.buildFromPolesMultsKnots(poles, mults, [1] * (ring + 1), spine.getKnots(),
                                 [float(k) for k in range(ring + 1)], False, True, deg, 3)
face = surface.toShape()
caps = [Part.Face(Part.Wire([e])) for e in face.Edges if e.isClosed() and not e.isSeam(face)]
shell = Part.Shell([face] + caps)
shell.sewShape()
solid = Part.Solid(shell)
if solid.Volume < 0:
    solid.reverse()
print("caps", len(caps), "valid", solid.isValid(), "volume", solid.Volume)
solid.exportStep("bspline_pipe.step")
