#!/usr/bin/env python3
"""Writes the meshes of scenes/meshes.toml into scenes/models/: a (3, 2) torus knot as a tube
(smooth, with vertex normals), and a faceted gem (flat). Run from the repository root:
    python3 scenes/tools/make_meshes.py
With --million, the same knot of 10^6 triangles for the benchmark, into bench/out/.
"""
import math
import os


def knot_point(t, p=3, q=2, R=1.0, r=0.45):
    phi = p * t
    rr = R + r * math.cos(q * t)
    return (rr * math.cos(phi), r * math.sin(q * t), rr * math.sin(phi))


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a):
    length = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
    return (a[0] / length, a[1] / length, a[2] / length)


def torus_knot(path, segments=240, sides=16, tube=0.16):
    vs, ns, fs = [], [], []
    for i in range(segments):
        t = 2 * math.pi * i / segments
        c = knot_point(t)
        tangent = norm(sub(knot_point(t + 1e-4), knot_point(t - 1e-4)))
        side = norm(cross(tangent, (0.0, 1.0, 0.0)))
        up = cross(side, tangent)
        for j in range(sides):
            a = 2 * math.pi * j / sides
            n = add(mul(side, math.cos(a)), mul(up, math.sin(a)))
            vs.append(add(c, mul(n, tube)))
            ns.append(n)
    for i in range(segments):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % segments) * sides + j
            c = ((i + 1) % segments) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            fs.append((a, b, c, d))
    with open(path, "w") as f:
        f.write("# (3, 2) torus knot tube, written by scenes/tools/make_meshes.py\n")
        for v in vs: f.write("v %.6f %.6f %.6f\n" % v)
        for n in ns: f.write("vn %.6f %.6f %.6f\n" % n)
        for q in fs: f.write("f " + " ".join("%d//%d" % (k + 1, k + 1) for k in q) + "\n")


def gem(path, facets=12):
    # A brilliant-like gem: table, crown ring, girdle ring, pavilion point.
    vs = [(0.0, 0.55, 0.0)]
    crown = [(0.55 * math.cos(2 * math.pi * k / facets), 0.55, 0.55 * math.sin(2 * math.pi * k / facets)) for k in range(facets)]
    girdle = [(math.cos(2 * math.pi * (k + 0.5) / facets), 0.25, math.sin(2 * math.pi * (k + 0.5) / facets)) for k in range(facets)]
    vs += crown + girdle + [(0.0, -0.75, 0.0)]
    top, c0, g0, bottom = 0, 1, 1 + facets, 1 + 2 * facets
    fs = []
    for k in range(facets):
        k1 = (k + 1) % facets
        fs.append((top, c0 + k1, c0 + k))
        fs.append((c0 + k, c0 + k1, g0 + k))
        fs.append((c0 + k1, g0 + k1, g0 + k))
        fs.append((g0 + k, g0 + k1, bottom))
    # Its own materials (an MTL beside it): the crown (table and upper facets) and the pavilion.
    mtl = os.path.splitext(path)[0] + ".mtl"
    with open(mtl, "w") as f:
        f.write("# the gem's materials, written by scenes/tools/make_meshes.py\n")
        f.write("newmtl crown\nKd 0.55 0.75 0.95\nKs 0.9 0.9 0.9\nNs 120\n")
        f.write("newmtl pavilion\nKd 0.25 0.35 0.85\nKs 0.6 0.6 0.6\nNs 60\n")
    with open(path, "w") as f:
        f.write("# a faceted gem, written by scenes/tools/make_meshes.py\n")
        f.write("mtllib %s\n" % os.path.basename(mtl))
        for v in vs: f.write("v %.6f %.6f %.6f\n" % v)
        for k, t in enumerate(fs):
            if k % 4 == 0: f.write("usemtl crown\n")
            if k % 4 == 3: f.write("usemtl pavilion\n")
            f.write("f %d %d %d\n" % tuple(j + 1 for j in t))


if __name__ == "__main__":
    import sys
    if len(sys.argv) > 1 and sys.argv[1] == "--million":
        # The benchmark's mesh of 10^6 triangles (bench/knot_million.toml), into bench/out/.
        os.makedirs("bench/out", exist_ok=True)
        torus_knot("bench/out/torus_knot_million.obj", segments=4096, sides=122)
    else:
        os.makedirs("scenes/models", exist_ok=True)
        torus_knot("scenes/models/torus_knot.obj")
        gem("scenes/models/gem.obj")
