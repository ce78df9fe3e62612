#!/usr/bin/env python3
"""Writes bench/out/bunny_field.toml: N placements (default 10,000: 6.9 x 10^8 triangles) of one
Stanford bunny (../shared/models/stanford-bunny.obj) on a grid over a checkered floor, each turned
and scaled a little, by a declared object: instances, one copy of the mesh on each backend.
    python3 bench/make_bunny_field.py [N] [--matte]
With --matte, bench/out/bunny_field_matte.toml instead: the same bunnies, flat and matte, with no
floor and one ray per pixel, for the driver's ray queries to trace alike (bench/ray_query.sh).
"""
import math
import os
import random
import sys

args = [a for a in sys.argv[1:] if a != "--matte"]
matte = "--matte" in sys.argv[1:]
n = int(args[0]) if args else 10000
side = math.ceil(math.sqrt(n))
random.seed(1)
os.makedirs("bench/out", exist_ok=True)
with open(f"bench/out/bunny_field{'_matte' if matte else ''}.toml", "w") as f:
    f.write(f"""# {n} bunnies: written by bench/make_bunny_field.py{' --matte' if matte else ''}.
[render]
width = 1280
height = 720
samples = {1 if matte else 3}
max_depth = {0 if matte else 3}
background = [0.42, 0.56, 0.78]

[camera]
eye = [0, 3.2, -4]
look_at = [0, 0.4, 10]
fov = 45

[[light]]
position = [-30, 60, -40]
color = [0.8, 0.8, 0.8]
""")
    if matte:
        f.write("""
[material.clay]
color = [0.92, 0.88, 0.8]

[declare.bunny]
type = "mesh"
file = "../../../shared/models/stanford-bunny.obj"
material = "clay"
""")
    else:
        f.write("""
[material.floor]
checker = { colors = [[1, 1, 1], [0.42, 0.42, 0.42]], size = 1.0 }

[material.porcelain]
color = [0.92, 0.88, 0.8]
specular = 0.5
shininess = 40

[declare.bunny]
type = "mesh"
file = "../../../shared/models/stanford-bunny.obj"
smooth = true
material = "porcelain"

[[object]]
type = "plane"
normal = [0, 1, 0]
material = "floor"
""")
    for k in range(n):
        x = (k % side - side / 2) * 0.9 + random.uniform(-0.2, 0.2)
        z = (k // side) * 0.9 + random.uniform(-0.2, 0.2)
        s = random.uniform(4.5, 6.5)
        a = random.uniform(0, 360)
        f.write(f'[[object]]\ntype = "object"\nof = "bunny"\n'
                f'transform = [{{ scale = {s:.3f} }}, {{ rotate = [0, {a:.1f}, 0] }}, '
                f'{{ translate = [{x:.3f}, {-0.033 * s:.4f}, {z:.3f}] }}]\n')
