#!/usr/bin/env python3
"""Writes a lancer scene as an equivalent POV-Ray 3.7 scene, for bench/run.sh: the same camera,
lights, materials and geometry, so both renderers draw the same picture and their times can be
compared. (A tool of the benchmark, not part of lancer.)

    python3 bench/toml_to_pov.py scenes/seed.toml > seed.pov
    python3 bench/toml_to_pov.py scenes/torus.toml --torus-as analytic > torus_analytic.pov

Where lancer and POV-Ray differ (docs/scene-format.md, "Porting from POV-Ray"):
- lancer mixes reflection as (1 - r) * local + r * reflected; POV adds r * reflected, so every
  finish's ambient, diffuse and phong are lancer's times (1 - r);
- lancer's fov is vertical, POV's camera angle horizontal;
- lancer's max_depth counts bounces, POV's max_trace_level counts the camera ray too;
- lancer stops following reflections below a weight of 1/1024: adc_bailout 1/1024.
Both are left-handed with y up, so coordinates and rotations carry over unchanged.
Cylinders and cones become POV's own (the same parameters, `open` included).
Bezier patches become bicubic_patch (POV tessellates them: type 1, its usual settings);
tori become POV's exact `torus` turned to their axis and moved to their centre by a `matrix`;
parametric surfaces become POV's `parametric` (Lipschitz subdivision with max_gradient, accuracy
0.001 and precompute), or with --torus-as analytic, a torus becomes POV's exact `torus`.
Implicit surfaces become POV's exact `polynomial` (expanded here, solved with Sturm sequences,
clipped to the box) when they are polynomials, or with --implicit-as isosurface (always for
other functions), POV's `isosurface` with `--accuracy` and a max_gradient measured over the box
(1.1 x the largest |grad f| on a 48^3 grid), `open` like lancer's clipped surface.
"""
import argparse
import ast
import math
import os
import re
import struct
import sys
import tomllib


# The keys this converter translates, per table. Any other key changes lancer's picture in a way
# the POV-Ray twin would not show (refraction, textures, area lights, ...), so it is refused
# rather than dropped: a benchmark must compare the same picture. ("subdivision" only changes how
# lancer's GPU path organises the work; "name" only labels.)
TRANSLATED = {
    "top": {"render", "camera", "ambient", "light", "material", "object", "declare", "fog"},
    "fog": {"type", "distance", "color", "offset", "altitude", "up"},
    "render": {"width", "height", "samples", "max_depth", "background"},
    "camera": {"eye", "look_at", "up", "fov"},
    "ambient": {"color"},
    "light": {"position", "color", "name"},
    "material": {"color", "checker", "ambient", "diffuse", "specular", "shininess", "reflection"},
    "checker": {"colors", "size", "transform"},
    "sphere": {"center", "radius"},
    "plane": {"point", "normal"},
    "rectangle": {"corner", "edge_u", "edge_v"},
    "box": {"min", "max"},
    "cylinder": {"base_point", "cap_point", "radius", "open"},
    "cone": {"base_point", "base_radius", "cap_point", "cap_radius", "open"},
    "torus": {"center", "axis", "major_radius", "minor_radius"},
    "disc": {"center", "normal", "radius", "hole_radius"},
    "bezier": {"file", "control_points", "patches", "transform", "subdivision"},
    "parametric": {"x", "y", "z", "u", "v", "params", "transform"},
    "implicit": {"function", "box", "params", "transform"},
    "superellipsoid": {"e", "n"},
    "blob": {"threshold", "spheres", "cylinders"},
    "sor": {"points", "open"},
    "text": {"text", "font", "thickness", "offset"},
    "lathe": {"spline", "points"},
    "prism": {"sweep", "spline", "height1", "height2", "points", "open"},
    "mesh": {"file", "smooth", "transform"},
    "spheres": {"file", "radius", "transform"},
}
OBJECT_KEYS = {"type", "material", "name", "transform"}
# Groups and CSG: POV-Ray's union and its CSG words, with their operands in `objects`.
COMPOUND = {"group": "union", "intersection": "intersection", "difference": "difference", "merge": "merge"}


def check_keys(table, allowed, what):
    for key in table:
        if key not in allowed:
            sys.exit(f"toml_to_pov: {what}: '{key}' is not translated to POV-Ray; "
                     f"the twin would not be the same picture")


def vec(v):
    return "<%s>" % ", ".join("%.9g" % float(x) for x in v)


def rgb(v):
    return "rgb " + vec(v)


def camera(scene):
    r = scene.get("render", {})
    w, h = r.get("width", 640), r.get("height", 480)
    c = scene["camera"]
    fov = c.get("fov", 60.0)
    horizontal = 2 * math.degrees(math.atan(math.tan(math.radians(fov / 2)) * w / h))
    up = c.get("up", [0, 1, 0])
    return (f"camera {{ location {vec(c['eye'])} sky {vec(up)} look_at {vec(c['look_at'])}\n"
            f"         right x * image_width / image_height angle {horizontal:.9g} }}\n")


def finish(m):
    r = m.get("reflection", 0.0)
    k = 1.0 - r
    return (f"finish {{ ambient {m.get('ambient', 0.1) * k:.9g} diffuse {m.get('diffuse', 0.6) * k:.9g} "
            f"phong {m.get('specular', 0.0) * k:.9g} phong_size {m.get('shininess', 40.0):.9g} reflection {r:.9g} }}")


def pigment(m):
    if "checker" in m:
        c = m["checker"]
        own = transform(c.get("transform"))  # none: no second space, so the kept twins stay as written
        return (f"pigment {{ checker {rgb(c['colors'][0])}, {rgb(c['colors'][1])} "
                f"scale {c.get('size', 1.0):.9g} {own + ' ' if own else ''}}}")
    return f"pigment {{ {rgb(m.get('color', [1, 1, 1]))} }}"


def transform(t):
    if t is None:
        return ""
    steps = t if isinstance(t, list) else [t]
    out = []
    for s in steps:
        if "scale" in s:
            sc = s["scale"]
            out.append("scale " + (vec(sc) if isinstance(sc, list) else "%.9g" % sc))
        if "rotate" in s:
            out.append("rotate " + vec(s["rotate"]))
        if "translate" in s:
            out.append("translate " + vec(s["translate"]))
        if "matrix" in s:
            out.append("matrix <" + ", ".join("%.9g" % x for x in s["matrix"]) + ">")
    return " ".join(out)


def read_bpt(path):
    """Patches of a BPT file as lists of 16 (x, y, z); weights are not supported by POV."""
    numbers = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].replace(",", " ")
            numbers.extend(float(x) for x in line.split())
    count = int(numbers[0])
    if len(numbers) != 1 + count * (2 + 16 * 3):
        sys.exit(f"toml_to_pov: {path}: not {count} patches of 16 points (x, y, z): "
                 "rational patches (a weight per point) are not translated to POV-Ray")
    pos, patches = 1, []
    for _ in range(count):
        pos += 2  # "3 3"
        pts = []
        for _ in range(16):
            pts.append(numbers[pos:pos + 3])
            pos += 3
        patches.append(pts)
    return patches


def bezier(o, base):
    if "file" in o:
        patches = read_bpt(os.path.join(base, o["file"]))
    elif "patches" in o:
        patches = o["patches"]
    else:
        patches = [o["control_points"]]
    parts = []
    for p in patches:
        pts = ",\n    ".join(vec(q) for q in p)
        # POV-Ray's usual teapot settings: a type 1 patch (subdivision tree kept) of 3 + 3 steps.
        parts.append(f"  bicubic_patch {{ type 1 flatness 0 u_steps 3 v_steps 3\n    {pts} }}")
    return "union {\n" + "\n".join(parts) + "\n"


# lancer's expression functions in POV-Ray's function syntax (POV's log is base 10, ln natural).
POV_FUNCTIONS = {"log": "ln", "log10": "log", "sqr": "pow(%s,2)", "cbrt": "pow(%s,1/3)", "exp2": "pow(2,%s)",
                 "log2": "(ln(%s)/ln(2))", "hypot": "sqrt(pow(%s,2)+pow(%s,2))"}


def pov_expression(text, params):
    for name, value in params.items():
        text = re.sub(r"\b%s\b" % re.escape(name), "(%.17g)" % value, text)
    for name, pov in POV_FUNCTIONS.items():
        if "%s" not in pov:
            text = re.sub(r"\b%s\(" % name, pov + "(", text)
    return text


def py_function(text, params):
    env = {"pi": math.pi, "e": math.e, **{k: float(v) for k, v in params.items()}}
    py = text.replace("^", "**")
    funcs = {n: getattr(math, n) for n in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh",
                                           "tanh", "exp", "log", "sqrt", "log10", "log2", "hypot")}
    funcs.update({"abs": abs, "min": min, "max": max, "pow": math.pow, "sqr": lambda x: x * x,
                  "cbrt": lambda x: math.copysign(abs(x) ** (1 / 3), x), "exp2": lambda x: 2 ** x})
    code = compile(py, "<expr>", "eval")
    return lambda u, v: eval(code, {"__builtins__": {}}, {**funcs, **env, "u": u, "v": v})


def bound(b, params):
    return float(b) if not isinstance(b, str) else py_function(b, params)(0.0, 0.0)


def parametric(o):
    params = o.get("params", {})
    u0, u1 = (bound(b, params) for b in o["u"])
    v0, v1 = (bound(b, params) for b in o["v"])
    fx, fy, fz = (py_function(o[a], params) for a in "xyz")
    # contained_by box and max_gradient from a dense sample of the surface and its differences.
    n = 200
    lo, hi, grad = [1e30] * 3, [-1e30] * 3, 0.0
    du, dv = (u1 - u0) / n, (v1 - v0) / n
    for i in range(n + 1):
        for j in range(n + 1):
            u, v = u0 + i * du, v0 + j * dv
            p = (fx(u, v), fy(u, v), fz(u, v))
            for k in range(3):
                lo[k], hi[k] = min(lo[k], p[k]), max(hi[k], p[k])
            if i < n and j < n:
                pu = (fx(u + du, v), fy(u + du, v), fz(u + du, v))
                pv = (fx(u, v + dv), fy(u, v + dv), fz(u, v + dv))
                for k in range(3):
                    grad = max(grad, abs(pu[k] - p[k]) / du, abs(pv[k] - p[k]) / dv)
    pad = [0.01 * (h - l) + 1e-3 for l, h in zip(lo, hi)]
    box = f"box {{ {vec([l - q for l, q in zip(lo, pad)])}, {vec([h + q for h, q in zip(hi, pad)])} }}"
    funcs = "\n".join(f"  function {{ {pov_expression(o[a], params)} }}" for a in "xyz")
    return (f"parametric {{\n{funcs}\n  <{u0:.17g}, {v0:.17g}>, <{u1:.17g}, {v1:.17g}>\n"
            f"  contained_by {{ {box} }}\n  max_gradient {1.1 * grad:.6g} accuracy 0.001 precompute 12 x, y, z\n")


def analytic_torus(o):
    """POV's exact torus for the lancer torus (R + r cos v) cos u, r sin v, (R + r cos v) sin u."""
    p = o.get("params", {})
    return f"torus {{ {p['R']:.9g}, {p['r']:.9g}\n"


def torus(o):
    """POV's exact torus (about +y at the origin) carried to lancer's axis and centre by a matrix
    whose rows are the images of x, y, z: lancer's texture axes for the axis (scene/
    parse_material_maps.cpp's set_plane_texture_axes), the axis, and u x axis. A spindle torus
    (minor > major) is the whole quartic in lancer, POV's `difference` spindle mode."""
    a = o.get("axis", [0, 1, 0])
    length = math.sqrt(sum(x * x for x in a))
    n = [x / length for x in a]
    up = [-n[1] * n[0], 1 - n[1] * n[1], -n[1] * n[2]]
    if math.sqrt(sum(x * x for x in up)) <= 1e-6:
        up = [-n[2] * n[0], -n[2] * n[1], 1 - n[2] * n[2]]
    lv = math.sqrt(sum(x * x for x in up))
    v = [x / lv for x in up]
    u = [n[1] * v[2] - n[2] * v[1], n[2] * v[0] - n[0] * v[2], n[0] * v[1] - n[1] * v[0]]
    w = [u[1] * n[2] - u[2] * n[1], u[2] * n[0] - u[0] * n[2], u[0] * n[1] - u[1] * n[0]]
    c = o.get("center", [0, 0, 0])
    spindle = " difference" if o["minor_radius"] > o["major_radius"] else ""
    rows = ", ".join("%.9g" % x for x in u + n + w + c)
    return f"torus {{ {o['major_radius']:.9g}, {o['minor_radius']:.9g}{spindle} matrix <{rows}>\n"


# Implicit surfaces: lancer's expression language read with Python's own parser (x^y is x**y,
# with the same precedence: -x^2 = -(x^2), right-associative).
FUNCTIONS_1 = {"sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
               "exp", "exp2", "log", "log2", "log10", "sqrt", "cbrt", "sqr", "abs"}
FUNCTIONS_2 = {"atan2", "pow", "min", "max", "hypot"}


def parse_function(text):
    return ast.parse(text.replace("^", "**"), mode="eval").body


def constant_value(node, params):
    """The value of a subtree without variables, or None."""
    env = {"pi": math.pi, "e": math.e, **{k: float(v) for k, v in params.items()}}
    funcs = {"sqr": lambda a: a * a, "cbrt": lambda a: math.copysign(abs(a) ** (1 / 3), a),
             "exp2": lambda a: 2.0 ** a, "abs": abs, "min": min, "max": max, "pow": math.pow}
    for n in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh",
              "atanh", "exp", "log", "log2", "log10", "sqrt", "hypot"):
        funcs[n] = getattr(math, n)
    try:
        return float(eval(compile(ast.Expression(node), "<f>", "eval"), {"__builtins__": {}}, {**funcs, **env}))
    except (NameError, TypeError):
        return None


def expand(node, params):
    """f as {(i, j, k): coefficient} when it is a polynomial in x, y, z, else None."""
    c = constant_value(node, params)
    if c is not None:
        return {(0, 0, 0): c} if c != 0 else {}
    if isinstance(node, ast.Name):
        return {{"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}[node.id]: 1.0}
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        a = expand(node.operand, params)
        return None if a is None else {k: -v for k, v in a.items()}
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.UAdd):
        return expand(node.operand, params)
    if isinstance(node, ast.Call) and node.func.id == "sqr":
        a = expand(node.args[0], params)
        return None if a is None else multiply(a, a)
    if isinstance(node, ast.Call) and node.func.id == "pow":
        node = ast.BinOp(node.args[0], ast.Pow(), node.args[1])
    if not isinstance(node, ast.BinOp):
        return None
    a = expand(node.left, params)
    if a is None:
        return None
    if isinstance(node.op, ast.Pow):
        n = constant_value(node.right, params)
        if n is None or n != int(n) or n < 0:
            return None
        r = {(0, 0, 0): 1.0}
        for _ in range(int(n)):
            r = multiply(r, a)
        return r
    if isinstance(node.op, ast.Div):
        d = constant_value(node.right, params)
        return None if not d else {k: v / d for k, v in a.items()}
    b = expand(node.right, params)
    if b is None:
        return None
    if isinstance(node.op, ast.Mult):
        return multiply(a, b)
    sign = 1.0 if isinstance(node.op, ast.Add) else -1.0
    r = dict(a)
    for k, v in b.items():
        r[k] = r.get(k, 0.0) + sign * v
    return {k: v for k, v in r.items() if v != 0.0}


def multiply(a, b):
    r = {}
    for (i, j, k), u in a.items():
        for (p, q, s), v in b.items():
            key = (i + p, j + q, k + s)
            r[key] = r.get(key, 0.0) + u * v
    return {k: v for k, v in r.items() if v != 0.0}


def pov_function(node, params):
    """f in POV-Ray's function syntax (no ^: pow; ln is the natural logarithm)."""
    c = constant_value(node, params)
    if c is not None:
        return "(%.17g)" % c
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.UnaryOp):
        return ("(-%s)" if isinstance(node.op, ast.USub) else "%s") % pov_function(node.operand, params)
    if isinstance(node, ast.BinOp):
        a, b = pov_function(node.left, params), pov_function(node.right, params)
        if isinstance(node.op, ast.Pow):
            return "pow(%s, %s)" % (a, b)
        op = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/"}[type(node.op)]
        return "(%s %s %s)" % (a, op, b)
    name = node.func.id
    args = [pov_function(x, params) for x in node.args]
    pov = {"log": "ln(%s)", "log10": "log(%s)", "log2": "(ln(%s)/ln(2))", "exp2": "pow(2, %s)", "sqr": "pow(%s, 2)",
           "cbrt": "(select(%s, -1, 1)*pow(abs(%s), 1/3))", "hypot": "sqrt(pow(%s, 2) + pow(%s, 2))"}
    if name == "cbrt":
        return pov["cbrt"] % (args[0], args[0])
    if name in pov:
        return pov[name] % tuple(args)
    return "%s(%s)" % (name, ", ".join(args))


def max_gradient(node, params, lo, hi, n=48):
    """1.1 x the largest |grad f| over an n^3 grid of the box (central differences)."""
    env = {"pi": math.pi, "e": math.e, **{k: float(v) for k, v in params.items()}}
    code = compile(ast.Expression(node), "<f>", "eval")
    funcs = {"sqr": lambda a: a * a, "cbrt": lambda a: math.copysign(abs(a) ** (1 / 3), a),
             "exp2": lambda a: 2.0 ** a, "abs": abs, "min": min, "max": max, "pow": math.pow}
    for name in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh",
                 "atanh", "exp", "log", "log2", "log10", "sqrt", "hypot"):
        funcs[name] = getattr(math, name)
    scope = {**funcs, **env}

    def f(x, y, z):
        scope["x"], scope["y"], scope["z"] = x, y, z
        return eval(code, {"__builtins__": {}}, scope)
    h = [1e-5 * (b - a) for a, b in zip(lo, hi)]
    best = 0.0
    for i in range(n + 1):
        x = lo[0] + (hi[0] - lo[0]) * i / n
        for j in range(n + 1):
            y = lo[1] + (hi[1] - lo[1]) * j / n
            for k in range(n + 1):
                z = lo[2] + (hi[2] - lo[2]) * k / n
                try:
                    g = ((f(x + h[0], y, z) - f(x - h[0], y, z)) / (2 * h[0]),
                         (f(x, y + h[1], z) - f(x, y - h[1], z)) / (2 * h[1]),
                         (f(x, y, z + h[2]) - f(x, y, z - h[2])) / (2 * h[2]))
                except (ValueError, ZeroDivisionError, OverflowError):
                    continue
                best = max(best, math.sqrt(sum(c * c for c in g)))
    return 1.1 * best


POLY_SCALE = 10.0


def implicit(o, implicit_as, accuracy):
    params = o.get("params", {})
    node = parse_function(o["function"])
    lo, hi = o["box"]["min"], o["box"]["max"]
    box = f"box {{ {vec(lo)}, {vec(hi)} }}"
    poly = expand(node, params) if implicit_as == "poly" else None
    if poly is not None:
        # POV-Ray's polynomial solver works with absolute tolerances that suit objects about ten
        # units across: at lancer's unit-sized boxes it loses roots near double points (the
        # Barth sextic's cones showed lit speckles in their shadows, 44.5 dB at one ray per
        # pixel), and a hundred times larger its small coefficients fall below its zero
        # threshold. So the twin is the same surface POLY_SCALE times larger, scaled back down.
        degree = max(sum(k) for k in poly)
        scaled = {k: v * POLY_SCALE ** -sum(k) for k, v in poly.items()}
        terms = ",\n  ".join("xyz(%d, %d, %d): %.17g" % (k + (v,)) for k, v in sorted(scaled.items(), reverse=True))
        big = f"box {{ {vec([POLY_SCALE * x for x in lo])}, {vec([POLY_SCALE * x for x in hi])} }}"
        return (f"polynomial {{ {degree},\n  {terms}\n  sturm\n"
                f"  clipped_by {{ {big} }}\n  bounded_by {{ clipped_by }}\n  scale {1 / POLY_SCALE:g}\n")
    return (f"isosurface {{\n  function {{ {pov_function(node, params)} }}\n  contained_by {{ {box} }}\n"
            f"  accuracy {accuracy:g} max_gradient {max_gradient(node, params, lo, hi):.6g} open\n")


def read_obj(path):
    """An OBJ's positions, vertex normals (one per position, or none) and triangles (polygons fanned
    from their first corner, as lancer's reader does). Normals are taken per position: the test
    models give each position one."""
    positions, normals, faces, corner_normals = [], [], [], {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                positions.append([float(x) for x in words[1:4]])
            elif words[0] == "vn":
                normals.append([float(x) for x in words[1:4]])
            elif words[0] == "f":
                corners = []
                for w in words[1:]:
                    parts = w.split("/")
                    i = int(parts[0])
                    i = i - 1 if i > 0 else len(positions) + i
                    if len(parts) > 2 and parts[2]:
                        n = int(parts[2])
                        corner_normals[i] = n - 1 if n > 0 else len(normals) + n
                    corners.append(i)
                faces += [[corners[0], corners[k - 1], corners[k]] for k in range(2, len(corners))]
    vertex_normals = [normals[corner_normals[i]] for i in range(len(positions))] if corner_normals else []
    return positions, vertex_normals, faces


def angle_weighted_normals(positions, faces):
    """lancer's vertex normals for a mesh without them (host/mesh/mesh_geometry.cpp)."""
    def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
    def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    def length(a): return math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
    sums = [[0.0, 0.0, 0.0] for _ in positions]
    for f in faces:
        a, b, c = (positions[k] for k in f)
        n = cross(sub(b, a), sub(c, a))
        ln = length(n)
        if ln == 0.0:
            continue
        for k, (p, q, r) in zip(f, ((a, b, c), (b, c, a), (c, a, b))):
            u, v = sub(q, p), sub(r, p)
            lu, lv = length(u), length(v)
            if lu == 0.0 or lv == 0.0:
                continue
            angle = math.acos(max(-1.0, min(1.0, sum(x * y for x, y in zip(u, v)) / (lu * lv))))
            sums[k] = [s + angle * x / ln for s, x in zip(sums[k], n)]
    return [[x / length(s) for x in s] if length(s) > 0.0 else [0.0, 1.0, 0.0] for s in sums]


def find_font(name, base):
    """The font file lancer reads for `font`: beside the scene file, else the system's fonts."""
    if os.path.dirname(name) or os.path.isabs(name) or os.path.isfile(os.path.join(base, name)):
        return os.path.join(base, name)
    found = sorted(os.path.join(folder, name) for root in ("/usr/share/fonts", "/usr/local/share/fonts")
                   for folder, _, files in os.walk(root) if name in files)
    if not found:
        sys.exit(f"toml_to_pov: no font '{name}' beside the scene or in /usr/share/fonts")
    return found[0]


def text(o, base):
    """POV-Ray's own text object: the same font file, thickness and offset."""
    string = o["text"]
    if not string.isascii() or '"' in string or "\\" in string:
        sys.exit("toml_to_pov: only ASCII text without quotes or backslashes is translated")
    font = find_font(o.get("font", "DejaVuSans.ttf"), base)
    ox, oy = o.get("offset", [0, 0])
    return f'text {{ ttf "{font}" "{string}" {o["thickness"]:.9g}, <{ox:.9g}, {oy:.9g}, 0>\n'


def mesh(o, base):
    """POV-Ray's mesh2 with the file's triangles (and, shaded smooth, lancer's vertex normals)."""
    path = os.path.join(base, o["file"])
    if not path.lower().endswith(".obj"):
        sys.exit(f"toml_to_pov: mesh file {path}: only OBJ files are translated")
    positions, normals, faces = read_obj(path)
    smooth = o.get("smooth", bool(normals))
    text = f"mesh2 {{\n  vertex_vectors {{ {len(positions)},\n" + ",\n".join(vec(p) for p in positions) + "\n  }\n"
    if smooth:
        normals = normals or angle_weighted_normals(positions, faces)
        text += f"  normal_vectors {{ {len(normals)},\n" + ",\n".join(vec(n) for n in normals) + "\n  }\n"
    text += f"  face_indices {{ {len(faces)},\n" + ",\n".join(f"<{a}, {b}, {c}>" for a, b, c in faces) + "\n  }\n"
    return text


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def read_ply_points(path):
    """The vertex element's scalar properties of a PLY file, as one dict per point, and the type
    of each (ASCII or binary; lists are refused: a point set has none)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    fmt, elements = "ascii", []
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[:1] == ["format"]:
            fmt = words[1]
        elif words[:1] == ["element"]:
            elements.append((words[1], int(words[2]), []))
        elif words[:1] == ["property"]:
            if words[1] == "list":
                sys.exit(f"toml_to_pov: point set {path}: list properties are not translated")
            elements[-1][2].append((words[2], words[1]))
    points, body = [], data[end:]
    if fmt == "ascii":
        numbers = iter(body.split())
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        offset = 0
    for name, count, props in elements:
        for _ in range(count):
            if fmt == "ascii":
                values = [float(next(numbers)) for _ in props]
            else:
                layout = order + "".join(PLY_TYPES[t] for _, t in props)
                values = struct.unpack_from(layout, body, offset)
                offset += struct.calcsize(layout)
            if name == "vertex":
                points.append(dict(zip((n for n, _ in props), values)))
    types = {n: t for name, _, props in elements if name == "vertex" for n, t in props}
    return points, types


def srgb_decoded(code):
    """An 8-bit sRGB code as linear light, as lancer reads a point's colour code."""
    c = code / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def sphere_set(o, base, scene):
    """POV-Ray's union of the point set's spheres; where the points have colours, each sphere has
    the object's material in its own colour (8-bit codes are sRGB, floats linear, as lancer reads
    them)."""
    points, types = read_ply_points(os.path.join(base, o["file"]))
    mat = scene.get("material", {}).get(o.get("material", ""), {})

    def own_texture(p):
        if "red" not in p:
            return ""
        channels = [p[c] for c in ("red", "green", "blue")]
        if types["red"] in ("uchar", "uint8"):
            channels = [srgb_decoded(c) for c in channels]
        return f" texture {{ pigment {{ {rgb(channels)} }} {finish(mat)} }}"

    return "union {\n" + "".join(
        f"  sphere {{ {vec([p['x'], p['y'], p['z']])}, {p.get('radius', o.get('radius', 0)):.9g}{own_texture(p)} }}\n"
        for p in points)


def shape_body(o, base, torus_as, implicit_as, accuracy, scene):
    t = o["type"]
    if t == "sphere":
        return f"sphere {{ {vec(o['center'])}, {o['radius']:.9g}\n"
    if t == "plane":
        n = o["normal"]
        length = math.sqrt(sum(x * x for x in n))
        n = [x / length for x in n]
        d = sum(a * b for a, b in zip(n, o.get("point", [0, 0, 0])))
        return f"plane {{ {vec(n)}, {d:.9g}\n"
    if t == "rectangle":
        c, eu, ev = o["corner"], o["edge_u"], o["edge_v"]
        pts = [c, [a + b for a, b in zip(c, eu)], [a + b + d for a, b, d in zip(c, eu, ev)],
               [a + d for a, d in zip(c, ev)], c]
        return "polygon { 5, " + ", ".join(vec(p) for p in pts) + "\n"
    if t == "disc":
        return (f"disc {{ {vec(o['center'])}, {vec(o['normal'])}, {o['radius']:.9g}, "
                f"{o.get('hole_radius', 0.0):.9g}\n")
    if t == "box":
        return f"box {{ {vec(o['min'])}, {vec(o['max'])}\n"
    if t == "cylinder":
        opened = " open" if o.get("open", False) else ""
        return f"cylinder {{ {vec(o['base_point'])}, {vec(o['cap_point'])}, {o['radius']:.9g}{opened}\n"
    if t == "cone":
        opened = " open" if o.get("open", False) else ""
        return (f"cone {{ {vec(o['base_point'])}, {o['base_radius']:.9g}, "
                f"{vec(o['cap_point'])}, {o['cap_radius']:.9g}{opened}\n")
    if t == "torus":
        return torus(o)
    if t == "bezier":
        return bezier(o, base)
    if t == "parametric":
        return analytic_torus(o) if torus_as == "analytic" else parametric(o)
    if t == "implicit":
        return implicit(o, implicit_as, accuracy)
    if t == "mesh":
        return mesh(o, base)
    if t == "spheres":
        return sphere_set(o, base, scene)
    if t == "superellipsoid":  # the same parameters and meaning
        return f"superellipsoid {{ <{o['e']:.9g}, {o['n']:.9g}>\n"
    if t == "blob":  # the same components; POV-Ray's cylinders have the same round ends
        parts = [f"  sphere {{ {vec(c['center'])}, {c['radius']:.9g}, strength {c['strength']:.9g} }}\n"
                 for c in o.get("spheres", [])]
        parts += [f"  cylinder {{ {vec(c['base_point'])}, {vec(c['cap_point'])}, {c['radius']:.9g}, strength {c['strength']:.9g} }}\n"
                  for c in o.get("cylinders", [])]
        return f"blob {{ threshold {o['threshold']:.9g}\n" + "".join(parts)
    if t == "prism":  # the same points and splines: lancer reads them as POV-Ray does
        points = ", ".join(f"<{x:.9g}, {z:.9g}>" for x, z in o["points"])
        return (f"prism {{ {o.get('sweep', 'linear')}_sweep {o.get('spline', 'linear')}_spline "
                f"{o.get('height1', 0.0):.9g}, {o.get('height2', 1.0):.9g}, {len(o['points'])}, {points}"
                f"{' open' if o.get('open') else ''}\n")
    if t == "lathe":  # the same points and spline (POV-Ray's default is linear_spline too)
        points = ", ".join(f"<{r:.9g}, {y:.9g}>" for r, y in o["points"])
        spline = o.get("spline", "linear") + "_spline"
        return f"lathe {{ {spline} {len(o['points'])}, {points}\n"
    if t == "sor":  # the same points, POV-Ray's order (radius, height)
        points = ", ".join(f"<{r:.9g}, {y:.9g}>" for r, y in o["points"])
        return f"sor {{ {len(o['points'])}, {points}{' open' if o.get('open') else ''}\n"
    if t == "text":
        return text(o, base)
    sys.exit(f"toml_to_pov: object type {t} is not supported")


def object_text(o, scene, where, base, torus_as, implicit_as, accuracy, inherited=True):
    """One object as POV-Ray text. A member of a group or CSG object without a material of its own
    gets none here: POV-Ray gives it the enclosing object's texture, as lancer its material.
    An operand's `inverse` is POV-Ray's."""
    t = o["type"]
    extra = {"inverse"} if not inherited else set()
    if t == "object":  # a placement of a declared object
        check_keys(o, {"type", "of", "material", "name", "transform"} | extra, where)
        body = f"object {{ {declared_name(o['of'])}\n"
    elif t in COMPOUND:
        check_keys(o, {"type", "material", "name", "transform", "objects"} | extra, where)
        members = [object_text(m, scene, f"{where} member {k + 1}", base, torus_as, implicit_as, accuracy, False)
                   for k, m in enumerate(o["objects"])]
        body = f"{COMPOUND[t]} {{\n" + "".join(members)
    else:
        check_keys(o, TRANSLATED.get(t, set()) | OBJECT_KEYS | extra, where)
        body = shape_body(o, base, torus_as, implicit_as, accuracy, scene)
    texture = ""
    if "material" in o or inherited:
        mat = scene.get("material", {}).get(o.get("material", ""), {})
        texture = f"  {pigment(mat)}\n  {finish(mat)}\n"
    flip = "  inverse\n" if o.get("inverse", False) else ""
    return body + texture + flip + f"  {transform(o.get('transform'))}\n}}\n"


def declared_name(name):
    return "Declared_" + re.sub(r"[^A-Za-z0-9_]", "_", name)


def declarations(scene, base, torus_as, implicit_as="poly", accuracy=0.001):
    """[declare.NAME] tables as POV-Ray's #declare (textures only where the declared parts name theirs)."""
    return [f"#declare {declared_name(name)} =\n" +
            object_text(o, scene, f"declared object '{name}'", base, torus_as, implicit_as, accuracy, False)
            for name, o in scene.get("declare", {}).items()]


def objects(scene, base, torus_as, implicit_as="poly", accuracy=0.001):
    return [object_text(o, scene, f"object {i + 1} ('{o['type']}')", base, torus_as, implicit_as, accuracy)
            for i, o in enumerate(scene.get("object", []))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--torus-as", choices=["parametric", "analytic"], default="parametric")
    ap.add_argument("--implicit-as", choices=["poly", "isosurface"], default="poly",
                    help="polynomial implicit surfaces as POV's exact polynomial (default) or as an isosurface")
    ap.add_argument("--accuracy", type=float, default=0.001, help="the isosurface's accuracy (default 0.001)")
    args = ap.parse_args()
    with open(args.scene, "rb") as f:
        scene = tomllib.load(f)
    check_keys(scene, TRANSLATED["top"], "the scene")
    for table in ("render", "camera", "ambient", "fog"):
        check_keys(scene.get(table, {}), TRANSLATED[table], f"[{table}]")
    for i, light in enumerate(scene.get("light", [])):
        plain = {k: v for k, v in light.items() if not (k == "type" and v == "point")}
        check_keys(plain, TRANSLATED["light"], f"light {i + 1}")
    for name, m in scene.get("material", {}).items():
        check_keys(m, TRANSLATED["material"], f"material '{name}'")
        check_keys(m.get("checker", {}), TRANSLATED["checker"], f"material '{name}' checker")
    r = scene.get("render", {})
    amb = scene.get("ambient", {}).get("color", [1, 1, 1])
    print(f"// Generated from {args.scene} by bench/toml_to_pov.py. Do not edit.")
    print("#version 3.7;")
    print(f"global_settings {{ assumed_gamma 1.0 ambient_light {rgb(amb)} "
          f"max_trace_level {r.get('max_depth', 5) + 1} adc_bailout 1/1024 }}")
    print(camera(scene))
    print(f"background {{ {rgb(r.get('background', [0, 0, 0]))} }}")
    if "fog" in scene:  # POV-Ray's fog_type 1 (constant) or 2 (ground), the same parameters
        fog = scene["fog"]
        ground = fog.get("type", "constant") == "ground"
        extra = (f" fog_type 2 fog_offset {fog.get('offset', 0.0):.9g} fog_alt {fog.get('altitude', 1.0):.9g}"
                 f" up {vec(fog.get('up', [0, 1, 0]))}") if ground else ""
        print(f"fog {{ distance {fog['distance']:.9g} {rgb(fog.get('color', [0.5, 0.5, 0.5]))}{extra} }}")
    for light in scene.get("light", []):
        print(f"light_source {{ {vec(light['position'])} color {rgb(light.get('color', [1, 1, 1]))} }}")
    print()
    base = os.path.dirname(args.scene)
    print("\n".join(declarations(scene, base, args.torus_as, args.implicit_as, args.accuracy) +
                    objects(scene, base, args.torus_as, args.implicit_as, args.accuracy)))


if __name__ == "__main__":
    main()
