#!/usr/bin/env python3
"""Writes door_hinge.stl: a 10 mm cable drawn sagging from a body pillar (x = 0) to a door
(x = 0.25 m) whose hinge is the vertical axis through (0.30, -0.03, 0), plus the pillar, the door
panel and a loudspeaker below as boxes. With door_hinge.json, `cablefit relax door_hinge.stl --config door_hinge.json` swings
the door open by 75 degrees and back. The STL is in millimetres (relax's default unit); the
script works in metres, like harness.json."""
import math
import struct

RADIUS, SIDES = 0.005, 20
SPAN, SAG = 0.25, 0.07


def route(n=120):
    # A parabola-like sag in the x-z plane: ends level, lowest in the middle.
    return [(SPAN * i / n, 0.0, -SAG * math.sin(math.pi * i / n)) for i in range(n + 1)]


def tube(points):
    tris = []
    rings = []
    for i, p in enumerate(points):
        a, b = points[max(0, i - 1)], points[min(len(points) - 1, i + 1)]
        t = [b[k] - a[k] for k in range(3)]
        tn = math.sqrt(sum(x * x for x in t))
        t = [x / tn for x in t]
        u = (0.0, 1.0, 0.0)  # the route lies in the x-z plane: y is normal to it
        v = (t[1] * u[2] - t[2] * u[1], t[2] * u[0] - t[0] * u[2], t[0] * u[1] - t[1] * u[0])
        ring = []
        for j in range(SIDES):
            ang = 2 * math.pi * j / SIDES
            ring.append(tuple(p[k] + RADIUS * (math.cos(ang) * u[k] + math.sin(ang) * v[k])
                              for k in range(3)))
        rings.append(ring)
    for i in range(len(rings) - 1):
        for j in range(SIDES):
            a, b = rings[i][j], rings[i][(j + 1) % SIDES]
            c, d = rings[i + 1][j], rings[i + 1][(j + 1) % SIDES]
            tris += [(a, b, c), (b, d, c)]
    for ring, p, flip in ((rings[0], points[0], True), (rings[-1], points[-1], False)):
        for j in range(SIDES):
            a, b = ring[j], ring[(j + 1) % SIDES]
            tris.append((p, b, a) if flip else (p, a, b))
    return tris


def box(lo, hi):
    v = [(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2])
         for k in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for q in quads:
        tris += [(v[q[0]], v[q[1]], v[q[2]]), (v[q[0]], v[q[2]], v[q[3]])]
    return tris


def write(path, tris):
    with open(path, "wb") as f:
        f.write(b"door hinge sample, millimetres".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for a, b, c in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            for p in (a, b, c):
                f.write(struct.pack("<3f", *(1000.0 * x for x in p)))
            f.write(b"\0\0")


if __name__ == "__main__":
    tris = tube(route())
    # The cable's ends are held in the pillar and in the door (inside their boxes: not contact).
    tris += box((-0.06, -0.04, -0.03), (0.01, 0.04, 0.03))        # body pillar
    tris += box((0.24, -0.04, -0.03), (0.29, 0.04, 0.03))         # door inner panel
    # A loudspeaker below, out of the cable's reach as drawn: clearance is measured to it.
    tris += box((0.08, -0.06, -0.22), (0.17, 0.06, -0.15))
    write("door_hinge.stl", tris)
