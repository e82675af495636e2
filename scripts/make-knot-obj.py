#!/usr/bin/env python3
"""Writes scenes/knot.obj: a trefoil knot as a closed tube, for the shipped scene
scenes/knot.json (an OBJ mesh with thin, curved, self-occluding parts; 2,400 triangles).

The tube follows p(t) = (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) / 3 with a ring of
RING vertices every 2 pi / SEGMENTS, each ring in the curve's Frenet frame (periodic, so
the tube closes on itself). Faces are wound outward (counter-clockwise seen from
outside), as the scene loader's check (`Mesh::check_closed`) and back-face culling want.
Run from the repository's root: python3 scripts/make-knot-obj.py
"""
import math

SEGMENTS, RING, RADIUS = 120, 10, 0.13


def p(t):
    return ((math.sin(t) + 2 * math.sin(2 * t)) / 3, (math.cos(t) - 2 * math.cos(2 * t)) / 3, -math.sin(3 * t) / 3)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return tuple(x / n for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


h = 1e-4
verts, centres = [], []
for i in range(SEGMENTS):
    t = 2 * math.pi * i / SEGMENTS
    c, d1 = p(t), unit(sub(p(t + h), p(t - h)))
    d2 = sub(sub(p(t + h), c), sub(c, p(t - h)))
    b = unit(cross(d1, d2))
    n = cross(b, d1)
    centres.append(c)
    for j in range(RING):
        a = 2 * math.pi * j / RING
        verts.append(tuple(c[k] + RADIUS * (math.cos(a) * n[k] + math.sin(a) * b[k]) for k in range(3)))

faces = []
for i in range(SEGMENTS):
    for j in range(RING):
        q = [((i + di) % SEGMENTS) * RING + (j + dj) % RING for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            a, b, c = (verts[k] for k in tri)
            normal = cross(sub(b, a), sub(c, a))
            # Outward: away from the tube's axis at this ring.
            if dot(normal, sub(a, centres[i])) < 0:
                tri = (tri[0], tri[2], tri[1])
            faces.append(tri)

with open("scenes/knot.obj", "w") as f:
    f.write("# A trefoil knot tube, written by scripts/make-knot-obj.py (see there).\n")
    for v in verts:
        f.write("v %.6f %.6f %.6f\n" % v)
    for t in faces:
        f.write("f %d %d %d\n" % tuple(k + 1 for k in t))
