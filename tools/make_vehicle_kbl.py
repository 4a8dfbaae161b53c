#!/usr/bin/env python3
"""Writes a KBL harness shaped as real vehicle harnesses are exported, for the bench and the tests.

tools/make_kbl_harness.py draws a regular tree (one segment length, one protection per segment,
wires from one root). Harnesses exported by design tools differ in what costs time:
- many nodes close together: a node wherever a breakout leaves, a protection or a fixing starts,
  so a third of the segments are 8-30 mm long beside segments of half a metre;
- centre curves as one-span B-splines of degree 6 (7 control points, as CATIA writes them),
  cubic B-splines of up to 40 spans and polylines of many points (other exporters),
  tangent-continuous through the nodes of one path;
- protections on most segments: tape wraps over whole segments, spot tapes, corrugated tubes
  over runs of segments, textile sleeves and heat-shrink, some segments with two areas;
- fixings on segments (clips, cable ties) at a fraction of them;
- hundreds of wires from connector to connector (not from one root), each routed through every
  segment between its ends, some of them cores of multi-core cables, so trunk segments list
  100+ wires;
- KBL 2.3 (routings name Connections) or 2.4 (routings name the wire occurrences).

The harness is a tree grown from a 3-D trunk, branches and sub-branches leaving its nodes. It is
deterministic: the same arguments give the same file (Python's random.Random, seeded).

Usage: tools/make_vehicle_kbl.py OUT.kbl [--segments N] [--version 2.3|2.4] [--seed S]
"""
import argparse
import math
import random
import sys

STEP = 4.0  # sampling of a drawn path [mm]


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(a, k):
    return tuple(x * k for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return mul(a, 1.0 / n)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def perpendicular(t, rng):
    """A random unit vector normal to t."""
    while True:
        v = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        v = sub(v, mul(t, dot(v, t)))
        if norm(v) > 0.2:
            return unit(v)


def drawn_path(start, direction, length, rng, turn):
    """A smooth route sampled every STEP mm: its direction turns slowly (at most `turn` rad per
    100 mm), as a bundle follows a body panel."""
    pts = [start]
    d = unit(direction)
    bend = perpendicular(d, rng)
    rate = rng.uniform(-turn, turn) / 100.0
    travelled = 0.0
    while travelled < length:
        if rng.random() < STEP / 150.0:  # the route changes its bend now and then
            bend = perpendicular(d, rng)
            rate = rng.uniform(-turn, turn) / 100.0
        d = unit(add(d, mul(bend, rate * STEP)))
        bend = unit(sub(bend, mul(d, dot(bend, d))))
        pts.append(add(pts[-1], mul(d, STEP)))
        travelled += STEP
    return pts


def node_spacings(length, rng):
    """Where nodes sit along a path: mostly short and medium spans, some long ones."""
    cuts = [0.0]
    while True:
        r = rng.random()
        gap = rng.uniform(8, 30) if r < 0.35 else rng.uniform(40, 160) if r < 0.85 else rng.uniform(160, 450)
        if cuts[-1] + gap > length - 8:
            break
        cuts.append(cuts[-1] + gap)
    cuts.append(length)
    return cuts


def tangent_at(pts, i):
    a, b = pts[max(i - 1, 0)], pts[min(i + 1, len(pts) - 1)]
    return unit(sub(b, a))


def hermite(p0, p1, t0, t1, u):
    h00 = 2 * u ** 3 - 3 * u ** 2 + 1
    h10 = u ** 3 - 2 * u ** 2 + u
    h01 = -2 * u ** 3 + 3 * u ** 2
    h11 = u ** 3 - u ** 2
    return add(add(mul(p0, h00), mul(t0, h10)), add(mul(p1, h01), mul(t1, h11)))


def bspline_basis(i, p, t, knots):
    """Cox-de Boor basis N_{i,p}(t)."""
    if p == 0:
        return 1.0 if knots[i] <= t < knots[i + 1] else 0.0
    a = 0.0
    if knots[i + p] != knots[i]:
        a = (t - knots[i]) / (knots[i + p] - knots[i]) * bspline_basis(i, p - 1, t, knots)
    b = 0.0
    if knots[i + p + 1] != knots[i + 1]:
        b = (knots[i + p + 1] - t) / (knots[i + p + 1] - knots[i + 1]) * bspline_basis(i + 1, p - 1, t, knots)
    return a + b


def solve(a, b):
    """Gaussian elimination with partial pivoting: a x = b, b a list of rows of 3."""
    n = len(a)
    m = [list(a[i]) + list(b[i]) for i in range(n)]
    for c in range(n):
        piv = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[piv] = m[piv], m[c]
        for r in range(n):
            if r != c:
                f = m[r][c] / m[c][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [tuple(m[i][n + k] / m[i][i] for k in range(3)) for i in range(n)]


def one_span_bspline(curve, degree):
    """Control points of the unclamped uniform B-spline of one span (knots 0..2p+1, valid on
    [p, p+1]) equal to the polynomial curve(u), u in [0, 1], of degree <= `degree`."""
    knots = list(range(2 * degree + 2))
    us = [(k + 0.5) / (degree + 1) for k in range(degree + 1)]
    a = [[bspline_basis(i, degree, degree + u, knots) for i in range(degree + 1)] for u in us]
    return solve(a, [curve(u) for u in us])


class Harness:
    def __init__(self, rng):
        self.rng = rng
        self.points = []      # (x, y, z) [mm]
        self.nodes = []       # (point id, path tangent)
        self.segments = []    # dict: a, b, control ids, degree, length, path (branch id)
        self.adjacent = {}    # node -> [(other node, segment index)]

    def point(self, p):
        self.points.append(p)
        return len(self.points)

    def node(self, p):
        self.nodes.append(self.point(p))
        self.adjacent[len(self.nodes)] = []
        return len(self.nodes)

    def position(self, n):
        return self.points[self.nodes[n - 1] - 1]

    def segment(self, a, b, piece, path_id):
        """Segment from node a to node b drawn along `piece` (samples of the path)."""
        p0, p1 = piece[0], piece[-1]
        chord = sum(norm(sub(piece[k + 1], piece[k])) for k in range(len(piece) - 1))
        t0, t1 = mul(tangent_at(piece, 0), chord), mul(tangent_at(piece, len(piece) - 1), chord)
        r = self.rng.random()
        if r < 0.4:  # CATIA: one span of degree 6, the curve a polynomial through both nodes
            degree = 6
            ctrl = one_span_bspline(lambda u: hermite(p0, p1, t0, t1, u), 6)
            samples = [hermite(p0, p1, t0, t1, i / 400) for i in range(401)]
        elif r < 0.75:  # a cubic B-spline of many spans through points of the path
            degree = 3
            spans = max(1, min(40, int(chord / 15)))
            data = [piece[round(i * (len(piece) - 1) / spans)] for i in range(spans + 1)]
            ctrl = interpolating_cubic(data)
            samples = sample_uniform_cubic(ctrl, 40)
        else:  # a polyline through the path's points every few millimetres
            degree = 1
            k = max(2, min(len(piece) - 1, int(chord / 5)))
            ctrl = [piece[round(i * (len(piece) - 1) / k)] for i in range(k + 1)]
            samples = ctrl
        ids = [self.point(c) for c in ctrl]
        if degree == 1:
            ids[0], ids[-1] = self.nodes[a - 1], self.nodes[b - 1]
        length = sum(norm(sub(samples[k + 1], samples[k])) for k in range(len(samples) - 1))
        self.segments.append(dict(a=a, b=b, ids=ids, degree=degree, length=length, path=path_id,
                                  t0=unit(t0), t1=unit(t1), fixings=[], protections=[]))
        s = len(self.segments)
        self.adjacent[a].append((b, s))
        self.adjacent[b].append((a, s))
        return s


def interpolating_cubic(data):
    """Control points of the unclamped uniform cubic B-spline through data[0..m] at its knots,
    starting and ending exactly on data[0] and data[m]: c0 = 2 c1 - c2 and its mirror at the end
    put the curve's ends on c1 and c(m+1); (c(i) + 4 c(i+1) + c(i+2)) / 6 = data[i] inside."""
    m = len(data) - 1
    if m == 1:
        c1, c2 = data[0], data[1]
        d = sub(c2, c1)
        return [sub(c1, d), c1, c2, add(c2, d)]
    # Unknowns c1..c(m+1); c1 = data[0], c(m+1) = data[m]; tridiagonal for c2..cm.
    n = m - 1
    rhs = [mul(data[i], 6.0) for i in range(1, m)]
    rhs[0] = sub(rhs[0], data[0])
    rhs[-1] = sub(rhs[-1], data[m])
    diag = [4.0] * n
    for i in range(1, n):  # Thomas algorithm, off-diagonals 1
        f = 1.0 / diag[i - 1]
        diag[i] -= f
        rhs[i] = sub(rhs[i], mul(rhs[i - 1], f))
    x = [None] * n
    x[-1] = mul(rhs[-1], 1.0 / diag[-1])
    for i in range(n - 2, -1, -1):
        x[i] = mul(sub(rhs[i], x[i + 1]), 1.0 / diag[i])
    c = [data[0]] + x + [data[m]]
    return [sub(mul(c[0], 2), c[1])] + c + [sub(mul(c[-1], 2), c[-2])]


def sample_uniform_cubic(ctrl, per_span):
    out = []
    for i in range(len(ctrl) - 3):
        for k in range(per_span + (1 if i == len(ctrl) - 4 else 0)):
            u = k / per_span
            b = ((1 - u) ** 3 / 6, (3 * u ** 3 - 6 * u ** 2 + 4) / 6,
                 (-3 * u ** 3 + 3 * u ** 2 + 3 * u + 1) / 6, u ** 3 / 6)
            out.append(tuple(sum(b[j] * ctrl[i + j][d] for j in range(4)) for d in range(3)))
    return out


def grow(count, rng):
    """The tree: a trunk, then branches off random nodes until `count` segments."""
    h = Harness(rng)
    paths = []  # per path: list of its node ids
    start = (0.0, 0.0, 0.0)
    first = h.node(start)
    # node, direction, length, turn, depth; the trunk grows with the harness (2.6 m at 183)
    pending = [(first, (1.0, 0.15, -0.05), 2600.0 * math.sqrt(count / 183.0), 0.8, 0)]
    branchable = []
    while len(h.segments) < count:
        if not pending:
            n = rng.choice(branchable)
            p = h.position(n)
            # leave along a direction near normal to the path through n
            t = None
            for other, s in h.adjacent[n]:
                t = h.segments[s - 1]["t0"]
            d = perpendicular(t, rng)
            depth = 1 if n in trunk_nodes else 2
            pending.append((n, add(d, mul(t, rng.uniform(-0.5, 0.5))),
                            rng.uniform(60, 600) / depth, 1.5, depth))
        n0, direction, length, turn, depth = pending.pop()
        path = drawn_path(h.position(n0), direction, length, rng, turn)
        cuts = node_spacings(length, rng)
        path_id = len(paths)
        nodes = [n0]
        prev_i = 0
        for c in cuts[1:]:
            if len(h.segments) >= count:
                break
            i = min(len(path) - 1, int(round(c / STEP)))
            if i <= prev_i:
                continue
            b = h.node(path[i])
            h.segment(nodes[-1], b, path[prev_i:i + 1], path_id)
            nodes.append(b)
            prev_i = i
        paths.append(nodes)
        if path_id == 0:
            trunk_nodes = set(nodes)
        branchable.extend(nodes[1:-1])
    return h, paths


def leaves(h):
    return [n for n, adj in h.adjacent.items() if len(adj) == 1]


def tree_path(h, a, b):
    """Segments between nodes a and b (the tree has one path)."""
    prev = {a: None}
    queue = [a]
    while queue:
        n = queue.pop()
        if n == b:
            break
        for other, s in h.adjacent[n]:
            if other not in prev:
                prev[other] = (n, s)
                queue.append(other)
    segs = []
    n = b
    while prev[n] is not None:
        n, s = prev[n]
        segs.append(s)
    return list(reversed(segs))


PROTECTIONS = [  # id, type as exporters name them, mass [g/m]
    ("prot_tape", "TAPE PVC 19MM", 5.5),
    ("prot_fleece", "GEWEBEBAND (textile tape)", 7.0),
    ("prot_corrugated", "WELLROHR NW10 (corrugated tube)", 24.0),
    ("prot_sleeve", "GEWEBESCHLAUCH (textile sleeve)", 12.0),
    ("prot_shrink", "SCHRUMPFSCHLAUCH (heat shrink)", 9.0),
]
GAUGES = [  # conductor area [mm2], outside diameter [mm], mass [g/m], bend radius [mm]
    (0.35, 1.3, 5.0, 4.0), (0.5, 1.6, 7.0, 5.0), (0.75, 1.9, 10.0, 6.0),
    (1.5, 2.4, 18.0, 8.0), (2.5, 3.0, 29.0, 10.0), (6.0, 4.2, 66.0, 14.0),
]


def decorate(h, paths, wire_count, rng):
    """Protections, fixings, connectors and wires."""
    # Protections: corrugated tube or sleeve over whole branch paths, tape on the trunk, spots.
    path_kind = {}
    for pid in range(len(paths)):
        r = rng.random()
        path_kind[pid] = ("prot_tape" if pid == 0 else "prot_corrugated" if r < 0.3 else
                          "prot_sleeve" if r < 0.45 else "prot_fleece" if r < 0.75 else None)
    for s, seg in enumerate(h.segments, 1):
        kind = path_kind[seg["path"]]
        if kind and rng.random() < 0.7:
            seg["protections"].append((kind, 0.0, 1.0))
        if seg["length"] > 40 and rng.random() < 0.12:  # a spot tape or a heat-shrink piece
            a = rng.uniform(0.1, 0.6)
            seg["protections"].append((rng.choice(["prot_tape", "prot_shrink"]), a, a + rng.uniform(0.1, 0.3)))
    # Fixings: one segment in eleven, on the longer segments, clips and cable ties.
    candidates = [s for s, seg in enumerate(h.segments, 1) if seg["length"] > 60]
    rng.shuffle(candidates)
    for s in sorted(candidates[:max(1, len(h.segments) // 11)]):
        h.segments[s - 1]["fixings"].append(rng.uniform(0.2, 0.8))
    # Connectors at the leaves (a few leaves end in a grommet without one).
    ends = leaves(h)
    connectors = [n for n in ends if rng.random() < 0.95]
    if len(connectors) < 2:
        connectors = ends
    # Wires between connectors, a few multi-core cables among them.
    wires = []
    hub = connectors[:max(2, len(connectors) // 8)]  # the connectors most wires come from
    for w in range(wire_count):
        a = rng.choice(hub) if rng.random() < 0.6 else rng.choice(connectors)
        b = rng.choice(connectors)
        while b == a:
            b = rng.choice(connectors)
        cores = rng.choice([2, 3, 4]) if rng.random() < 0.05 else 0
        wires.append(dict(a=a, b=b, gauge=rng.randrange(len(GAUGES)), cores=cores,
                          segments=tree_path(h, a, b)))
    return connectors, wires


def write(h, connectors, wires, version, out):
    w = out.write
    w('<?xml version="1.0" encoding="UTF-8"?>\n')
    w('<kbl:KBL_container xmlns:kbl="http://www.prostep.org/Car_electric_container/KBL%s/KBLSchema" '
      'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" id="KBL_container_1" '
      'version_id="%s SR-1">\n' % (version, version))
    for i, (x, y, z) in enumerate(h.points, 1):
        w('\t<Cartesian_point id="Cartesian_point_%d">\n' % i)
        for c in (x, y, z):
            w('\t\t<Coordinates>%.6f</Coordinates>\n' % c)
        w('\t</Cartesian_point>\n')
    part = ('\t\t<Part_number>%s</Part_number>\n\t\t<Company_name>cablefit</Company_name>\n'
            '\t\t<Version>1</Version>\n\t\t<Abbreviation>/NULL</Abbreviation>\n'
            '\t\t<Description>%s</Description>\n')
    w('\t<Connector_housing id="housing_1">\n' + part % ("VEH-CONN-1", "connector") +
      '\t</Connector_housing>\n')
    for fid, ftype in (("fixing_clip", "CLIP"), ("fixing_tie", "CABLE TIE")):
        w('\t<Fixing id="%s">\n' % fid + part % (fid.upper(), ftype) +
          '\t\t<Fixing_type>%s</Fixing_type>\n\t</Fixing>\n' % ftype)
    for pid, ptype, mass in PROTECTIONS:
        w('\t<Wire_protection id="%s">\n' % pid + part % (pid.upper(), ptype) +
          '\t\t<Mass_information id="%s_mass">\n\t\t\t<Unit_component>unit_gpm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Mass_information>\n'
          '\t\t<Protection_type>%s</Protection_type>\n\t</Wire_protection>\n' % (pid, mass, ptype))
    for g, (area, od, mass, bend) in enumerate(GAUGES, 1):
        w('\t<General_wire id="wire_part_%d">\n' % g + part % ("FLRY-B %.2f" % area, "wire") +
          '\t\t<Mass_information id="wire_mass_%d">\n\t\t\t<Unit_component>unit_gpm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Mass_information>\n'
          '\t\t<Wire_type>FLRY-B</Wire_type>\n'
          '\t\t<Bend_radius id="wire_bend_%d">\n\t\t\t<Unit_component>unit_mm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Bend_radius>\n'
          '\t\t<Cross_section_area id="wire_csa_%d">\n\t\t\t<Unit_component>unit_mm2</Unit_component>\n'
          '\t\t\t<Value_component>%.2f</Value_component>\n\t\t</Cross_section_area>\n'
          '\t\t<Outside_diameter id="wire_od_%d">\n\t\t\t<Unit_component>unit_mm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Outside_diameter>\n'
          '\t</General_wire>\n' % (g, mass, g, bend, g, area, g, od))
    w('\t<Harness id="harness_1">\n' + part % ("VEH-HARNESS-%d" % len(h.segments), "vehicle harness"))
    for i, n in enumerate(connectors, 1):
        w('\t\t<Connector_occurrence id="connector_%d">\n\t\t\t<Id>X%d</Id>\n'
          '\t\t\t<Part>housing_1</Part>\n\t\t</Connector_occurrence>\n' % (i, i))
    routed = []  # (routing target id, segments)
    for i, wire in enumerate(wires, 1):
        if wire["cores"]:
            w('\t\t<Special_wire_occurrence id="cable_%d">\n\t\t\t<Part>wire_part_%d</Part>\n'
              '\t\t\t<Special_wire_id>W%d</Special_wire_id>\n' % (i, 1 + wire["gauge"], i))
            for c in range(1, wire["cores"] + 1):
                w('\t\t\t<Core_occurrence id="core_%d_%d">\n\t\t\t\t<Wire_number>%d.%d</Wire_number>\n'
                  '\t\t\t</Core_occurrence>\n' % (i, c, i, c))
                routed.append(("core_%d_%d" % (i, c), wire["segments"]))
            w('\t\t</Special_wire_occurrence>\n')
        else:
            w('\t\t<General_wire_occurrence xsi:type="kbl:Wire_occurrence" id="wire_%d">\n'
              '\t\t\t<Part>wire_part_%d</Part>\n\t\t\t<Wire_number>%d</Wire_number>\n'
              '\t\t</General_wire_occurrence>\n' % (i, 1 + wire["gauge"], i))
            routed.append(("wire_%d" % i, wire["segments"]))
    if version == "2.3":  # routings name Connections, which name the wire or core
        for k, (target, _) in enumerate(routed, 1):
            w('\t\t<Connection id="connection_%d">\n\t\t\t<Signal_name>SIG%d</Signal_name>\n'
              '\t\t\t<Wire>%s</Wire>\n\t\t</Connection>\n' % (k, k, target))
    fixing = 0
    for s, seg in enumerate(h.segments, 1):
        for _ in seg["fixings"]:
            fixing += 1
            w('\t\t<Fixing_occurrence id="fixing_%d">\n\t\t\t<Id>F%d</Id>\n'
              '\t\t\t<Part>%s</Part>\n\t\t</Fixing_occurrence>\n'
              % (fixing, fixing, "fixing_clip" if fixing % 3 else "fixing_tie"))
        for k, (pid, _, _) in enumerate(seg["protections"], 1):
            w('\t\t<Wire_protection_occurrence id="protection_%d_%d">\n\t\t\t<Id>P%d.%d</Id>\n'
              '\t\t\t<Part>%s</Part>\n\t\t</Wire_protection_occurrence>\n' % (s, k, s, k, pid))
    w('\t</Harness>\n')
    connector_at = {n: i for i, n in enumerate(connectors, 1)}
    for n, p in enumerate(h.nodes, 1):
        w('\t<Node id="Node_%d">\n\t\t<Id>N%d</Id>\n\t\t<Cartesian_point>Cartesian_point_%d'
          '</Cartesian_point>\n' % (n, n, p))
        if n in connector_at:
            w('\t\t<Referenced_components>connector_%d</Referenced_components>\n' % connector_at[n])
        w('\t</Node>\n')
    for k, (target, segs) in enumerate(routed, 1):
        ref = "connection_%d" % k if version == "2.3" else target
        w('\t<Routing id="routing_%d">\n\t\t<Routed_wire>%s</Routed_wire>\n'
          '\t\t<Segments>%s</Segments>\n\t</Routing>\n'
          % (k, ref, " ".join("Segment_%d" % s for s in segs)))
    fixing = 0
    for s, seg in enumerate(h.segments, 1):
        w('\t<Segment id="Segment_%d">\n\t\t<Id>HARNESS/Bundle.%d/Flexible Curve.%d</Id>\n' % (s, s, s))
        for tag, v in (("Start_vector", seg["t0"]), ("End_vector", seg["t1"])):
            for c in v:
                w('\t\t<%s>%.6f</%s>\n' % (tag, c, tag))
        w('\t\t<Virtual_length id="virtual_length_%d">\n\t\t\t<Unit_component>unit_mm'
          '</Unit_component>\n\t\t\t<Value_component>%.6f</Value_component>\n'
          '\t\t</Virtual_length>\n' % (s, seg["length"]))
        w('\t\t<End_node>Node_%d</End_node>\n\t\t<Start_node>Node_%d</Start_node>\n'
          % (seg["b"], seg["a"]))
        w('\t\t<Form>circular</Form>\n')
        w('\t\t<Center_curve id="center_curve_%d">\n\t\t\t<Degree>%d</Degree>\n'
          '\t\t\t<Control_points>%s</Control_points>\n\t\t</Center_curve>\n'
          % (s, seg["degree"], " ".join("Cartesian_point_%d" % i for i in seg["ids"])))
        for loc in seg["fixings"]:
            fixing += 1
            w('\t\t<Fixing_assignment id="fixing_assignment_%d">\n\t\t\t<Location>%.6f</Location>\n'
              '\t\t\t<Fixing>fixing_%d</Fixing>\n\t\t</Fixing_assignment>\n' % (fixing, loc, fixing))
        for k, (_, lo, hi) in enumerate(seg["protections"], 1):
            w('\t\t<Protection_area id="protection_area_%d_%d">\n'
              '\t\t\t<Start_location>%.6f</Start_location>\n\t\t\t<End_location>%.6f</End_location>\n'
              '\t\t\t<Associated_protection>protection_%d_%d</Associated_protection>\n'
              '\t\t</Protection_area>\n' % (s, k, lo, min(hi, 1.0), s, k))
        w('\t</Segment>\n')
    w('\t<Unit id="unit_mm">\n\t\t<Si_unit_name>metre</Si_unit_name>\n\t\t<Si_prefix>milli'
      '</Si_prefix>\n\t</Unit>\n')
    w('\t<Unit id="unit_mm2">\n\t\t<Si_unit_name>metre</Si_unit_name>\n\t\t<Si_prefix>milli'
      '</Si_prefix>\n\t\t<Si_dimension>square</Si_dimension>\n\t</Unit>\n')
    w('\t<Unit id="unit_gpm">\n\t\t<Unit_name>GramPerMetre</Unit_name>\n\t</Unit>\n')
    w('</kbl:KBL_container>\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--segments", type=int, default=183)
    ap.add_argument("--wires", type=int, default=0, help="default: 1.2 per segment")
    ap.add_argument("--version", choices=["2.3", "2.4"], default="2.4")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    h, paths = grow(a.segments, rng)
    connectors, wires = decorate(h, paths, a.wires or int(1.2 * a.segments), rng)
    with open(a.out, "w") as out:
        write(h, connectors, wires, a.version, out)
    areas = sum(len(s["protections"]) for s in h.segments)
    fixings = sum(len(s["fixings"]) for s in h.segments)
    short = sum(1 for s in h.segments if s["length"] < 30)
    print("%s: KBL %s, %d segments (%d under 30 mm), %d nodes, %d connectors, %d wires, "
          "%d fixings, %d protection areas" % (a.out, a.version, len(h.segments), short,
                                               len(h.nodes), len(connectors), len(wires),
                                               fixings, areas))
    return 0


if __name__ == "__main__":
    sys.exit(main())
