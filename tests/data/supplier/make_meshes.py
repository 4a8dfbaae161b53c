# Writes the test meshes of this folder as binary STL in millimetres (plain python3):
# - coax_layers.stl: a coax cable (6 mm jacket over a 4.8 mm shield over a 4.2 mm dielectric over
#   a 1.2 mm conductor) along 60 mm straight, a 50 mm-radius quarter bend and 60 mm straight,
#   each layer a closed surface of its own (the jacket, shield and dielectric hollow, each touching
#   the next), each tessellated with its own number of sides (16, 20, 24, 10), a ring every 3 mm,
#   as a CAD system meshes the solids one by one: where they touch, their vertices coincide only
#   where those counts agree.
# - ear_tube.stl: a stethoscope's ear tube, 3.2 mm across with a 2 mm bore, 60 mm straight, a
#   40 mm-radius bend of 100 degrees and 30 mm straight, its two rims rounded (each a half torus
#   from the outer wall to the bore: no sharp edge anywhere), 16 sides, a ring every 1.3 mm.
import math
import struct


def route(pieces, step):
    """Points every `step` along straight pieces ('line', length) and planar bends ('arc',
    radius, angle), starting at the origin along +z, bending towards +x."""
    pts, pos, heading = [(0.0, 0.0, 0.0)], (0.0, 0.0, 0.0), 0.0  # heading: angle from +z to +x
    for piece in pieces:
        length = piece[1] if piece[0] == 'line' else piece[1] * piece[2]
        n = max(1, int(round(length / step)))
        start, h0 = pos, heading
        for i in range(1, n + 1):
            u = length * i / n
            if piece[0] == 'line':
                p = (start[0] + u * math.sin(h0), 0.0, start[2] + u * math.cos(h0))
            else:
                radius = piece[1]
                a = u / radius
                cx, cz = start[0] + radius * math.cos(h0), start[2] - radius * math.sin(h0)
                p = (cx - radius * math.cos(h0 + a), 0.0, cz + radius * math.sin(h0 + a))
            pts.append(p)
        pos = pts[-1]
        if piece[0] == 'arc':
            heading = h0 + piece[2]
    return pts


def frames(pts):
    out, prev = [], None
    for i, p in enumerate(pts):
        a, b = pts[max(0, i - 1)], pts[min(len(pts) - 1, i + 1)]
        t = [b[k] - a[k] for k in range(3)]
        norm = math.sqrt(sum(x * x for x in t))
        t = [x / norm for x in t]
        ref = prev if prev else (0.0, 1.0, 0.0)
        d = sum(ref[k] * t[k] for k in range(3))
        n = [ref[k] - d * t[k] for k in range(3)]
        norm = math.sqrt(sum(x * x for x in n))
        n = [x / norm for x in n]
        b = (t[1] * n[2] - t[2] * n[1], t[2] * n[0] - t[0] * n[2], t[0] * n[1] - t[1] * n[0])
        out.append((t, n, b))
        prev = n
    return out


def ring(p, f, r, sides, along=0.0):
    t, n, b = f
    return [tuple(p[k] + along * t[k] + r * (math.cos(2 * math.pi * j / sides) * n[k] +
                                            math.sin(2 * math.pi * j / sides) * b[k])
                  for k in range(3)) for j in range(sides)]


def strip(a_ring, b_ring, flip=False):
    """Quads between two rings of equal size, outward when going a -> b along the tube."""
    tris, sides = [], len(a_ring)
    for j in range(sides):
        a, b = a_ring[j], a_ring[(j + 1) % sides]
        c, d = b_ring[j], b_ring[(j + 1) % sides]
        tris += [(a, d, b), (a, c, d)] if flip else [(a, b, d), (a, d, c)]
    return tris


def annulus(outer, inner, flip):
    """The flat end between an outer ring and an inner ring of other sizes (a fan each way)."""
    tris = []
    no, ni = len(outer), len(inner)
    i = j = 0
    while i < no or j < ni:
        # advance along whichever ring's next vertex comes first by angle
        if j >= ni or (i < no and (i + 1) / no <= (j + 1) / ni):
            t = (outer[i % no], outer[(i + 1) % no], inner[j % ni])
            i += 1
        else:
            t = (outer[i % no], inner[(j + 1) % ni], inner[j % ni])
            j += 1
        tris.append((t[0], t[2], t[1]) if flip else t)
    return tris


def layer(pts, fr, ro, ri, sides):
    outer = [ring(p, f, ro, sides) for p, f in zip(pts, fr)]
    tris = []
    for i in range(len(pts) - 1):
        tris += strip(outer[i], outer[i + 1])
    if ri > 0:
        inner = [ring(p, f, ri, sides) for p, f in zip(pts, fr)]
        for i in range(len(pts) - 1):
            tris += strip(inner[i], inner[i + 1], flip=True)
        tris += annulus(outer[0], inner[0], flip=True) + annulus(outer[-1], inner[-1], flip=False)
    else:
        for end, flip in ((0, True), (len(pts) - 1, False)):
            c = pts[end]
            for j in range(sides):
                a, b = outer[end][j], outer[end][(j + 1) % sides]
                tris.append((a, c, b) if flip else (a, b, c))
    return tris


def rounded_lip_tube(pts, fr, ro, ri, sides, lip_steps=6):
    rm, rw = 0.5 * (ro + ri), 0.5 * (ro - ri)
    loops = []
    for k in range(lip_steps + 1):  # start lip: from the bore over the back to the outer wall
        a = math.pi - math.pi * k / lip_steps
        loops.append(ring(pts[0], fr[0], rm + rw * math.cos(a), sides, -rw * math.sin(a)))
    for i in range(1, len(pts) - 1):
        loops.append(ring(pts[i], fr[i], ro, sides))
    for k in range(lip_steps + 1):  # end lip: from the outer wall over the front to the bore
        a = math.pi * k / lip_steps
        loops.append(ring(pts[-1], fr[-1], rm + rw * math.cos(a), sides, rw * math.sin(a)))
    for i in range(len(pts) - 2, 0, -1):
        loops.append(ring(pts[i], fr[i], ri, sides))
    tris = []
    for q in range(len(loops)):
        tris += strip(loops[q], loops[(q + 1) % len(loops)])
    return tris


def write_stl(path, tris):
    with open(path, 'wb') as f:
        f.write(b'\0' * 80)
        f.write(struct.pack('<I', len(tris)))
        for t in tris:
            f.write(struct.pack('<3f', 0, 0, 0))
            for v in t:
                f.write(struct.pack('<3f', *v))
            f.write(b'\0\0')


coax = route([('line', 60.0), ('arc', 50.0, math.pi / 2), ('line', 60.0)], 3.0)
cf = frames(coax)
tris = []
for ro, ri, sides in ((3.0, 2.4, 16), (2.4, 2.1, 20), (2.1, 0.6, 24), (0.6, 0.0, 10)):
    tris += layer(coax, cf, ro, ri, sides)
write_stl('coax_layers.stl', tris)

ear = route([('line', 60.0), ('arc', 40.0, math.radians(100)), ('line', 30.0)], 1.3)
write_stl('ear_tube.stl', rounded_lip_tube(ear, frames(ear), 1.6, 1.0, 16))
