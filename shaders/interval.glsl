// Interval arithmetic in float for implicit surfaces (shapes/implicit.glsl): an interval is a
// vec2 (x = lower bound, y = upper bound). The generated code of each implicit surface
// (host/gpu/shaders/glsl_interval_emitter.cpp) calls these to enclose f(o + s d) and its
// derivative in s over a piece [s.x, s.y] of the ray. Twin of host/surface/interval.cpp, written
// for the GPU's constraints:
//  * GLSL has no directed rounding: every result is widened by I_ULPS float ulps of its bounds
//    (Vulkan allows 2.5 ulps for a division, about 4 for sqrt), library functions (sin, exp,
//    pow, asin) by an absolute and a relative margin per function, a few times the largest error
//    measured on lavapipe (Mesa 22.3: asin and acos are off by up to 4e-4, atan by 3e-6, sinh,
//    tanh and atanh by 5e-5 of small values). tests/render/glsl_implicit_test.cpp checks every
//    function against double precision on the device the tests run on: a driver whose functions
//    are worse fails it there, rather than missing roots in silence;
//  * there is no empty interval: a function outside its domain is evaluated at the nearest point
//    of its domain (sqrt([-2, -1]) = [0, 0]), which only loosens the enclosure. The intersector
//    accepts a root only where f is defined at a point (shapes/implicit.glsl);
//  * NaN bounds (inf - inf, 0 * inf) become infinite ones, so no comparison ever sees a NaN.
#ifndef LANCER_INTERVAL_GLSL
#define LANCER_INTERVAL_GLSL
#ifndef LANCER_FLOAT64
#define LANCER_FLOAT64 0  // 1 where the device has shaderFloat64 (surface_codegen.cpp)
#endif

const float I_INF = 1.0 / 0.0;
const float I_ULPS = 8.0 * 1.1920929e-7;  // 8 ulps, relative
const float I_LIB_REL = 1e-5;             // library functions: relative margin
const float I_LIB_ABS = 1e-6;             // and absolute (sin, cos near 0)
const float I_PI = 3.14159265;

vec2 i_sane(vec2 r) {
    return vec2(isnan(r.x) ? -I_INF : r.x, isnan(r.y) ? I_INF : r.y);
}
vec2 i_widen(vec2 r) {
    return i_sane(r + vec2(-1.0, 1.0) * (abs(r) * I_ULPS + 1e-37));
}
// Widened for n roundings in a row (integer powers as chains of products).
vec2 i_widen_n(vec2 r, float n) {
    return i_sane(r + vec2(-1.0, 1.0) * (abs(r) * (I_ULPS * n) + 1e-37));
}
vec2 i_widen_lib(vec2 r) {
    return i_sane(r + vec2(-1.0, 1.0) * (abs(r) * I_LIB_REL + I_LIB_ABS));
}
vec2 i_widen_by(vec2 r, float relative, float absolute) {
    return i_sane(r + vec2(-1.0, 1.0) * (abs(r) * relative + absolute));
}
vec2 i_sorted(float a, float b) { return vec2(min(a, b), max(a, b)); }

vec2 i_affine(float o, float d, vec2 s) { return i_widen(i_sorted(o + d * s.x, o + d * s.y)); }
vec2 i_add(vec2 a, vec2 b) { return i_widen(a + b); }
vec2 i_sub(vec2 a, vec2 b) { return i_widen(a - b.yx); }
vec2 i_neg(vec2 a) { return -a.yx; }
vec2 i_scale(vec2 a, float c) { return i_widen(c >= 0.0 ? a * c : a.yx * c); }

// 0 * inf is 0: an infinite bound stands for "arbitrarily large", times 0 it is 0.
float i_times(float a, float b) {
    float p = a * b;
    return isnan(p) ? 0.0 : p;
}
vec2 i_mul(vec2 a, vec2 b) {
    float p1 = i_times(a.x, b.x), p2 = i_times(a.x, b.y), p3 = i_times(a.y, b.x), p4 = i_times(a.y, b.y);
    return i_widen(vec2(min(min(p1, p2), min(p3, p4)), max(max(p1, p2), max(p3, p4))));
}
vec2 i_div(vec2 a, vec2 b) {
    if (b.x <= 0.0 && b.y >= 0.0) return vec2(-I_INF, I_INF);
    float q1 = a.x / b.x, q2 = a.x / b.y, q3 = a.y / b.x, q4 = a.y / b.y;
    if (isnan(q1) || isnan(q2) || isnan(q3) || isnan(q4)) return vec2(-I_INF, I_INF);
    return i_widen(vec2(min(min(q1, q2), min(q3, q4)), max(max(q1, q2), max(q3, q4))));
}

// The smallest and the largest |x| over the interval.
float i_mig(vec2 a) { return a.x > 0.0 ? a.x : (a.y < 0.0 ? -a.y : 0.0); }
float i_mag(vec2 a) { return max(abs(a.x), abs(a.y)); }
vec2 i_magnitudes(vec2 a) { return vec2(i_mig(a), i_mag(a)); }

vec2 i_sqr(vec2 a) {
    vec2 m = i_magnitudes(a);
    vec2 r = i_widen(m * m);
    return vec2(max(r.x, 0.0), r.y);
}
vec2 i_abs(vec2 a) { return i_magnitudes(a); }
vec2 i_min(vec2 a, vec2 b) { return min(a, b); }
vec2 i_max(vec2 a, vec2 b) { return max(a, b); }
vec2 i_hull(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }

vec2 i_sqrt(vec2 a) { return i_widen(sqrt(max(a, vec2(0.0)))); }
vec2 i_cbrt(vec2 a) { return i_widen_lib(sign(a) * pow(abs(a), vec2(1.0 / 3.0))); }
vec2 i_exp(vec2 a) {
    vec2 r = i_widen_lib(exp(a));
    return vec2(max(r.x, 0.0), r.y);
}
vec2 i_exp2(vec2 a) {
    vec2 r = i_widen_lib(exp2(a));
    return vec2(max(r.x, 0.0), r.y);
}
vec2 i_log(vec2 a) { return i_widen_lib(log(max(a, vec2(0.0)))); }
vec2 i_log2(vec2 a) { return i_widen_lib(log2(max(a, vec2(0.0)))); }
vec2 i_log10(vec2 a) { return i_widen_lib(log(max(a, vec2(0.0))) * 0.434294482); }
// x^c for a constant c (x >= 0): monotone.
vec2 i_powc(vec2 a, float c) {
    vec2 p = pow(max(a, vec2(0.0)), vec2(c));
    vec2 r = i_widen_lib(c >= 0.0 ? p : p.yx);
    return vec2(max(r.x, 0.0), r.y);
}
// x^y (x > 0): the extremes are at the corners.
vec2 i_powr(vec2 a, vec2 b) {
    vec2 x = max(a, vec2(0.0));
    float p1 = pow(x.x, b.x), p2 = pow(x.x, b.y), p3 = pow(x.y, b.x), p4 = pow(x.y, b.y);
    if (isnan(p1) || isnan(p2) || isnan(p3) || isnan(p4)) return vec2(0.0, I_INF);
    vec2 r = i_widen_lib(vec2(min(min(p1, p2), min(p3, p4)), max(max(p1, p2), max(p3, p4))));
    return vec2(max(r.x, 0.0), r.y);
}

// Whether [a.x, a.y] may contain offset + k * period for an integer k (widened, so a true
// extremum is never missed).
bool i_may_contain(vec2 a, float offset, float period) {
    float margin = 1e-6 * (1.0 + i_mag(a));
    return offset + ceil((a.x - margin - offset) / period) * period <= a.y + margin;
}
bool i_covers_period(vec2 a) { return !(a.y - a.x < 6.0) || !(i_mag(a) < 1e5); }

// sin and cos reduce their argument modulo 2 pi in float: the error grows with it (NVIDIA's
// driver, measured by glsl_implicit_test: 1.9e-6 at |x| = 19, about 1e-7 |x|, beyond the fixed
// margins), so their margin has a term in the argument's magnitude, five times that.
const float I_TRIG_ARGUMENT = 5e-7;
vec2 i_sin(vec2 a) {
    if (i_covers_period(a)) return vec2(-1.0, 1.0);
    vec2 r = i_widen_by(i_sorted(sin(a.x), sin(a.y)), I_LIB_REL, I_LIB_ABS + I_TRIG_ARGUMENT * i_mag(a));
    if (i_may_contain(a, 0.5 * I_PI, 2.0 * I_PI)) r.y = 1.0;
    if (i_may_contain(a, -0.5 * I_PI, 2.0 * I_PI)) r.x = -1.0;
    return clamp(r, -1.0, 1.0);
}
vec2 i_cos(vec2 a) {
    if (i_covers_period(a)) return vec2(-1.0, 1.0);
    vec2 r = i_widen_by(i_sorted(cos(a.x), cos(a.y)), I_LIB_REL, I_LIB_ABS + I_TRIG_ARGUMENT * i_mag(a));
    if (i_may_contain(a, 0.0, 2.0 * I_PI)) r.y = 1.0;
    if (i_may_contain(a, I_PI, 2.0 * I_PI)) r.x = -1.0;
    return clamp(r, -1.0, 1.0);
}
vec2 i_tan(vec2 a) {
    if (i_covers_period(a) || !(a.y - a.x < I_PI) || i_may_contain(a, 0.5 * I_PI, I_PI)) return vec2(-I_INF, I_INF);
    return i_widen_lib(tan(a));
}
vec2 i_asin(vec2 a) { return i_widen_by(asin(clamp(a, -1.0, 1.0)), I_LIB_REL, 2e-3); }
vec2 i_acos(vec2 a) { return i_widen_by(acos(clamp(a, -1.0, 1.0)).yx, I_LIB_REL, 2e-3); }
vec2 i_atan(vec2 a) { return i_widen_by(atan(a), I_LIB_REL, 2e-5); }
// The angle of the points of the box y x x, in (-pi, pi]: at the corners, away from the cut.
vec2 i_atan2(vec2 y, vec2 x) {
    if (y.x <= 0.0 && y.y >= 0.0 && x.x <= 0.0) return vec2(-I_PI, I_PI) * 1.000001;
    float a1 = atan(y.x, x.x), a2 = atan(y.x, x.y), a3 = atan(y.y, x.x), a4 = atan(y.y, x.y);
    return i_widen_by(vec2(min(min(a1, a2), min(a3, a4)), max(max(a1, a2), max(a3, a4))), I_LIB_REL, 2e-5);
}
vec2 i_sinh(vec2 a) { return i_widen_by(sinh(a), 3e-4, I_LIB_ABS); }
vec2 i_cosh(vec2 a) {
    vec2 r = i_widen_lib(cosh(i_magnitudes(a)));
    return vec2(max(r.x, 1.0), r.y);
}
vec2 i_tanh(vec2 a) { return clamp(i_widen_by(tanh(a), 3e-4, I_LIB_ABS), -1.0, 1.0); }
vec2 i_asinh(vec2 a) { return i_widen_lib(asinh(a)); }
vec2 i_acosh(vec2 a) { return i_widen_lib(acosh(max(a, vec2(1.0)))); }
vec2 i_atanh(vec2 a) { return i_widen_by(atanh(clamp(a, -1.0, 1.0)), 1e-3, I_LIB_ABS); }
vec2 i_hypot(vec2 a, vec2 b) {
    vec2 ma = i_magnitudes(a), mb = i_magnitudes(b);
    return i_widen(vec2(length(vec2(ma.x, mb.x)), length(vec2(ma.y, mb.y))));
}

// Derivatives at the kinks: the derivative of the branch when the interval decides it, else the
// hull of the branches' (as Dual<Interval> in host/surface/dual.hpp).
vec2 i_abs_derivative(vec2 a, vec2 da) {
    if (a.x > 0.0) return da;
    if (a.y < 0.0) return i_neg(da);
    float m = i_mag(da);
    return vec2(-m, m);
}
vec2 i_min_derivative(vec2 a, vec2 b, vec2 da, vec2 db) {
    if (a.y < b.x) return da;
    if (b.y <= a.x) return db;
    return i_hull(da, db);
}
vec2 i_max_derivative(vec2 a, vec2 b, vec2 da, vec2 db) {
    if (a.x > b.y) return da;
    if (b.x >= a.y) return db;
    return i_hull(da, db);
}

#if LANCER_FLOAT64
// The same arithmetic in double, for the value of f at one point (implicit_point_may_hold_root
// in shapes/implicit.glsl): float's enclosures cannot tell f from 0 within about 1e-2 on a
// degree-8 surface, double's within about 1e-11. Only +, -, *, /, sqrt and integer powers have
// double versions (Vulkan's core double instructions); every other function is the float
// one's, on the interval rounded outward to float (i_flt) and back (i_dbl).
const double I_ULPS_D = 8.0lf * 2.220446049250313e-16lf;  // 8 ulps, relative
const double I_INF_D = double(I_INF);

dvec2 i_sane(dvec2 r) {
    return dvec2(isnan(r.x) ? -I_INF_D : r.x, isnan(r.y) ? I_INF_D : r.y);
}
dvec2 i_widen(dvec2 r) {
    return i_sane(r + dvec2(-1.0lf, 1.0lf) * (abs(r) * I_ULPS_D + 1e-300lf));
}
dvec2 i_widen_n(dvec2 r, double n) {
    return i_sane(r + dvec2(-1.0lf, 1.0lf) * (abs(r) * (I_ULPS_D * n) + 1e-300lf));
}
// Outward to float: rounding to nearest moves a bound by at most half a float ulp.
vec2 i_flt(dvec2 a) {
    vec2 r = vec2(a);
    return i_widen_by(r, 1.1920929e-7, 1e-37);
}
dvec2 i_dbl(vec2 a) { return dvec2(a); }

dvec2 i_affine(double o, double d, dvec2 s) { return i_widen(dvec2(min(o + d * s.x, o + d * s.y), max(o + d * s.x, o + d * s.y))); }
dvec2 i_add(dvec2 a, dvec2 b) { return i_widen(a + b); }
dvec2 i_sub(dvec2 a, dvec2 b) { return i_widen(a - b.yx); }
dvec2 i_neg(dvec2 a) { return -a.yx; }
double i_times(double a, double b) {
    double p = a * b;
    return isnan(p) ? 0.0lf : p;
}
dvec2 i_mul(dvec2 a, dvec2 b) {
    double p1 = i_times(a.x, b.x), p2 = i_times(a.x, b.y), p3 = i_times(a.y, b.x), p4 = i_times(a.y, b.y);
    return i_widen(dvec2(min(min(p1, p2), min(p3, p4)), max(max(p1, p2), max(p3, p4))));
}
dvec2 i_div(dvec2 a, dvec2 b) {
    if (b.x <= 0.0lf && b.y >= 0.0lf) return dvec2(-I_INF_D, I_INF_D);
    double q1 = a.x / b.x, q2 = a.x / b.y, q3 = a.y / b.x, q4 = a.y / b.y;
    if (isnan(q1) || isnan(q2) || isnan(q3) || isnan(q4)) return dvec2(-I_INF_D, I_INF_D);
    return i_widen(dvec2(min(min(q1, q2), min(q3, q4)), max(max(q1, q2), max(q3, q4))));
}
double i_mig(dvec2 a) { return a.x > 0.0lf ? a.x : (a.y < 0.0lf ? -a.y : 0.0lf); }
double i_mag(dvec2 a) { return max(abs(a.x), abs(a.y)); }
dvec2 i_magnitudes(dvec2 a) { return dvec2(i_mig(a), i_mag(a)); }
dvec2 i_sqr(dvec2 a) {
    dvec2 m = i_magnitudes(a);
    dvec2 r = i_widen(m * m);
    return dvec2(max(r.x, 0.0lf), r.y);
}
dvec2 i_abs(dvec2 a) { return i_magnitudes(a); }
dvec2 i_min(dvec2 a, dvec2 b) { return min(a, b); }
dvec2 i_max(dvec2 a, dvec2 b) { return max(a, b); }
dvec2 i_sqrt(dvec2 a) { return i_widen(sqrt(max(a, dvec2(0.0lf)))); }
#endif

#endif
