#!/usr/bin/env python3
"""A blob of thousands of components for bench/run.sh's `solids` suite: a rippled pool of liquid
(a sheet of N x N sphere components, each meeting its four neighbours' fields) with a crown of
droplets rising from its centre, on a checkered floor. Writes the scene to stdout.

    python3 bench/make_blob_field.py [N=70] > bench/out/blob_field.toml
"""
import math
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 70
spacing = 8.0 / n
spheres = []
for i in range(n):
    for k in range(n):
        x, z = (i - (n - 1) / 2) * spacing, (k - (n - 1) / 2) * spacing
        r = math.hypot(x, z)
        y = 0.6 + 0.12 * math.cos(4.0 * r) * math.exp(-0.25 * r)
        spheres.append((x, y, z, spacing, 1.0))
# The crown: rings of droplets rising from the centre, each smaller and higher.
for ring in range(3):
    count = 16 + 8 * ring
    for j in range(count):
        a = 2 * math.pi * (j + 0.5 * ring) / count
        rad = 0.5 + 0.35 * ring
        spheres.append((rad * math.cos(a), 1.1 + 0.45 * (2 - ring), rad * math.sin(a), 0.3 - 0.05 * ring, 1.0))

print(f"""# bench/make_blob_field.py {n}: a blob of {len(spheres)} sphere components (a rippled pool and a
# crown of droplets), one material, on a checkered floor.

[render]
width = 1280
height = 720
samples = 3

[camera]
eye = [0, 5.5, -8.5]
look_at = [0, 0.6, 0]
fov = 40

[[light]]
position = [-6, 10, -7]
color = [0.9, 0.9, 0.9]

[material.floor]
checker = {{ colors = [[0.9, 0.9, 0.9], [0.25, 0.27, 0.3]], size = 1 }}
diffuse = 0.8

[material.liquid]
color = [0.2, 0.45, 0.8]
ambient = 0.1
diffuse = 0.6
specular = 0.9
shininess = 120

[[object]]
type = "plane"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"

[[object]]
type = "blob"
threshold = 0.8
material = "liquid"
spheres = [""")
for x, y, z, r, s in spheres:
    print(f"  {{ center = [{x:.6g}, {y:.6g}, {z:.6g}], radius = {r:.6g}, strength = {s:g} }},")
print("]")
