#!/usr/bin/env python3
"""Writes a synthetic KBL 2.3 harness of the size real vehicle harnesses have (default: 183
segments), for the tests and the bench: the public VW samples stop at 30 segments.

The tree is deterministic (no random numbers): a trunk along x, side branches off every trunk
node along +-y that fork again, every leaf a connector. Segments are drawn drooping (degree-1
centre curves through a dropped midpoint, so that they start and end exactly on their nodes);
every wire runs from the root connector to one leaf, so trunk segments carry many wires and
leaves one; trunk segments have a fixing at their middle and a tape over most of their length,
every third branch a corrugated tube. Units are declared as in the VW files (mm, g, g/m).

Usage: tools/make_kbl_harness.py OUT.kbl [SEGMENTS]
"""
import math
import sys


class Harness:
    def __init__(self):
        self.points = []     # (x, y, z) [mm]
        self.nodes = []      # point index
        self.segments = []   # (start node, end node, [control point indices], length)
        self.parent = {}     # node -> (parent node, segment index)
        self.leaves = []

    def point(self, p):
        self.points.append(p)
        return len(self.points)  # ids are 1-based

    def node(self, p):
        self.nodes.append(self.point(p))
        return len(self.nodes)

    def segment(self, a, b):
        pa, pb = self.points[self.nodes[a - 1] - 1], self.points[self.nodes[b - 1] - 1]
        chord = math.dist(pa, pb)
        mid = tuple(0.5 * (u + v) for u, v in zip(pa, pb))
        mid = (mid[0], mid[1], mid[2] - 0.02 * chord)  # drawn drooping by 2 % of its chord
        ids = [self.nodes[a - 1], self.point(mid), self.nodes[b - 1]]
        length = math.dist(pa, mid) + math.dist(mid, pb)
        self.segments.append((a, b, ids, length))
        self.parent[b] = (a, len(self.segments))
        return len(self.segments)


def build(count):
    h = Harness()
    root = h.node((0.0, 0.0, 0.0))
    trunk = [root]
    k = 0
    while len(h.segments) < count:
        # Next trunk node, then a fork of side branches off it while segments remain.
        prev = trunk[-1]
        px, py, pz = h.points[h.nodes[prev - 1] - 1]
        nxt = h.node((px + 300.0, py, pz + (20.0 if k % 2 else -20.0)))
        h.segment(prev, nxt)
        trunk.append(nxt)
        for side in (1, -1):
            if len(h.segments) >= count:
                break
            a = nxt
            ax, ay, az = h.points[h.nodes[a - 1] - 1]
            b = h.node((ax + 40.0, ay + side * 180.0, az + 30.0))
            h.segment(a, b)
            for fork in (1, -1):
                if len(h.segments) >= count:
                    break
                bx, by, bz = h.points[h.nodes[b - 1] - 1]
                c = h.node((bx + fork * 120.0, by + side * 150.0, bz - 40.0))
                h.segment(b, c)
                h.leaves.append(c)
            if not any(h.parent.get(n, (None,))[0] == b for n in h.leaves):
                h.leaves.append(b)
        k += 1
    # The trunk's far end is a leaf too; the root is the other connector.
    h.leaves.append(trunk[-1])
    return h, trunk


def path(h, leaf):
    segs = []
    n = leaf
    while n in h.parent:
        n, s = h.parent[n]
        segs.append(s)
    return list(reversed(segs))


def write(h, trunk, out):
    trunk_segments = {h.parent[n][1] for n in trunk[1:]}
    w = out.write
    w('<?xml version="1.0" encoding="UTF-8"?>\n')
    w('<kbl:KBL_container xmlns:kbl="http://www.prostep.org/Car_electric_container/KBL2.3/'
      'KBLSchema" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" id="KBL_container_1" '
      'version_id="2.3 SR-1">\n')
    for i, (x, y, z) in enumerate(h.points, 1):
        w('\t<Cartesian_point id="Cartesian_point_%d">\n' % i)
        for c in (x, y, z):
            w('\t\t<Coordinates>%.6f</Coordinates>\n' % c)
        w('\t</Cartesian_point>\n')
    w('\t<Connector_housing id="housing_1">\n\t\t<Part_number>SYN-CONN-1</Part_number>\n'
      '\t\t<Company_name>cablefit</Company_name>\n\t\t<Version>1</Version>\n'
      '\t\t<Abbreviation>/NULL</Abbreviation>\n\t\t<Description>connector</Description>\n'
      '\t</Connector_housing>\n')
    w('\t<Fixing id="fixing_part_1">\n\t\t<Part_number>SYN-CLIP-1</Part_number>\n'
      '\t\t<Company_name>cablefit</Company_name>\n\t\t<Version>1</Version>\n'
      '\t\t<Abbreviation>/NULL</Abbreviation>\n\t\t<Description>clip</Description>\n'
      '\t\t<Fixing_type>clip</Fixing_type>\n\t</Fixing>\n')
    for pid, ptype, mass in (("protection_tape", "TAPE", 6.0), ("protection_tube", "Wellrohr NW10", 25.0)):
        w('\t<Wire_protection id="%s">\n\t\t<Part_number>%s</Part_number>\n'
          '\t\t<Company_name>cablefit</Company_name>\n\t\t<Version>1</Version>\n'
          '\t\t<Abbreviation>/NULL</Abbreviation>\n\t\t<Description>%s</Description>\n'
          '\t\t<Mass_information id="%s_mass">\n\t\t\t<Unit_component>unit_gpm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Mass_information>\n'
          '\t\t<Protection_type>%s</Protection_type>\n\t</Wire_protection>\n'
          % (pid, pid, ptype, pid, mass, ptype))
    gauges = [(1.6, 12.0, 4.8), (2.1, 20.0, 6.3), (2.6, 32.0, 7.8)]  # OD [mm], g/m, bend radius
    for g, (od, mass, bend) in enumerate(gauges, 1):
        w('\t<General_wire id="wire_part_%d">\n\t\t<Part_number>SYN-WIRE-%d</Part_number>\n'
          '\t\t<Company_name>cablefit</Company_name>\n\t\t<Version>1</Version>\n'
          '\t\t<Abbreviation>/NULL</Abbreviation>\n\t\t<Description>wire</Description>\n'
          '\t\t<Mass_information id="wire_mass_%d">\n\t\t\t<Unit_component>unit_gpm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Mass_information>\n'
          '\t\t<Wire_type>individual wire</Wire_type>\n'
          '\t\t<Bend_radius id="wire_bend_%d">\n\t\t\t<Unit_component>unit_mm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Bend_radius>\n'
          '\t\t<Outside_diameter id="wire_od_%d">\n\t\t\t<Unit_component>unit_mm</Unit_component>\n'
          '\t\t\t<Value_component>%.1f</Value_component>\n\t\t</Outside_diameter>\n'
          '\t</General_wire>\n' % (g, g, g, mass, g, bend, g, od))
    w('\t<Harness id="harness_1">\n\t\t<Part_number>SYN-HARNESS-%d</Part_number>\n'
      '\t\t<Company_name>cablefit</Company_name>\n\t\t<Version>1</Version>\n'
      '\t\t<Abbreviation>/NULL</Abbreviation>\n\t\t<Description>synthetic harness</Description>\n'
      % len(h.segments))
    ends = [1] + h.leaves
    for i, n in enumerate(ends, 1):
        w('\t\t<Connector_occurrence id="connector_%d">\n\t\t\t<Id>X%d</Id>\n'
          '\t\t\t<Part>housing_1</Part>\n\t\t</Connector_occurrence>\n' % (i, i))
    for i, leaf in enumerate(h.leaves, 1):
        w('\t\t<General_wire_occurrence xsi:type="kbl:Wire_occurrence" id="wire_%d">\n'
          '\t\t\t<Part>wire_part_%d</Part>\n\t\t\t<Wire_number>%d</Wire_number>\n'
          '\t\t</General_wire_occurrence>\n' % (i, 1 + i % len(gauges), i))
    for s in trunk_segments:
        w('\t\t<Fixing_occurrence id="fixing_%d">\n\t\t\t<Id>F%d</Id>\n'
          '\t\t\t<Part>fixing_part_1</Part>\n\t\t</Fixing_occurrence>\n' % (s, s))
    for s in range(1, len(h.segments) + 1):
        part = "protection_tape" if s in trunk_segments else "protection_tube"
        if s in trunk_segments or s % 3 == 0:
            w('\t\t<Wire_protection_occurrence id="protection_%d">\n\t\t\t<Id>P%d</Id>\n'
              '\t\t\t<Part>%s</Part>\n\t\t</Wire_protection_occurrence>\n' % (s, s, part))
    w('\t</Harness>\n')
    connector_at = {n: i for i, n in enumerate(ends, 1)}
    for n, p in enumerate(h.nodes, 1):
        w('\t<Node id="Node_%d">\n\t\t<Id>N%d</Id>\n\t\t<Cartesian_point>Cartesian_point_%d'
          '</Cartesian_point>\n' % (n, n, p))
        if n in connector_at:
            w('\t\t<Referenced_components>connector_%d</Referenced_components>\n' % connector_at[n])
        w('\t</Node>\n')
    for i, leaf in enumerate(h.leaves, 1):
        w('\t<Routing id="routing_%d">\n\t\t<Routed_wire>wire_%d</Routed_wire>\n'
          '\t\t<Segments>%s</Segments>\n\t</Routing>\n'
          % (i, i, " ".join("Segment_%d" % s for s in path(h, leaf))))
    for s, (a, b, ids, length) in enumerate(h.segments, 1):
        w('\t<Segment id="Segment_%d">\n\t\t<Id>S%d</Id>\n' % (s, s))
        w('\t\t<Virtual_length id="virtual_length_%d">\n\t\t\t<Unit_component>unit_mm'
          '</Unit_component>\n\t\t\t<Value_component>%.6f</Value_component>\n'
          '\t\t</Virtual_length>\n' % (s, length))
        w('\t\t<End_node>Node_%d</End_node>\n\t\t<Start_node>Node_%d</Start_node>\n' % (b, a))
        w('\t\t<Center_curve id="center_curve_%d">\n\t\t\t<Degree>1</Degree>\n'
          '\t\t\t<Control_points>%s</Control_points>\n\t\t</Center_curve>\n'
          % (s, " ".join("Cartesian_point_%d" % i for i in ids)))
        if s in trunk_segments:
            w('\t\t<Fixing_assignment id="fixing_assignment_%d">\n\t\t\t<Location>0.5</Location>\n'
              '\t\t\t<Fixing>fixing_%d</Fixing>\n\t\t</Fixing_assignment>\n' % (s, s))
        if s in trunk_segments or s % 3 == 0:
            lo, hi = (0.1, 0.9) if s in trunk_segments else (0.0, 0.6)
            w('\t\t<Protection_area id="protection_area_%d">\n'
              '\t\t\t<Start_location>%.6f</Start_location>\n\t\t\t<End_location>%.6f</End_location>\n'
              '\t\t\t<Associated_protection>protection_%d</Associated_protection>\n'
              '\t\t</Protection_area>\n' % (s, lo, hi, s))
        w('\t</Segment>\n')
    w('\t<Unit id="unit_mm">\n\t\t<Si_unit_name>metre</Si_unit_name>\n\t\t<Si_prefix>milli'
      '</Si_prefix>\n\t</Unit>\n')
    w('\t<Unit id="unit_gpm">\n\t\t<Unit_name>GramPerMetre</Unit_name>\n\t</Unit>\n')
    w('</kbl:KBL_container>\n')


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 183
    h, trunk = build(count)
    with open(sys.argv[1], "w") as out:
        write(h, trunk, out)
    print("%s: %d segments, %d nodes, %d connectors, %d wires" %
          (sys.argv[1], len(h.segments), len(h.nodes), len(h.leaves) + 1, len(h.leaves)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
