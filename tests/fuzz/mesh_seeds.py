#!/usr/bin/env python3
"""Writes the seed corpora of fuzz_obj and fuzz_ply (tests/fuzz/corpus/obj/, corpus/ply/): small
files of every form the readers take (host/mesh: OBJ corners, MTL statements after a "#MTL" line
as obj_entry serves them; PLY in ascii and both binary byte orders, faces, tristrips, lists to
skip) and the refusals the unit tests check. Run from the repository root."""
import os, struct

QUAD = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
MTL = "\n#MTL\nnewmtl red\nKd 0.9 0.1 0.1\nKs 0.5 0.5 0.5\nNs 32\nd 0.5\nmap_Kd t.png\nnewmtl blue\nKd 0 0 1\nTr 0.2\n"
OBJ = {
    "triangle": QUAD + "f 1 2 3\n",
    "quad": QUAD + "f 1 2 3 4\n",
    "pentagon": QUAD + "v 0.5 2 0\nf 1 2 3 5 4\n",
    "negative": QUAD + "f -4 -3 -2\nv 2 2 2\nf -1 -5 -4\n",
    "vt": QUAD + "vt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/2\n",
    "vn": QUAD + "vn 0 0 1\nf 1//1 2//1 3//1\n",
    "vt-vn": QUAD + "vt 0 0\nvt 1 0\nvn 0 0 1\nvn 0 1 1\nf 1/1/1 2/2/1 3/1/2 4/2/2\n",
    "materials": "mtllib a.mtl\n" + QUAD + "f 1 2 3\nusemtl red\nf 1 3 4\nusemtl blue\nf 2 3 4\n" + MTL,
    "missing-mtl": "mtllib a.mtl\n" + QUAD + "usemtl red\nf 1 2 3\n",
    "missing-texture": "mtllib a.mtl\n" + QUAD + "f 1 2 3\n\n#MTL\nnewmtl x\nmap_Kd t.jpg\n",
    "groups": "# comment\no thing\ng a b\ns 1\n" + QUAD + "l 1 2\np 3\nf 1 2 3 # end\n",
    "degenerate": QUAD + "f 1 1 2\nf 1 2 3\n",
    "all-degenerate": QUAD + "f 1 1 2\n",
    "index-zero": QUAD + "f 0 1 2\n",
    "index-range": QUAD + "f 1 2 9\n",
    "nan": "v 0 nan 0\n" + QUAD + "f 1 2 3\n",
    "huge": "v 0 1e13 0\n" + QUAD + "f 1 2 3\n",
    "zero-normal": QUAD + "vn 0 0 0\nf 1//1 2//1 3//1\n",
    "mixed-corners": QUAD + "vt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n",
    "free-form": QUAD + "curv 0 1 1 2\n",
    "crlf": QUAD.replace("\n", "\r\n") + "f 1 2 3\r\n",
    "w-and-colors": "v 0 0 0 1\nv 1 0 0 1 0 0\nv 0 1 0 0 1 0\nf 1 2 3\n",
    "empty": "",
}

def ply_header(fmt, vertex_props, count, face_elem="face", face_count=1, extra=""):
    h = "ply\nformat %s 1.0\ncomment seed\nelement vertex %d\n" % (fmt, count)
    h += "".join("property %s %s\n" % p for p in vertex_props)
    h += extra
    h += "element %s %d\nproperty list uchar int vertex_indices\nend_header\n" % (face_elem, face_count)
    return h.encode()

XYZ = [("float", "x"), ("float", "y"), ("float", "z")]
PTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]

def binary(order, elem="face", lists=None, props=XYZ, values=None):
    lists = lists or [[0, 1, 2, 3]]
    fmt = "binary_little_endian" if order == "<" else "binary_big_endian"
    body = b"".join(struct.pack(order + "3f", *p) for p in (values or PTS))
    for l in lists:
        body += struct.pack(order + "B", len(l)) + b"".join(struct.pack(order + "i", i) for i in l)
    return ply_header(fmt, props, len(values or PTS), elem, len(lists)) + body

ASCII_SQUARE = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
PLY = {
    "ascii-quad": ply_header("ascii", XYZ, 4) + (ASCII_SQUARE + "4 0 1 2 3\n").encode(),
    "ascii-normals-uv": ply_header("ascii", XYZ + [("float", "nx"), ("float", "ny"), ("float", "nz"), ("float", "u"), ("float", "v")], 3)
        + b"0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n0 1 0 0 0 1 0 1\n3 0 1 2\n",
    "ascii-st": ply_header("ascii", XYZ + [("double", "s"), ("double", "t")], 3) + b"0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n",
    "ascii-skip": ply_header("ascii", XYZ + [("uchar", "red")], 3, extra="element edge 1\nproperty list uchar int pair\nproperty float w\n")
        + b"0 0 0 1\n1 0 0 2\n0 1 0 3\n2 0 1 0.5\n3 0 1 2\n",
    "ascii-tristrips": ply_header("ascii", XYZ, 4, "tristrips") + (ASCII_SQUARE + "5 0 1 3 2 -1\n").encode(),
    "ascii-index-range": ply_header("ascii", XYZ, 4) + (ASCII_SQUARE + "3 0 1 7\n").encode(),
    "ascii-nan": ply_header("ascii", XYZ, 4) + ("0 0 0\n1 nan 0\n1 1 0\n0 1 0\n3 0 1 2\n").encode(),
    "ascii-truncated": ply_header("ascii", XYZ, 4) + ASCII_SQUARE.encode(),
    "ascii-trailing": ply_header("ascii", XYZ, 4) + (ASCII_SQUARE + "3 0 1 2\nextra\n").encode(),
    "le-quad": binary("<"),
    "be-quad": binary(">"),
    "le-tristrips": binary("<", "tristrips", [[0, 1, 3, 2, -1, 0, 2, 3]]),
    "be-tristrips": binary(">", "tristrips", [[0, 1, 3, 2]]),
    "le-two-faces": binary("<", lists=[[0, 1, 2], [0, 2, 3]]),
    "le-degenerate": binary("<", lists=[[0, 0, 1], [0, 1, 2]]),
    "le-index-range": binary("<", lists=[[0, 1, 9]]),
    "le-truncated": binary("<")[:-5],
    "le-trailing": binary("<") + b"xy",
    "le-claims-many": binary("<").replace(b"element face 1\n", b"element face 1000000000\n"),
    "le-double-short": ply_header("binary_little_endian", [("double", "x"), ("short", "y"), ("uchar", "z")], 3)
        + b"".join(struct.pack("<dhB", *p) for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]) + struct.pack("<B3i", 3, 0, 1, 2),
    "no-end-header": b"ply\nformat ascii 1.0\nelement vertex 3\n",
    "header-only": b"ply\nformat ascii 1.0\nend_header\n",
    "points-ascii": b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        b"property float radius\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
        b"0 0 0 0.5 255 0 0\n1 0 0 0.25 0 255 0\n0 1 0 1 255 0 0\n",
    "points-le": b"ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
        b"property float radius\nproperty float red\nproperty float green\nproperty float blue\nend_header\n"
        + b"".join(struct.pack("<7f", *p) for p in [(0, 0, 0, 0.5, 1, 0, 0), (1, 2, 3, 0.1, 0.2, 0.4, 0.6)]),
    "face-first": b"ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
}

for target, seeds in (("obj", OBJ), ("ply", PLY)):
    folder = os.path.join("tests", "fuzz", "corpus", target)
    os.makedirs(folder, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data.encode() if isinstance(data, str) else data)
