// The first root of a polynomial of degree at most 4 in an interval, in float: blobs' quartics
// (shapes/blob.glsl) and sors' cubics (shapes/sor.glsl), each re-based by its caller at its
// stretch's middle. As the torus's search (shapes/torus.glsl): the critical points (the roots of
// the cubic derivative, whose own critical points a quadratic gives) split the interval into
// monotone pieces, and safeguarded Newton finds the root of the first piece whose ends differ in
// sign. Written without the closed forms, which lose roots near tangency in float.
#ifndef LANCER_POLYNOMIAL_GLSL
#define LANCER_POLYNOMIAL_GLSL

float quartic_value(float k0, vec4 k, float s) { return (((k.w * s + k.z) * s + k.y) * s + k.x) * s + k0; }
float quartic_slope(vec4 k, float s) { return ((4.0 * k.w * s + 3.0 * k.z) * s + 2.0 * k.y) * s + k.x; }  // the quartic's derivative
float quartic_curvature(vec4 k, float s) { return (12.0 * k.w * s + 6.0 * k.z) * s + 2.0 * k.y; }  // and its own

// The root in [lo, hi] of the quartic (derivative = false) or of its derivative (true), monotone
// there, whose value at lo is v_lo, of the other sign than at hi: safeguarded Newton.
float quartic_monotone_root(float k0, vec4 k, bool derivative, float lo, float hi, float v_lo, float tolerance) {
    float x = 0.5 * (lo + hi);
    for (int i = 0; i < 40; ++i) {
        float v = derivative ? quartic_slope(k, x) : quartic_value(k0, k, x);
        if (v == 0.0) break;
        if ((v > 0.0) == (v_lo > 0.0)) lo = x; else hi = x;
        float slope = derivative ? quartic_curvature(k, x) : quartic_slope(k, x);
        float next = x - v / slope;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        bool done = abs(next - x) <= tolerance || hi - lo <= tolerance;
        x = next;
        if (done) break;
    }
    return x;
}

// The first root in (-w, w) of k0 + k.x s + k.y s^2 + k.z s^3 + k.w s^4, or INFINITY.
float quartic_first_root(float k0, vec4 k, float w, float tolerance) {
    // The derivative's monotone pieces: the roots of its derivative 12 k.w s^2 + 6 k.z s + 2 k.y
    // (stable form; linear where k.w vanishes), in order.
    float gx[4];
    int m = 0;
    gx[m++] = -w;
    float a = 12.0 * k.w, b = 6.0 * k.z, c = 2.0 * k.y;
    float x1 = INFINITY, x2 = INFINITY;
    if (a != 0.0) {
        float disc = b * b - 4.0 * a * c;
        if (disc > 0.0) {
            float q = -0.5 * (b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            x1 = q / a;
            x2 = q != 0.0 ? c / q : x1;
        }
    } else if (b != 0.0) {
        x1 = -c / b;
    }
    float first = min(x1, x2), second = max(x1, x2);
    if (first > -w && first < w) gx[m++] = first;
    if (second > -w && second < w && second > first) gx[m++] = second;
    gx[m++] = w;
    // The quartic's breakpoints: the ends and its critical points between them.
    float bp[5];
    int n = 0;
    bp[n++] = -w;
    float g_lo = quartic_slope(k, gx[0]);
    for (int i = 1; i < m; ++i) {
        float g_hi = quartic_slope(k, gx[i]);
        if ((g_lo > 0.0) != (g_hi > 0.0)) bp[n++] = quartic_monotone_root(k0, k, true, gx[i - 1], gx[i], g_lo, tolerance);
        g_lo = g_hi;
    }
    bp[n++] = w;
    float f_lo = quartic_value(k0, k, bp[0]);
    for (int i = 1; i < n; ++i) {
        float f_hi = quartic_value(k0, k, bp[i]);
        if ((f_lo > 0.0) != (f_hi > 0.0)) return quartic_monotone_root(k0, k, false, bp[i - 1], bp[i], f_lo, tolerance);
        f_lo = f_hi;
    }
    return INFINITY;
}

#endif
