#!/usr/bin/env python3
"""Writes the point set of scenes/galaxy.toml into scenes/models/: a spiral galaxy of 4,000
spheres (x y z radius, and an sRGB colour per point) as an ASCII PLY. Run from the repository root:
    python3 scenes/tools/make_points.py
With --million N, a binary PLY of N spheres at random in a 10-unit cube, for bench/million_spheres.sh,
into the file given after N.
"""
import math
import random
import struct
import sys


def galaxy(path, count=4000, arms=3):
    random.seed(7)
    rows = []
    for i in range(count):
        core = i < count // 5
        if core:  # a warm bulge
            r = abs(random.gauss(0.0, 0.45))
            angle = random.uniform(0, 2 * math.pi)
            height = random.gauss(0.0, 0.18)
            color = (255, random.randint(170, 215), random.randint(90, 140))
        else:  # blue-white arms, logarithmic spirals, thinner outward
            arm = random.randrange(arms)
            r = 0.4 + 3.2 * math.sqrt(random.random())
            angle = 2 * math.pi * arm / arms + 1.9 * math.log(r / 0.4) + random.gauss(0.0, 0.22)
            height = random.gauss(0.0, 0.06)
            w = random.random()
            color = (int(150 + 100 * w), int(180 + 70 * w), 255)
        x, z = r * math.cos(angle), r * math.sin(angle)
        radius = random.uniform(0.012, 0.045) * (1.6 if core else 1.0)
        rows.append(f"{x:.5f} {height:.5f} {z:.5f} {radius:.5f} {color[0]} {color[1]} {color[2]}")
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment scenes/tools/make_points.py\n")
        f.write(f"element vertex {count}\n")
        for p in ("x", "y", "z", "radius"):
            f.write(f"property float {p}\n")
        for p in ("red", "green", "blue"):
            f.write(f"property uchar {p}\n")
        f.write("end_header\n" + "\n".join(rows) + "\n")


def million(path, count):
    random.seed(1)
    pack = struct.Struct("<fff")
    with open(path, "wb") as f:
        f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {count}\n"
                "property float x\nproperty float y\nproperty float z\nend_header\n".encode())
        f.write(b"".join(pack.pack(random.uniform(-5, 5), random.uniform(0.5, 10.5), random.uniform(-5, 5))
                         for _ in range(count)))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--million":
        million(sys.argv[3], int(sys.argv[2]))
    else:
        galaxy("scenes/models/galaxy.ply")
