#!/usr/bin/env python3
"""One-off converter: POV-Ray's teapot.inc (32 bicubic_patch blocks) -> lancer's BPT patch file.

Not part of the build. It was run once to produce scenes/teapot.bpt (and the indexed copy
tests/data/teapot.newell, used to check that both patch-file formats read the same teapot):

    python3 scenes/tools/pov_teapot_to_bpt.py \
        /usr/share/doc/povray/examples/advanced/teapot/teapot.inc \
        scenes/teapot.bpt --newell tests/data/teapot.newell

The source comes with Debian's povray-examples package (`apt-get install povray-examples`).
Control points are copied in the order POV-Ray lists them: 4 rows of 4 points per patch; the
row index becomes u (i) and the position in the row becomes v (j), so points[4*i + j] is the
j-th point of row i. Coordinates are written as the shortest decimal that parses to the same
double as the source text. The scene's `rotate Teapot_Orientation` is not applied: the data
stays in Newell's frame (z up).
"""
import argparse
import hashlib
import re
import sys

HEADER = """\
# The Utah teapot: Martin Newell's 32 bicubic Bezier patches (1975; the 4 bottom patches are a
# later addition), z up: bottom at z = 0, rim at z = 2.4, lid apex at z = 3.15.
#
# Provenance: converted once by scenes/tools/pov_teapot_to_bpt.py from
#   {source}
#   (sha256 {sha256}),
#   Debian 12 package povray-examples {version}: "Teapot.inc - Bezier patch definition of the utah
#   Teapot, adapted by Alexander Enzmann", Persistence of Vision Raytracer sample file
#   (updated 09Aug2008 jh, 28Sep2008 cjc).
# Licence: Creative Commons Attribution 3.0 Unported (CC BY 3.0),
#   http://creativecommons.org/licenses/by/3.0/ , as stated in that file's header.
#   Attribution: the POV-Ray team (Persistence of Vision Raytracer Pty. Ltd.) and Alexander Enzmann.
#   (Debian's copyright file lists the scenes/advanced folder as CC BY-SA 3.0; the file itself
#   says CC BY 3.0.)
# Changes: the format, and one corrected typo: patch 12, point 7 is (2.0, 1.12, 0.45), as in its
#   mirror image patch 9 and in other copies of the data; teapot.inc has (2.0, 1.2, 0.45). All
#   other points, and their order, are as in the source.
#
# Format (BPT): the patch count, then per patch a line "3 3" (degrees in u and v) and 16 lines
# "x y z", row-major: line 4*i + j is control point (i, j), i along u, j along v.
"""


def read_pov_patches(text):
    """The control points of every bicubic_patch block, in source order."""
    patches = []
    for block in re.split(r"\bbicubic_patch\b", text)[1:]:
        body = block.split("texture", 1)[0]  # the points come before the texture statement
        points = []
        for vec in re.findall(r"<([^>]*)>", body):
            coords = [c.strip() for c in vec.split(",")]
            if len(coords) != 3:
                sys.exit(f"not a 3-vector: <{vec}>")
            points.append(tuple(float(c) for c in coords))
        if len(points) != 16:
            sys.exit(f"patch {len(patches) + 1} has {len(points)} control points, not 16")
        patches.append(points)
    return patches


# teapot.inc mistypes one coordinate: patch 12 has (2.0, 1.2, 0.45) where its mirror image,
# patch 9, has (2.0, -1.12, 0.45), the three other body quarters have 1.12 in that place, and
# other copies of the data (e.g. mkeeter/teapot-mrep's teapot.bpt) have (2.0, 1.12, 0.45). The
# typo puts a bump in the body and breaks the teapot's mirror symmetry, so it is corrected here.
# (patch index from 0, point index from 0, value in the source, corrected value)
FIXES = [(11, 6, (2.0, 1.2, 0.45), (2.0, 1.12, 0.45))]


def apply_fixes(patches):
    for k, i, wrong, right in FIXES:
        if patches[k][i] != wrong:
            sys.exit(f"patch {k + 1} point {i + 1} is {patches[k][i]}, not the known typo {wrong}")
        patches[k][i] = right


def check_mirror_symmetry(patches):
    """Every patch has a mirror image in y (the body, lid and bottom also in x)."""
    sets = [frozenset(p) for p in patches]
    for k, p in enumerate(patches):
        if frozenset((x, -y, z) for x, y, z in p) not in sets:
            sys.exit(f"patch {k + 1} has no mirror image in y")


def fmt(x):
    return repr(x)


def check_teapot(patches):
    zs = [p[2] for patch in patches for p in patch]
    assert len(patches) == 32, len(patches)
    assert min(zs) == 0.0 and max(zs) == 3.15, (min(zs), max(zs))
    assert patches[0][0] == (1.4, 0.0, 2.4), patches[0][0]  # the rim


def write_bpt(path, patches, header):
    with open(path, "w", newline="\n") as out:
        out.write(header)
        out.write(f"{len(patches)}\n")
        for patch in patches:
            out.write("3 3\n")
            for p in patch:
                out.write(" ".join(fmt(c) for c in p) + "\n")


def write_newell(path, patches, header):
    """The indexed format: shared vertices listed once, patches as 16 1-based indices."""
    vertices, index = [], {}
    rows = []
    for patch in patches:
        row = []
        for p in patch:
            if p not in index:
                index[p] = len(vertices) + 1
                vertices.append(p)
            row.append(index[p])
        rows.append(row)
    with open(path, "w", newline="\n") as out:
        out.write(header.replace("Format (BPT)", "Original format (BPT)"))
        out.write("# This copy is in the indexed Newell format: patch count, 16 1-based vertex indices per\n")
        out.write("# patch, vertex count, one vertex \"x, y, z\" per line.\n")
        out.write(f"{len(rows)}\n")
        for row in rows:
            out.write(", ".join(str(i) for i in row) + "\n")
        out.write(f"{len(vertices)}\n")
        for v in vertices:
            out.write(", ".join(fmt(c) for c in v) + "\n")
    return len(vertices)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("teapot_inc")
    ap.add_argument("bpt_out")
    ap.add_argument("--newell", help="also write the indexed (Newell) format here")
    ap.add_argument("--package-version", default="1:3.7.0.10-2")
    args = ap.parse_args()
    raw = open(args.teapot_inc, "rb").read()
    patches = read_pov_patches(raw.decode("utf-8"))
    apply_fixes(patches)
    check_teapot(patches)
    check_mirror_symmetry(patches)
    header = HEADER.format(source=args.teapot_inc, sha256=hashlib.sha256(raw).hexdigest(),
                           version=args.package_version)
    write_bpt(args.bpt_out, patches, header)
    if args.newell:
        n = write_newell(args.newell, patches, header)
        print(f"{args.newell}: {len(patches)} patches, {n} distinct vertices")
    print(f"{args.bpt_out}: {len(patches)} patches")


if __name__ == "__main__":
    main()
