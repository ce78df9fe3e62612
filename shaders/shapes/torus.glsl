// Ray/torus (POV-Ray's torus), exactly: the nearest root of its quartic, in float. Twin of
// host/cpu/shapes/torus.cpp (which isolates the roots by Bernstein subdivision in double).
// p0 = (centre, major radius R), p1 = (unit axis, minor radius r), p2 = (texture u axis, 0).
//
// The ray is carried into the torus's frame (y along the axis, x along the u axis, z = u x axis)
// scaled by S = R + r, so that the surface lies in the unit ball (a = R / S, b = r / S):
//   f(p) = (|p|^2 + a^2 - b^2)^2 - 4 a^2 (x^2 + z^2) = h-(p) h+(p),
//   h-+(p) = (rho -+ a)^2 + (y - b)(y + b),   rho^2 = x^2 + z^2.
// h- = 0 is the tube (a spindle's outer "apple"), h+ = 0 its mirror through the axis (a
// spindle's inner "lemon"; positive everywhere for a ring torus). In these factored forms each
// term is small where its factor vanishes, so f's sign is right to a few roundings of the unit
// ball's scale however thin the tube; the expanded quartic loses it to cancellation.
// The ray is cut to the ball (from its point nearest the centre, so that nothing large enters
// the quartic, however far the ray comes from) and to the slab |y| <= b, and re-based at the
// segment's middle P: along p = P + s d, s in [-w, w], w <= 1, f is the monic quartic whose
// derivative f'/4 = s^3 + A s^2 + B s + C has at most 3 roots (the critical points), which the
// quadratic 3 s^2 + 2 A s + B splits into monotone pieces. Between consecutive critical points f
// is monotone: a root there is bracketed by a sign change of f (factored), and safeguarded
// Newton (bisection where Newton leaves the bracket) finds it to float's resolution. The nearest
// bracket with a sign change holds the nearest root. The closed-form (Ferrari) solution is not
// used: in float it loses roots near tangency, where the two roots of a pair merge. A ray
// passing within rounding of the tube's tangent may be called a hit or a miss either way.
const float TORUS_TOLERANCE = 6e-8;  // of s, in the unit ball: float's resolution there

// f's sign and value at p, from its factors.
float torus_f(vec3 p, float a, float b) {
    float rho = sqrt(p.x * p.x + p.z * p.z);
    float y2b2 = (p.y - b) * (p.y + b);
    return ((rho - a) * (rho - a) + y2b2) * ((rho + a) * (rho + a) + y2b2);
}

float torus_cubic(vec3 abc, float s) { return ((s + abc.x) * s + abc.y) * s + abc.z; }

// The root of the cubic s^3 + A s^2 + B s + C in [lo, hi], where it is monotone and its value
// at lo is g_lo, of the other sign than at hi: safeguarded Newton.
float torus_cubic_root(vec3 abc, float lo, float hi, float g_lo) {
    float x = 0.5 * (lo + hi);
    for (int i = 0; i < 40; ++i) {
        float g = torus_cubic(abc, x);
        if (g == 0.0) break;
        if ((g > 0.0) == (g_lo > 0.0)) lo = x; else hi = x;
        float dg = (3.0 * x + 2.0 * abc.x) * x + abc.y;
        float next = x - g / dg;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        bool done = abs(next - x) <= TORUS_TOLERANCE || hi - lo <= TORUS_TOLERANCE;
        x = next;
        if (done) break;
    }
    return x;
}

// The root of f along P + s d in [lo, hi], where f is monotone and f(lo) = f_lo has the other
// sign than f(hi): safeguarded Newton on the factored f, its derivative 4 (s^3 + A s^2 + B s + C).
float torus_root(vec3 P, vec3 d, float a, float b, vec3 abc, float lo, float hi, float f_lo) {
    float x = 0.5 * (lo + hi);
    for (int i = 0; i < 40; ++i) {
        float f = torus_f(P + x * d, a, b);
        if (f == 0.0) break;
        if ((f > 0.0) == (f_lo > 0.0)) lo = x; else hi = x;
        float next = x - f / (4.0 * torus_cubic(abc, x));
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        bool done = abs(next - x) <= TORUS_TOLERANCE || hi - lo <= TORUS_TOLERANCE;
        x = next;
        if (done) break;
    }
    return x;
}

bool torus_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    float S = p.p0.w + p.p1.w, inv = 1.0 / S;
    float a = p.p0.w * inv, b = p.p1.w * inv;
    vec3 ax = p.p1.xyz, u = p.p2.xyz, v = cross(u, ax);
    vec3 e = (ray.origin - p.p0.xyz) * inv;
    vec3 o = vec3(dot(e, u), dot(e, ax), dot(e, v));
    vec3 d = vec3(dot(ray.dir, u), dot(ray.dir, ax), dot(ray.dir, v));
    // The ball (widened by far more than the roundings of a + b = 1) from the point nearest
    // the centre, then the slab, then (t_min, t_max): s relative to tc. c is that point only to
    // the rounding of o + tc d, which is of |o|: off along the ray by more than the ball's margin
    // for a ray from afar, so the ball's entry and exit keep c.d (beta0): s^2 + 2 beta0 s + |c|^2 = 1.
    float tc = -dot(o, d);
    vec3 c = o + tc * d;
    float beta0 = dot(c, d);
    float reach2 = beta0 * beta0 + 1.00002 - dot(c, c);
    if (!(reach2 >= 0.0)) return false;
    float hi = sqrt(reach2) - beta0, lo = -sqrt(reach2) - beta0;
    float slab = b * 1.00001 + 1e-6;
    if (d.y != 0.0) {
        float y0 = (-slab - c.y) / d.y, y1 = (slab - c.y) / d.y;
        lo = max(lo, min(y0, y1));
        hi = min(hi, max(y0, y1));
    } else if (abs(c.y) > slab) {
        return false;
    }
    lo = max(lo, t_min * inv - tc);
    hi = min(hi, t_max * inv - tc);
    if (!(lo < hi)) return false;
    float mid = 0.5 * (lo + hi), w = 0.5 * (hi - lo);
    vec3 P = c + mid * d;
    // f'/4 along P + s d (d is unit to float's rounding, taken as exactly so here).
    float beta = dot(P, d);
    float G = dot(P, P) + (a - b) * (a + b);
    float a2 = a * a;
    float r1 = P.x * d.x + P.z * d.z, r2 = d.x * d.x + d.z * d.z;
    vec3 abc = vec3(3.0 * beta, 2.0 * beta * beta + G - 2.0 * a2 * r2, beta * G - 2.0 * a2 * r1);
    // The monotone pieces of the cubic: the roots of 3 s^2 + 2 A s + B (stable form), in order.
    float gx[4];
    int m = 0;
    gx[m++] = -w;
    float disc = abc.x * abc.x - 3.0 * abc.y;
    if (disc > 0.0) {
        float q = -(abc.x + (abc.x >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
        float x1 = q / 3.0, x2 = q != 0.0 ? abc.y / q : 0.0;
        float first = min(x1, x2), second = max(x1, x2);
        if (first > -w && first < w) gx[m++] = first;
        if (second > -w && second < w && second > first) gx[m++] = second;
    }
    gx[m++] = w;
    // f's breakpoints: the ends and the critical points between them.
    float bp[5];
    int n = 0;
    bp[n++] = -w;
    float g_lo = torus_cubic(abc, gx[0]);
    for (int i = 1; i < m; ++i) {
        float g_hi = torus_cubic(abc, gx[i]);
        if ((g_lo > 0.0) != (g_hi > 0.0)) bp[n++] = torus_cubic_root(abc, gx[i - 1], gx[i], g_lo);
        g_lo = g_hi;
    }
    bp[n++] = w;
    // The nearest piece where f changes sign.
    float f_lo = torus_f(P + bp[0] * d, a, b);
    for (int i = 1; i < n; ++i) {
        float f_hi = torus_f(P + bp[i] * d, a, b);
        if ((f_lo > 0.0) != (f_hi > 0.0)) {
            float s = torus_root(P, d, a, b, abc, bp[i - 1], bp[i], f_lo);
            float t = (tc + (mid + s)) * S;
            if (t > t_min && t < t_max) {
                t_hit = t;
                return true;
            }
        }
        f_lo = f_hi;
    }
    return false;
}

// The hit's error (Hit.error), in world units, from the scaled frame's (times S):
//   the frame: e = (o - centre) / S and its three dot products with the axes (whose own rounding
//   turns the frame by an ulp): about 6 roundings of |o| + |centre|; the point nearest the centre
//   c = o + tc d and P = c + mid d: 2 roundings of |e| + tc each (tc is the ray's own parameter
//   of c as computed, so its rounding only renames the point);
//   the root: Newton stops within TORUS_TOLERANCE (an ulp of the ball) of a sign change of the
//   factored f, whose rounding, divided by |grad h-+| = 2b at the tube, is a dozen roundings of
//   the ball's scale, not of 1 / b (the squares are of differences that vanish there: rho - a,
//   y -+ b), and p = P + s d adds 2 more; a = R / S and b = r / S are 2 roundings of S off;
//   t = (tc + mid + s) S: 3 roundings of t along the ray; and the hit point's (hit_point_rounding).
// About 24 roundings of |o| + |centre| + t + S in Euclidean norms; with max_abs for them (up to
// sqrt(3) less) and a factor 2 of margin: 64.
float torus_hit_error(Primitive p, Ray ray, float t) {
    return rounding_bound(64.0, max_abs(ray.origin) + max_abs(p.p0.xyz) + t + p.p0.w + p.p1.w);
}

// The hit in the scaled frame.
vec3 torus_local(Primitive p, vec3 point) {
    vec3 e = (point - p.p0.xyz) / (p.p0.w + p.p1.w);
    vec3 u = p.p2.xyz, ax = p.p1.xyz;
    return vec3(dot(e, u), dot(e, ax), dot(e, cross(u, ax)));
}

// Whether a point is inside the tube (f < 0: CSG's walked leaves, csg.glsl).
bool torus_inside(Primitive p, vec3 point) {
    float S = p.p0.w + p.p1.w;
    return torus_f(torus_local(p, point), p.p0.w / S, p.p1.w / S) < 0.0;
}

// The gradient of f = h- h+ (normalised): h+ grad h- + h- grad h+, each factor and gradient
// accurate near its own zero, all of the unit ball's scale (no overflow, nothing to rescale).
vec3 torus_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = torus_hit_error(p, ray, t);
    float S = p.p0.w + p.p1.w;
    float a = p.p0.w / S, b = p.p1.w / S;
    vec3 q = torus_local(p, point);
    float rho = sqrt(q.x * q.x + q.z * q.z);
    float y2b2 = (q.y - b) * (q.y + b);
    float minus = (rho - a) * (rho - a) + y2b2, plus = (rho + a) * (rho + a) + y2b2;
    vec2 radial = rho > 0.0 ? q.xz / rho : vec2(0.0);  // a spindle's cusp: no radial direction
    vec3 g_minus = vec3((rho - a) * radial.x, q.y, (rho - a) * radial.y);
    vec3 g_plus = vec3((rho + a) * radial.x, q.y, (rho + a) * radial.y);
    vec3 g = plus * g_minus + minus * g_plus;
    vec3 u = p.p2.xyz, ax = p.p1.xyz;
    vec3 n = g.x * u + g.y * ax + g.z * cross(u, ax);
    float len = length(n);
    return len > 0.0 ? n / len : ax;
}

// Texture (u, v): u the angle about the axis from the u axis toward u x axis, v the angle around
// the tube from its outer equator toward +axis, both over 2 pi, in [0, 1).
float torus_turn(float sine, float cosine) {
    const float PI = 3.14159265358979;
    float angle = (sine == 0.0 && cosine == 0.0) ? 0.0 : atan(sine, cosine);  // atan(0, 0) is undefined in GLSL
    float f = angle < 0.0 ? 1.0 + angle / (2.0 * PI) : angle / (2.0 * PI);
    return f >= 1.0 ? 0.0 : f;
}

vec2 torus_texture_uv(Primitive p, Hit hit, vec3 point) {
    vec3 q = torus_local(p, point);
    float a = p.p0.w / (p.p0.w + p.p1.w);
    return vec2(torus_turn(q.z, q.x), torus_turn(q.y, sqrt(q.x * q.x + q.z * q.z) - a));
}
