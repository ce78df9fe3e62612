#!/usr/bin/env python3
"""How much of POV-Ray's shape vocabulary lancer covers, over POV-Ray's own example scenes.

A scene counts as covered when every shape keyword its .pov file uses is one lancer has (the
file itself: shapes from included .inc files are not followed). Prints the share of scenes
covered, and for each keyword lancer lacks, the share of scenes that use it.

    apt-get install povray-examples
    python3 bench/pov_coverage.py [DIR]   # DIR: /usr/share/doc/povray/examples by default
"""
import pathlib
import re
import sys

# POV-Ray 3.7's object keywords (finite, infinite and CSG; `object` only refers to a declared one).
POV_SHAPES = {
    "bicubic_patch", "blob", "box", "cone", "cubic", "cylinder", "difference", "disc", "height_field",
    "intersection", "isosurface", "julia_fractal", "lathe", "lemon", "merge", "mesh", "mesh2", "ovus",
    "parametric", "plane", "poly", "polygon", "polynomial", "prism", "quadric", "quartic",
    "smooth_triangle", "sor", "sphere", "sphere_sweep", "superellipsoid", "text", "torus", "triangle",
    "union",
}

# What lancer has, as POV-Ray words: its shapes, its exact surfaces (implicit polynomials and
# equations, parametric surfaces, Bezier patches), groups for union and its CSG. (A scene whose
# CSG combines shapes lancer's CSG does not take yet, tori or isosurfaces, still counts: the
# count is of words, as the figure.) POV-Ray's meshes (mesh, mesh2 and their triangles)
# are lancer's meshes, whose triangles come from an OBJ or PLY file. Superellipsoids and blobs
# are implicit surfaces in lancer (a blob of at most about 18 components: its function's
# operations are limited).
LANCER = {
    "sphere", "box", "plane", "disc", "cylinder", "cone", "torus", "union", "intersection", "difference", "merge",
    "bicubic_patch", "parametric", "isosurface", "poly", "polynomial", "quartic", "cubic", "quadric",
    "mesh", "mesh2", "triangle", "smooth_triangle", "superellipsoid", "blob",
}


def words(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)  # block comments
    text = re.sub(r"//[^\n]*", " ", text)                # line comments
    text = re.sub(r'"(?:\\.|[^"\\])*"', " ", text)       # strings (file names, text)
    return set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text))


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "/usr/share/doc/povray/examples")
    scenes = sorted(p for p in root.rglob("*.pov"))
    if not scenes:
        sys.exit(f"no .pov files under {root}: apt-get install povray-examples")
    used = {p: words(p.read_text(errors="replace")) & POV_SHAPES for p in scenes}
    covered = sum(1 for shapes in used.values() if shapes <= LANCER)
    print(f"{len(scenes)} scenes under {root}")
    print(f"covered (every shape keyword is one lancer has): {covered} = {100.0 * covered / len(scenes):.1f}%")
    missing = {}
    for shapes in used.values():
        for s in shapes - LANCER:
            missing[s] = missing.get(s, 0) + 1
    print("shape keywords lancer lacks, by the share of scenes using them:")
    for s, n in sorted(missing.items(), key=lambda kv: -kv[1]):
        print(f"  {s:16} {100.0 * n / len(scenes):5.1f}%  ({n})")


if __name__ == "__main__":
    main()
