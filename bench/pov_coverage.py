#!/usr/bin/env python3
"""How much of POV-Ray's vocabulary lancer covers, over POV-Ray's own example scenes.

Two counts, each of the words a scene's .pov file uses (the file itself: included .inc files are
not followed, but using a name one of POV-Ray's texture libraries declares counts as using it):
  * shapes: a scene counts when every shape keyword it uses is one lancer has;
  * ports today: when, besides, no word it uses is a feature lancer lacks (a camera, pattern,
    finish, light, object modifier, atmosphere or language feature; the list is LACKS below), so
    that it can be written in lancer's terms by hand, as bench/port/ does. A word used inside a
    sky_sphere counts as the sky's (lancer's [sky] takes a gradient or a pattern).
Prints both shares, and for each missing word the share of scenes that use it.

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
# count is of words, as the issue's figure.) POV-Ray's meshes (mesh, mesh2 and their triangles)
# are lancer's meshes, whose triangles come from an OBJ or PLY file. Superellipsoids, blobs,
# sors, lathes, prisms and text are shapes of their own, exact.
LANCER = {
    "sphere", "box", "plane", "disc", "cylinder", "cone", "torus", "union", "intersection", "difference", "merge",
    "bicubic_patch", "parametric", "isosurface", "poly", "polynomial", "quartic", "cubic", "quadric",
    "mesh", "mesh2", "triangle", "smooth_triangle", "superellipsoid", "blob", "sor", "lathe", "prism", "text",
}


# Features lancer lacks, as POV-Ray words, by kind (the shapes are POV_SHAPES - LANCER).
LACKS = {
    "camera": {"orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic", "spherical", "aperture",
               "focal_point", "blur_samples", "mesh_camera", "user_defined", "cylindrical camera"},
    "pattern": {"agate", "bozo", "brick", "cells", "crackle", "dents", "facets", "gradient", "granite", "hexagon",
                "julia", "leopard", "mandel", "onion", "planar", "quilted", "radial", "ripples", "spiral1", "spiral2",
                "spotted", "tiles", "waves", "boxed", "cylindrical", "pigment_map", "texture_map", "normal_map",
                "slope_map", "material_map", "average", "image_pattern", "bump_map", "warp", "function"},
    "finish": {"metallic", "brilliance", "irid", "crand", "subsurface", "translucency", "fresnel", "fade_color",
               "dispersion", "caustics"},
    "light": {"parallel", "shadowless", "looks_like", "projected_through", "area_illumination"},
    "object": {"clipped_by", "no_shadow", "no_image", "no_reflection", "double_illuminate"},
    "atmosphere": {"media", "rainbow", "radiosity", "scattering", "emission", "density"},
    "language": {"macro", "array", "rand", "seed"},
}
LACKED = set().union(*LACKS.values())
# Includes whose declared names lancer knows: colors.inc's colours; shapes.inc's and shapesq.inc's
# shapes (quadrics, boxes and quartics, which are written out in lancer's terms).
KNOWN_INCLUDES = {"colors.inc", "shapes.inc", "shapesq.inc", "shapes_old.inc"}


def library_names(include_dir):
    """The names POV-Ray's other include files declare (textures, finishes, skies, ...)."""
    names = set()
    for inc in pathlib.Path(include_dir).glob("*.inc"):
        if inc.name not in KNOWN_INCLUDES:
            names |= set(re.findall(r"#declare\s+([A-Za-z_][A-Za-z_0-9]*)", inc.read_text(errors="replace")))
    return names


def blocks(text, keyword):
    """The text of every `keyword { ... }` block, braces matched."""
    found = []
    for m in re.finditer(rf"\b{keyword}\s*\{{", text):
        depth, j = 1, m.end()
        while j < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            j += 1
        found.append(text[m.end():j])
    return found


def without_sky_spheres(text):
    """The text with every sky_sphere { ... } taken out (its patterns are the sky's)."""
    out, i = [], 0
    for m in re.finditer(r"\bsky_sphere\s*\{", text):
        if m.start() < i:
            continue
        out.append(text[i:m.start()])
        depth, j = 1, m.end()
        while j < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            j += 1
        i = j
    return "".join(out) + text[i:]


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
    texts = {p: p.read_text(errors="replace") for p in scenes}
    used = {p: words(t) & POV_SHAPES for p, t in texts.items()}
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

    libraries = library_names(pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "/usr/share/povray-3.7/include"))
    blockers = {}
    ports = []
    for p, text in texts.items():
        w = words(without_sky_spheres(text))
        if any(re.search(r"\bcylinder\b", b) for b in blocks(text, "camera")):
            w.add("cylindrical camera")  # POV-Ray's `camera { cylinder N }`, not the shape
        lacked = (w & POV_SHAPES) - LANCER | (w & LACKED) | ({"a texture library's name"} if w & libraries else set())
        for word in lacked:
            blockers[word] = blockers.get(word, 0) + 1
        if not lacked:
            ports.append(p)
    print(f"\nport today (every shape and feature word is lancer's): {len(ports)} = {100.0 * len(ports) / len(scenes):.1f}%")
    for p in ports:
        print(f"  {p.relative_to(root)}")
    print("what keeps the others from porting, by the share of scenes using it:")
    for s, n in sorted(blockers.items(), key=lambda kv: -kv[1])[:25]:
        print(f"  {s:24} {100.0 * n / len(scenes):5.1f}%  ({n})")


if __name__ == "__main__":
    main()
