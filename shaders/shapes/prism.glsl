// Ray/prism (POV-Ray's prism, linear and conic sweeps), exactly, in float, in its own coordinates
// (it is always placed: placement.glsl carries rays there). Twin of host/cpu/shapes/prism.cpp
// (which isolates the roots by Bernstein subdivision in double).
// p.p0 = (bottom y0, top y1 (scene/prism.hpp's prism_walk_heights), its caps: 1 the bottom's + 2
// the top's, its size), p.p1 = the outline's box (x, z low, x, z high), p.p2.x = 1 for a conic
// sweep (the outline at y = 1 scaled by y about the apex at the origin), p.data its MeshInfo: a tree (MESH_NODES) over its segments (PRISM_CURVES, in
// leaf order; each a 2-D Bezier of degree 1 to 3: xs, zs its control points' coordinates).
//
// The ray o + t d sees the outline plane along the line q + s e, e = (d.x, d.z), s = t - t_q. A
// segment crosses it where f(u) = n . (B(u) - q) changes side (n = (-e.y, e.x), 0 counted as
// positive): f's Bernstein coefficients are n . (P_i - q), its sides sampled at the segment's
// ends (the control points' own values: a shared vertex gives both segments the same number) and
// at f's critical points (at most two), so that f is monotone between samples and a change of
// side has one root there, found by safeguarded Newton (bisection where Newton leaves the
// bracket). One walk of the half-line from the ray's entry into the slab through the tree counts
// the crossings beyond it (the entry cap is hit where that count is odd), beyond the slab's exit
// (the exit cap, where odd), and keeps the nearest (the first wall, where before the exit). A ray
// along y sees a point: its parity from the half-line along +x, and no walls. A conic sweep's line
// is the ray's central projection from the apex onto y = 1 (the plane through the apex and the
// ray, cut with y = 1), its s increasing with t inside the slab (which does not hold the apex);
// a wall's t is where the ray meets the line from the apex through the crossing (B, 1).
//
// uv: x the hit segment's index in PRISM_CURVES (-1 the bottom cap, -2 the top), y the segment's
// u where the ray enters there, -1 - u where it leaves (the normal's side).

struct PrismWalk {
    uint total;    // crossings beyond q
    uint far;      // of them, beyond s_far
    float s_near;  // the nearest
    uint segment;
    float u;
};

// f at u for Bernstein coefficients c of degree k (de Casteljau).
float prism_f(vec4 c, int k, float u) {
    float v = 1.0 - u;
    if (k == 1) return v * c.x + u * c.y;
    if (k == 2) return v * (v * c.x + u * c.y) + u * (v * c.y + u * c.z);
    vec3 a = v * c.xyz + u * c.yzw;
    vec2 b = v * a.xy + u * a.yz;
    return v * b.x + u * b.y;
}

// f's derivative at u.
float prism_df(vec4 c, int k, float u) {
    float v = 1.0 - u;
    if (k == 1) return c.y - c.x;
    if (k == 2) return 2.0 * (v * (c.y - c.x) + u * (c.z - c.y));
    vec3 d = c.yzw - c.xyz;
    return 3.0 * (v * (v * d.x + u * d.y) + u * (v * d.y + u * d.z));
}

// The one root of f in [a, b] where f is monotone and fa, fb on opposite sides.
float prism_root(vec4 c, int k, float a, float b, float fa, float fb) {
    if (k == 1) return clamp(fa / (fa - fb), a, b);
    float u = fa == fb ? 0.5 * (a + b) : clamp(a + (b - a) * fa / (fa - fb), a, b);
    bool a_positive = fa >= 0.0;
    for (int i = 0; i < 24; ++i) {
        float f = prism_f(c, k, u);
        if (f == 0.0) return u;
        if ((f >= 0.0) == a_positive) a = u; else b = u;
        float df = prism_df(c, k, u);
        float next = df != 0.0 ? u - f / df : 0.5 * (a + b);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (abs(next - u) <= 1e-7 * max(abs(u), 1e-3) || b - a <= 1e-7) return next;
        u = next;
    }
    return u;
}

// The segment's point and derivative at u.
vec2 prism_point(PrismCurve g, int k, float u) {
    float v = 1.0 - u;
    if (k == 1) return vec2(v * g.xs.x + u * g.xs.y, v * g.zs.x + u * g.zs.y);
    return vec2(prism_f(g.xs, k, u), prism_f(g.zs, k, u));
}
vec2 prism_tangent(PrismCurve g, int k, float u) {
    vec2 t = vec2(prism_df(g.xs, k, u), prism_df(g.zs, k, u));
    if (t == vec2(0.0)) t = vec2(g.xs[k] - g.xs.x, g.zs[k] - g.zs.x);
    return t;
}

// The crossings of segment i with the line q + s e (normal n) beyond s = 0, into w.
void prism_curve_crossings(uint i, vec2 q, vec2 e, vec2 n, float s_far, inout PrismWalk w) {
    PrismCurve g = prism_curve_at(i);
    int k = int(g.info.x);
    precise vec4 c = n.x * (g.xs - q.x) + n.y * (g.zs - q.y);
    float last = c[k];
    // Quick rejection: no change of side (the unused control points repeat the last).
    if (k == 1 ? (c.x >= 0.0) == (c.y >= 0.0) : (all(greaterThan(c, vec4(0.0))) || all(lessThan(c, vec4(0.0))))) return;
    // The samples: 0, f's critical points in (0, 1) in order, 1.
    float us[4];
    int m = 0;
    us[m++] = 0.0;
    if (k == 2) {
        float den = c.x - 2.0 * c.y + c.z;
        float u = den != 0.0 ? (c.x - c.y) / den : -1.0;
        if (u > 0.0 && u < 1.0) us[m++] = u;
    } else if (k == 3) {
        // f' / 3 = d0 (1-u)^2 + 2 d1 u (1-u) + d2 u^2 = A u^2 + B u + C.
        vec3 d = c.yzw - c.xyz;
        float A = d.x - 2.0 * d.y + d.z, B = 2.0 * (d.y - d.x), C = d.x;
        float r0 = -1.0, r1 = -1.0;
        if (A != 0.0) {
            float disc = B * B - 4.0 * A * C;
            if (disc > 0.0) {
                float h = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
                r0 = h / A;
                r1 = h != 0.0 ? C / h : r0;
            }
        } else if (B != 0.0) {
            r0 = -C / B;
        }
        float lo = min(r0, r1), hi = max(r0, r1);
        if (lo > 0.0 && lo < 1.0) us[m++] = lo;
        if (hi > 0.0 && hi < 1.0 && hi != lo) us[m++] = hi;
    }
    us[m++] = 1.0;
    float fa = c.x;
    for (int j = 1; j < m; ++j) {
        float fb = j == m - 1 ? last : prism_f(c, k, us[j]);
        if ((fa >= 0.0) != (fb >= 0.0)) {
            float u = prism_root(c, k, us[j - 1], us[j], fa, fb);
            vec2 r = prism_point(g, k, u) - q;
            float s = dot(e, r) / dot(e, e);
            if (s > 0.0) {
                ++w.total;
                if (s > s_far) ++w.far;
                if (s < w.s_near) {
                    w.s_near = s;
                    w.segment = i;
                    w.u = u;
                }
            }
        }
        fa = fb;
    }
}

// Every crossing of the outline with the half-line q + s e, s > 0, through the tree (all the
// leaves whose boxes it passes: the outline lies in y = 0 of the tree's boxes).
PrismWalk prism_walk(Primitive p, vec2 q, vec2 e, float s_far) {
    PrismWalk w;
    w.total = 0u;
    w.far = 0u;
    w.s_near = INFINITY;
    w.segment = 0u;
    w.u = 0.0;
    MeshInfo info = mesh_at(p.data);
    vec2 n = vec2(-e.y, e.x);
    vec3 origin = vec3(q.x, 0.0, q.y);
    vec3 inv_dir = safe_inverse(vec3(e.x, 0.0, e.y));
    uint stack[ELEMENT_STACK_SIZE];
    int sp = 0;
    stack[sp++] = info.first_node;
    while (sp > 0) {
        MeshNode node = mesh_node_at(stack[--sp]);
        if (box_entry(node.lo.xyz, node.hi.xyz, origin, inv_dir, INFINITY) == INFINITY) continue;
        if (node.count > 0u) {
            for (uint i = node.first; i < node.first + node.count; ++i) prism_curve_crossings(i, q, e, n, s_far, w);
        } else if (sp + 2 <= ELEMENT_STACK_SIZE) {
            stack[sp++] = node.first + 1u;
            stack[sp++] = node.first;
        }
    }
    return w;
}

// Whether the outline holds the plane's point q (the parity along +x).
bool prism_holds(Primitive p, vec2 q) { return (prism_walk(p, q, vec2(1.0, 0.0), INFINITY).total & 1u) == 1u; }

// The outline plane's point of a point of the prism's space: (x, z), or for a conic sweep its
// central projection from the apex onto y = 1.
vec2 prism_plane_point(Primitive p, vec3 x) { return p.p2.x != 0.0 ? x.xz / x.y : x.xz; }

bool prism_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    float t_in = -INFINITY, t_out = INFINITY;
    if (ray.dir.y != 0.0) {
        float a = (p.p0.x - ray.origin.y) / ray.dir.y, b = (p.p0.y - ray.origin.y) / ray.dir.y;
        t_in = min(a, b);
        t_out = max(a, b);
    } else if (!(ray.origin.y > p.p0.x && ray.origin.y < p.p0.y)) {
        return false;
    }
    float start = max(t_in, t_min), end = min(t_out, t_max);
    if (!(start < end)) return false;
    bool up = ray.dir.y > 0.0;
    uint caps = uint(p.p0.z);
    bool entry_cap = (caps & (up ? 1u : 2u)) != 0u, exit_cap = (caps & (up ? 2u : 1u)) != 0u;
    float entry_id = up ? -1.0 : -2.0, exit_id = up ? -2.0 : -1.0;
    // The outline plane's line of the ray, from its point at `start`, and its s at t_out.
    // A conic sweep's: Q(tau) = (x0.xz + tau d.xz) / (x0.y + tau d.y) = q + s e with
    // e = d.xz x0.y - x0.xz d.y and s = tau / (x0.y (x0.y + tau d.y)), whose last factor at t_out
    // is the exit's height itself (the far end's own projection, near an apex, would cancel).
    // Near the apex q is far off (1 / y): the line is taken from the plane through the apex and the
    // ray instead (normal n3 = x0 x d: n3.x X + n3.z Z + n3.y = 0 at y = 1; e = (-n3.z, n3.x) is the
    // e above), walked from its point nearest the outline's box centre, or from q where q is nearer
    // than the box's reach (s then counted from there), and not at all where q is beyond the box.
    bool conic = p.p2.x != 0.0;
    vec3 x0 = ray.origin + start * ray.dir;
    if (start == t_in) x0.y = up ? p.p0.x : p.p0.y;  // on the entry cap exactly
    vec2 q = prism_plane_point(p, x0);
    vec2 e = ray.dir.xz;
    float s_out = t_out - start;
    bool beyond = false;
    bool point;
    if (conic) {
        vec3 n3 = cross(x0, ray.dir);
        e = vec2(-n3.z, n3.x);
        float ee = dot(e, e);
        point = !(ee > 1e-12 * dot(x0, x0) * dot(ray.dir, ray.dir)) || ee < 1e-30;
        if (!point) {
            vec2 centre = 0.5 * (p.p1.xy + p.p1.zw), normal = n3.xz;
            vec2 foot = centre - ((dot(normal, centre) + n3.y) / dot(normal, normal)) * normal;
            float sigma0 = dot(q - foot, e) / ee;
            // Where the ray leaves the slab, from that point's own projection (its height exact):
            // near the apex one of q and it is far off, but then only its side of the box counts.
            float sigma_out = sigma0 + s_out / (x0.y * x0.y);  // at a fixed height, s = tau / y^2
            if (ray.dir.y != 0.0) {
                vec3 x1 = ray.origin + t_out * ray.dir;
                x1.y = up ? p.p0.y : p.p0.x;
                sigma_out = dot(prism_plane_point(p, x1) - foot, e) / ee;
            }
            float reach = (0.5 * length(p.p1.zw - p.p1.xy) * 1.01 + 1e-30) / sqrt(ee);
            beyond = sigma0 > reach;
            float sigma_start = max(sigma0, -reach);
            s_out = sigma_out - sigma_start;
            q = foot + sigma_start * e;
        }
    } else {
        // A point (a ray along y): no walls, the parity there.
        point = dot(e, e) < 1e-30;
    }
    PrismWalk w;
    if (beyond) {
        w.total = 0u;
        w.far = 0u;
        w.s_near = INFINITY;
    } else {
        w = prism_walk(p, q, point ? vec2(1.0, 0.0) : e, point ? INFINITY : s_out);
    }
    if (point) {
        w.far = w.total;
        w.s_near = INFINITY;
    }
    if (entry_cap && t_in > t_min && (w.total & 1u) == 1u) {
        t_hit = t_in;
        uv = vec2(entry_id, 0.0);
        return true;
    }
    if (w.s_near < s_out) {
        float t = start + w.s_near;
        if (conic) {  // where the ray meets the line from the apex through (B, 1)
            PrismCurve g = prism_curve_at(w.segment);
            vec2 b = prism_point(g, int(g.info.x), w.u);
            vec3 along = vec3(b.x, 1.0, b.y);
            vec3 dw = cross(ray.dir, along);
            float den = dot(dw, dw);
            t = den > 0.0 ? start - dot(cross(x0, along), dw) / den : start;
        }
        if (t > t_min && t < end) {  // (a conic sweep's t, from the apex's line, may round to the start)
            t_hit = t;
            bool entering = ((w.total - 1u) & 1u) == 1u;
            uv = vec2(float(w.segment), entering ? w.u : -1.0 - w.u);
            return true;
        }
    }
    if (exit_cap && t_out < t_max && (w.far & 1u) == 1u) {
        t_hit = t_out;
        uv = vec2(exit_id, 0.0);
        return true;
    }
    return false;
}

// Whether a point is inside (CSG's walked leaves; its reader lets only a closed prism in).
bool prism_inside(Primitive p, vec3 point) {
    return point.y > p.p0.x && point.y < p.p0.y && prism_holds(p, prism_plane_point(p, point));
}

// The hit's error (Hit.error): a wall's point is the ray's at t from the root u, whose f is within
// a few roundings of the control points' and q's magnitudes (the outline's size and |o| + t), and
// Newton stops within 1e-7 of u (of the segment's extent, at most the outline's size); a cap's is
// the plane's. As the sor's: 64 roundings of max |o| + t + the prism's size. A conic sweep's
// crossing is found in the plane y = 1 (the line from the plane through the apex and the ray) and
// its t from two cross products with the line from the apex: 4 times that (its reintersection
// family's worst distance was 1.67 of the 64 roundings).
float prism_hit_error(Primitive p, Ray ray, float t) {
    return rounding_bound(p.p2.x != 0.0 ? 256.0 : 64.0, max_abs(ray.origin) + t + max(p.p0.w, max(abs(p.p0.x), abs(p.p0.y))));
}

// The outward normal: the caps' axis, or the segment's tangent turned in the plane, against the
// ray where it enters.
vec3 prism_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = prism_hit_error(p, ray, t);
    if (uv.x == -1.0) return vec3(0.0, -1.0, 0.0);
    if (uv.x == -2.0) return vec3(0.0, 1.0, 0.0);
    PrismCurve g = prism_curve_at(uint(uv.x));
    bool entering = uv.y >= -0.5;
    float u = entering ? uv.y : -1.0 - uv.y;
    vec2 tangent = prism_tangent(g, int(g.info.x), u);
    vec3 n = vec3(tangent.y, 0.0, -tangent.x);
    if (p.p2.x != 0.0) {  // a conic sweep: across its tangents (B', 0) and (B, 1)
        vec2 b = prism_point(g, int(g.info.x), u);
        n.y = tangent.x * b.y - tangent.y * b.x;
    }
    n = normalize(n);
    if ((dot(n, ray.dir) < 0.0) != entering) n = -n;
    return n;
}

// Texture (u, v): POV-Ray's default, planar: (x, z) in the prism's own coordinates.
vec2 prism_texture_uv(Primitive p, Hit hit, vec3 point) { return point.xz; }
