// Ray / implicit surface f(x, y, z) = 0 inside its box, in float: interval arithmetic along the
// ray isolates the nearest root, Newton's method finishes it. Twin of
// host/cpu/shapes/implicit.cpp (companion matrix or interval Newton, in double precision).
//
// f, its derivative along the ray, its gradient and its interval enclosure are generated from
// the expression (host/gpu/shaders/surface_codegen.cpp, shaders/interval.glsl), so no Lipschitz bound
// is needed: a piece of the ray on which f's enclosure excludes 0 holds no root, however steep
// f is. The ray is carried into the surface's coordinates (ImplicitInfo: world -> local; t is
// kept), clipped to the box and re-origined at its entry. Pieces of it are examined nearest
// first:
//   * f's enclosure over the piece excludes 0: no root;
//   * f' excludes 0 (f is monotone there): a root exactly when f changes sign between the ends,
//     found by Newton's method kept inside the piece by bisection;
//   * otherwise the piece is halved, down to IMPLICIT_EPS of the box's diagonal: a piece that
//     short whose enclosure still holds 0 is where the ray touches the surface (a double root)
//     or passes a singular point, to within rounding. It is a hit, as on the CPU reference,
//     if f is defined at its middle.
// The generated functions are called from one place each here (and once more in Newton's
// loop): lavapipe inlines every call into both call sites of trace_scene, so each extra call
// would cost compile time and registers.
#if LANCER_IMPLICIT_SURFACES

const int IMPLICIT_STACK = 24;        // pieces waiting: halving to IMPLICIT_EPS takes at most 20 levels
const int IMPLICIT_MAX_PIECES = 512;  // pieces examined per ray and surface; beyond, a miss
const float IMPLICIT_EPS = 1e-6;      // of the box's diagonal, along the ray: a piece this short is a point
const int IMPLICIT_NEWTON_STEPS = 24;
const int IMPLICIT_MEAN_VALUE_AFTER = 16;  // pieces examined before the mean-value form narrows enclosures

// The ray's origin and direction in the surface's coordinates.
void implicit_local_ray(ImplicitInfo info, Ray ray, out vec3 o, out vec3 d) {
    mat3 rows = mat3(info.row0.xyz, info.row1.xyz, info.row2.xyz);  // columns hold the map's rows
    o = ray.origin * rows + vec3(info.row0.w, info.row1.w, info.row2.w);
    d = ray.dir * rows;
}

// The root of f(o + s d) in [a, b], where f is monotone and fa = f(a), fb = f(b) differ in sign:
// Newton's method from the regula falsi point, each step kept 1% of the bracket inside it (a
// root at an end of the bracket, where rounding puts Newton's step just outside, then still
// shrinks the bracket a hundredfold per step), the bracket shrinking around the root at every
// step. `spread` is how far the root may be from the result: the last Newton step (quadratic
// convergence leaves far less), else the bracket.
float implicit_refine(uint surface, vec3 o, vec3 d, float a, float b, float fa, float fb, out float spread) {
    spread = 0.0;
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    const float tolerance = 1e-7 * (b - a);
    float x = a + (b - a) * clamp(fa / (fa - fb), 0.01, 0.99);
    for (int k = 0; k < IMPLICIT_NEWTON_STEPS; ++k) {
        float df;
        float fx = implicit_eval(surface, o + x * d, d, df);
        if (fx == 0.0) return x;
        if (isnan(fx)) break;
        if ((fx < 0.0) == (fa < 0.0)) {
            a = x;
            fa = fx;
        } else {
            b = x;
        }
        float step = fx / df;
        if (abs(step) <= tolerance || b - a <= tolerance) {
            spread = min(abs(step), b - a);
            return clamp(x - step, a, b);
        }
        float margin = 0.01 * (b - a);
        x = isnan(step) ? 0.5 * (a + b) : clamp(x - step, a + margin, b - margin);
    }
    spread = b - a;
    return x;
}

// The mean-value form's f(m), in double where the device has it (LANCER_FLOAT64): float's
// enclosure of f at a point of a degree-8 surface cannot tell f from about 1e-2, double's from
// about 1e-11. With float alone, rays that skim Chmutov's octic spent their budget of pieces
// halving stretches where |f| was below that, and missed the roots beyond (0.9% of the pixels
// of a 160 x 120 picture off the reference's); where they touched nothing they were hits.
#if LANCER_FLOAT64
vec2 implicit_at_middle(uint surface, vec3 base, vec3 d, float m) {
    return i_flt(implicit_at_a_point(surface, dvec3(base), dvec3(d), dvec2(double(m))));
}
#endif

// f at two points of the ray: one call site, so the generated code is inlined once here.
vec2 implicit_pair(uint surface, vec3 o, vec3 d, vec2 s) {
    vec2 values;
    for (int k = 0; k < 2; ++k) {
        float unused;
        values[k] = implicit_eval(surface, o + s[k] * d, d, unused);
    }
    return values;
}

// The hit's error here: where the root may be along the ray (Newton's last step or bracket, or
// half a point piece) and the hit point's rounding. The band around the surface that the
// enclosures cannot resolve is added once the hit is known (implicit_band).
bool implicit_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit, out float error) {
    uint surface = prim.data;
    vec3 o, d;
    implicit_local_ray(implicit_at(surface), ray, o, d);
    vec3 lo = prim.p0.xyz, hi = prim.p1.xyz;
    vec3 inv = safe_inverse(d);
    vec3 ta = (lo - o) * inv, tb = (hi - o) * inv;
    vec3 tn = min(ta, tb), tf = max(ta, tb);
    float t0 = max(max(tn.x, tn.y), max(tn.z, t_min));
    float t1 = min(min(tf.x, tf.y), min(tf.z, t_max));
    if (!(t0 <= t1)) return false;
    vec3 base = o + t0 * d;  // s = t - t0 from here
    float eps = IMPLICIT_EPS * length(hi - lo) / length(d);

    vec2 stack[IMPLICIT_STACK];
    int waiting = 0;
    vec2 piece = vec2(0.0, t1 - t0);
    for (int n = 0; n < IMPLICIT_MAX_PIECES; ++n) {
        // f's enclosure over the piece; after many pieces (a ray that skims the surface, where
        // the natural enclosure stays wide) narrowed by the mean-value form f(m) + f'(piece)
        // (piece - m), which costs a second enclosure, at the piece's middle.
        float m = 0.5 * (piece.x + piece.y);
        vec2 f = vec2(-I_INF, I_INF), df;
        for (int k = 0; k < (n < IMPLICIT_MEAN_VALUE_AFTER ? 1 : 2); ++k) {
            vec2 fk, dfk;
#if LANCER_FLOAT64
            if (k == 1) fk = implicit_at_middle(surface, base, d, m);
            else
#endif
            implicit_interval(surface, base, d, k == 0 ? piece : vec2(m), fk, dfk);
            if (k == 0) {
                df = dfk;
                if (fk.x > 0.0 || fk.y < 0.0 || isinf(df.x) || isinf(df.y)) k = 1;  // settled, or no use
            } else {
                fk = i_add(fk, i_mul(df, piece - m));
            }
            f = vec2(max(f.x, fk.x), min(f.y, fk.y));
        }
        bool may_hold_root = f.x <= 0.0 && f.y >= 0.0;
        bool monotone = df.x > 0.0 || df.y < 0.0;
        bool point = piece.y - piece.x <= eps;
        bool split = may_hold_root && !monotone && !point;
        if (may_hold_root && (monotone || point)) {
            // Monotone: a root exactly where f changes sign between the ends. A point: a touching
            // (or singular) hit, where f is defined.
            vec2 at = monotone ? piece : vec2(m);
            vec2 v = implicit_pair(surface, base, d, at);
            bool defined = !isnan(v.x) && !isnan(v.y);
            bool hit = false;
            float s = m;
            float spread = 0.5 * (piece.y - piece.x);
            if (monotone && defined) {
                if (v.x == 0.0 || v.y == 0.0 || (v.x < 0.0) != (v.y < 0.0)) {
                    s = implicit_refine(surface, base, d, piece.x, piece.y, v.x, v.y, spread);
                    hit = true;
                }
            } else if (point) {
                hit = defined;
            } else {
                split = true;  // monotone, but f undefined at an end
            }
            if (hit) {
                t_hit = t0 + s;
                vec3 p = base + s * d;
                vec4 box = implicit_at(surface).texture_box;
                uv_hit = (p.xy - box.xy) / (box.zw - box.xy);
                error = spread + hit_point_rounding(ray.origin, t_hit);
                return true;
            }
        }
        if (split && waiting < IMPLICIT_STACK) {
            stack[waiting++] = vec2(m, piece.y);
            piece = vec2(piece.x, m);
            continue;
        }
        if (waiting == 0) return false;
        piece = stack[--waiting];
    }
    return false;
}

// Whether a world point is inside: f < 0 (CSG's walked leaves, csg.glsl; the reader proved f > 0
// on the box's faces, so the surface closes that region).
bool implicit_inside(Primitive prim, vec3 p) {
    vec3 o, d;
    implicit_local_ray(implicit_at(prim.data), Ray(p, vec3(0.0)), o, d);
    float unused;
    return implicit_eval(prim.data, o, d, unused) < 0.0;
}

// The half-width of the band around the surface at world point p in which f's enclosures cannot
// tell on which side of it a point is, in world units: f's enclosure over the cube of the
// intersector's resolution around p (sides of IMPLICIT_EPS of the box's diagonal: a piece of a
// ray halved down to that length spans no more along any axis), over |grad f|. A ray's
// piece that starts further than this from the surface has an enclosure that excludes 0; a hit
// may lie anywhere in the band, and a ray leaving the surface must start outside it (pieces
// nearer would be a hit at t ~ 0: acne). The enclosure holds the rounding of evaluating f (the
// interval library's outward margins), so the band also covers where float's f cannot tell the
// sign, which moves Newton's roots too (without it, torus hits lay up to 7 times their other
// bounds off the surface); and the natural enclosures of high-degree surfaces (Barth's sextic)
// overestimate f's range over a piece several times, which makes it wider than that rounding.
// `gradient` is |grad f| at p in world space; where it vanishes (a singular point) the fixed
// rule of the CPU reference stands in.
//
// Where the device has double precision the band is proved instead (implicit_certified_band):
// float's enclosures of a degree-8 surface are about 1e-2 wide at a point, a band of 1e-3 of
// the box, and shadow rays that started that far off Chmutov's octic passed through its folds.
float implicit_band(Primitive prim, vec3 local, float gradient, vec3 p) {
    float h = IMPLICIT_EPS * length(prim.p1.xyz - prim.p0.xyz);
    vec2 f, df;
    implicit_interval(prim.data, local, vec3(1.0), vec2(-0.5 * h, 0.5 * h), f, df);  // x, y and z each within h / 2 of p's
    float band = 0.5 * (f.y - f.x) / gradient;
    return isinf(band) || isnan(band) ? 1e-4 * max(1.0, max_abs(p)) : band;
}

#if LANCER_FLOAT64
// A band around p proved in double: r such that f's enclosures at p - r n and p + r n (n the
// world normal) have opposite signs, so the surface crosses the normal's line within r of p,
// plus four of the search's shortest pieces along it, where the mean-value form (in double)
// cannot exclude a piece and a ray leaving the surface would see a root at t ~ 0. r starts at
// one shortest piece and grows fourfold; 0 where six tries prove nothing (then the float
// band stands).
float implicit_certified_band(Primitive prim, mat3 rows, vec3 local, vec3 normal) {
    vec3 along = normal * rows;  // the normal's direction in the surface's coordinates
    float piece = IMPLICIT_EPS * length(prim.p1.xyz - prim.p0.xyz) / length(along);
    if (!(piece > 0.0) || isinf(piece)) return 0.0;
    float r = piece;
    dvec2 below = dvec2(0.0lf);
    [[dont_unroll]] for (int k = 0; k < 12; ++k) {  // one call site: the generated code is inlined once
        bool above = k % 2 == 1;
        dvec2 v = implicit_at_a_point(prim.data, dvec3(local), dvec3(along), dvec2(double(above ? r : -r)));
        if (!above) {
            below = v;
            continue;
        }
        if ((below.y < 0.0lf && v.x > 0.0lf) || (below.x > 0.0lf && v.y < 0.0lf)) return r + 4.0 * piece;
        r *= 4.0;
    }
    return 0.0;
}
#endif

// The unit normal at world point p: the gradient, carried to world space by the transpose of
// the world -> local map. Where it vanishes (a singular point) the gradient a little away
// along the box's diagonal is taken, as on the CPU reference. Adds the band (implicit_band) to
// the hit's error bound.
vec3 implicit_hit_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    ImplicitInfo info = implicit_at(prim.data);
    mat3 rows = mat3(info.row0.xyz, info.row1.xyz, info.row2.xyz);
    vec3 local = p * rows + vec3(info.row0.w, info.row1.w, info.row2.w);
    vec3 step = (prim.p1.xyz - prim.p0.xyz) * 0.57735027;
    // Gradients scaled by a power of two before they are squared (unit_scale): f = 1e20 (...)
    // or 1e-30 (...) would otherwise overflow or underflow float; |grad f| is then the scaled
    // length over the scale.
    vec3 g = implicit_gradient(prim.data, local);
    float s = unit_scale(max_abs(g));
    float gradient = length(rows * (s * g)) / s;
    g = s * g;
    if (!(dot(g, g) > 0.0) || isinf(dot(g, g))) g = implicit_gradient(prim.data, local + 1e-5 * step);
    if (!(dot(g, g) > 0.0) || isinf(dot(g, g))) g = implicit_gradient(prim.data, local + 1e-3 * step);
    if (!(dot(g, g) > 0.0) || isinf(dot(g, g))) g = implicit_gradient(prim.data, local + 1e-2 * step);
    vec3 n = rows * g;
    n *= unit_scale(max_abs(n));
    float len = length(n);
    n = len > 0.0 && !isinf(len) ? n / len : vec3(0.0, 0.0, 1.0);
    float band = 0.0;
#if LANCER_FLOAT64
    band = implicit_certified_band(prim, rows, local, n);
#endif
    error += band > 0.0 ? band : implicit_band(prim, local, gradient, p);
    return n;
}

// Texture (u, v): the intersection's (an implicit surface has no parameters of its own).
vec2 implicit_texture_uv(Primitive prim, Hit hit, vec3 p) { return hit.uv; }

#else
// No implicit surface in the scene: the family's functions exist for the shape table's
// dispatch, which SCENE_HAS_IMPLICIT (false) leaves out.
bool implicit_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit, out float error) {
    return false;
}
vec3 implicit_hit_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) { return vec3(0.0, 0.0, 1.0); }
vec2 implicit_texture_uv(Primitive prim, Hit hit, vec3 p) { return hit.uv; }
bool implicit_inside(Primitive prim, vec3 p) { return false; }
#endif
