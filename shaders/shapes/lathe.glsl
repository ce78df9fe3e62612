// Ray/lathe (POV-Ray's lathe), exactly, in float, in its own coordinates (it is always placed:
// placement.glsl carries rays there, with unit directions). Twin of host/cpu/shapes/lathe.cpp
// (which isolates the roots of one polynomial per segment by Bernstein subdivision in double).
// p.p0 = (lowest y, highest y, largest radius, degree), p.p1 = (segment count, 1 where closed),
// p.data its first segment (LATHE_BANDS: r(s) and y(s) as cubics about s = 1/2, and the band).
//
// A linear lathe's segments are cones, met in closed form (lathe_linear_intersect) in a scene
// whose lathes are all linear; otherwise they are searched. On a segment the curve is (r(s), y(s)), s in [0, 1]. Where the ray y = o.y + t d.y meets it,
// F(s) = (d.y o.x + (y(s) - o.y) d.x)^2 + (d.y o.z + (y(s) - o.y) d.z)^2 - (d.y r(s))^2 = 0, a
// polynomial of degree 2n in s (n the lathe's degree). For a ray nearly level, F's roots come in
// pairs (the ray nears the axis and leaves it again at almost one height), too close for float:
// so the ray's stretch through the segment's band is cut at its point nearest the axis, and each
// half is taken on its own over the pieces of s where y(s) is monotone and within the half's
// heights. On such a piece t and s grow together (or against each other), the half meets the
// curve at most where F does, and F is re-expanded about the piece's middle, scaled to x in
// [-1, 1], its first root in t's order found from its derivatives' roots (each derivative's roots
// split [-1, 1] into pieces where the next is monotone; safeguarded Newton on each). A piece too
// narrow for float's s (a ray level within rounding) is solved as POV-Ray's level ray is: the
// circle of radius r(s) at the ray's height, s refined once from the ray's height there. t is then
// (y(s) - o.y) / d.y for a ray more along the axis than across it, else the crossing of the
// circle of radius r(s) on the half's side, polished by one Newton step on (s, t) (a small step
// beyond the segment's end drops the root: the ray meets the next segment there). A flat ring (a
// segment of one height: a base, a cap) is solved where the ray crosses its plane. A ray within
// rounding of touching the surface may be called a hit or a miss either way.

// A cubic given about s = 1/2 at s, and its derivative.
float lathe_cubic(vec4 c, float s) {
    float h = s - 0.5;
    return ((c.w * h + c.z) * h + c.y) * h + c.x;
}
float lathe_cubic_slope(vec4 c, float s) {
    float h = s - 0.5;
    return (3.0 * c.w * h + 2.0 * c.z) * h + c.y;
}

// Where the chord from (a, fa) to (b, fb) crosses 0 (fa, fb of other signs), within (a, b); else
// the middle.
float lathe_chord_root(float a, float b, float fa, float fb) {
    float x = a + fa / (fa - fb) * (b - a);
    return x > a && x < b ? x : 0.5 * (a + b);
}

// The s in [a, b] where y(s) = Y, y monotone there and y(a) - Y = fa of the other sign than
// y(b) - Y = fb: safeguarded Newton from the chord's crossing (a linear y's root: one trip).
float lathe_height_root(vec4 yc, float Y, float a, float b, float fa, float fb) {
    float x = lathe_chord_root(a, b, fa, fb);
    for (int i = 0; i < 60; ++i) {
        float v = lathe_cubic(yc, x) - Y;
        if (v == 0.0) break;
        if ((v > 0.0) == (fa > 0.0)) a = x; else b = x;
        float next = x - v / lathe_cubic_slope(yc, x);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        bool done = abs(next - x) <= 6e-8 * max(abs(x), 1e-3) || !(b > a);
        x = next;
        if (done) break;
    }
    return x;
}

// The breakpoints of a segment's s where y'(s) = 0 (y a cubic about 1/2), with 0 and 1, in order;
// returns their count (2 to 4).
int lathe_monotone_pieces(vec4 yc, out float bp[4]) {
    int n = 0;
    bp[n++] = 0.0;
    float a = 3.0 * yc.w, b = 2.0 * yc.z, c = yc.y;  // y' in h = s - 1/2
    float h1 = INFINITY, h2 = INFINITY;
    if (a != 0.0) {
        float disc = b * b - 4.0 * a * c;
        if (disc > 0.0) {
            float q = -0.5 * (b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            h1 = q / a;
            h2 = q != 0.0 ? c / q : h1;
        }
    } else if (b != 0.0) {
        h1 = -c / b;
    }
    float first = min(h1, h2), second = max(h1, h2);
    if (first > -0.5 && first < 0.5) bp[n++] = first + 0.5;
    if (second > -0.5 && second < 0.5 && second > first) bp[n++] = second + 0.5;
    bp[n++] = 1.0;
    return n;
}

// The k-th derivative at x of the polynomial sum c[i] x^i of degree n, and the (k+1)-th: one
// Horner loop, the factors i! / (i - k)! stepped down exactly (integers).
vec2 lathe_poly_slope(float c[7], int n, int k, float x) {
    float f = 1.0;  // n! / (n - k)!
    for (int j = 0; j < k; ++j) f *= float(n - j);
    float v = 0.0, w = 0.0;
    for (int i = n; i > k; --i) {
        w = w * x + f * float(i - k) * c[i];  // i! / (i - k - 1)!
        v = v * x + f * c[i];
        f = f * float(i - k) / float(i);
    }
    return vec2(v * x + f * c[k], w);
}

// The k-th derivative at x of the polynomial sum c[i] x^i of degree n.
float lathe_poly(float c[7], int n, int k, float x) {
    return lathe_poly_slope(c, n, k, x).x;
}

// The root in [lo, hi] of the k-th derivative, monotone there, whose value at lo is v_lo, of the
// other sign than v_hi at hi: safeguarded Newton from the chord's crossing.
float lathe_monotone_root(float c[7], int n, int k, float lo, float hi, float v_lo, float v_hi) {
    float x = lathe_chord_root(lo, hi, v_lo, v_hi);
    for (int i = 0; i < 50; ++i) {
        vec2 vs = lathe_poly_slope(c, n, k, x);
        float v = vs.x;
        if (v == 0.0) break;
        if ((v > 0.0) == (v_lo > 0.0)) lo = x; else hi = x;
        float next = x - v / vs.y;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        bool done = abs(next - x) <= 1.2e-7 || hi - lo <= 1.2e-7;
        x = next;
        if (done) break;
    }
    return x;
}

// The first root in (-1, 1) of the polynomial of degree n <= 6, or INFINITY: from the (n-1)-th
// derivative down, each one's roots split [-1, 1] into pieces where the one below is monotone.
float lathe_first_root(float c[7], int n) {
    float bp[8];
    int nb = 2;
    bp[0] = -1.0;
    bp[1] = 1.0;
    for (int k = n - 1; k >= 0; --k) {
        float next[8];
        int nn = 0;
        next[nn++] = -1.0;
        float v_lo = lathe_poly(c, n, k, bp[0]);
        for (int i = 1; i < nb; ++i) {
            float v_hi = lathe_poly(c, n, k, bp[i]);
            if ((v_lo > 0.0) != (v_hi > 0.0)) {
                float root = lathe_monotone_root(c, n, k, bp[i - 1], bp[i], v_lo, v_hi);
                if (k == 0) return root;
                next[nn++] = root;
            }
            v_lo = v_hi;
        }
        if (k == 0) return INFINITY;
        next[nn++] = 1.0;
        for (int i = 0; i < nn; ++i) bp[i] = next[i];
        nb = nn;
    }
    return INFINITY;
}

// F at s (o the ray's origin, rebased near the segment), evaluated from the curve.
float lathe_f(LatheBand band, vec3 o, vec3 d, float s) {
    float q = lathe_cubic(band.height, s) - o.y;
    float a = d.y * o.x + q * d.x, b = d.y * o.z + q * d.z, e = d.y * lathe_cubic(band.radius, s);
    return a * a + b * b - e * e;
}

// The ray's t (about the rebased origin) where it crosses the circle of radius r at the height
// it has there, on the side `side` of its point nearest the axis tm; rho2 its distance from the
// axis there, squared; across = d.x^2 + d.z^2.
float lathe_circle_t(float r, float tm, float rho2, float across, float side) {
    return tm + side * sqrt(max(r * r - rho2, 0.0) / across);
}

// A flat ring (a base, a cap, a rim: a segment of one height, whose slab would have no width in
// float): where the ray crosses its plane within (t_min, t_max), a radius the curve takes (r(s) is
// continuous: between its least and its most), its s found on the monotone piece of r that holds it.
bool lathe_ring_hit(LatheBand band, Ray ray, float t_min, float t_max, inout float t_hit, out float s) {
    s = 0.0;
    if (ray.dir.y == 0.0) return false;
    float t = (band.band.y - ray.origin.y) / ray.dir.y;
    if (!(t > t_min && t < t_max)) return false;
    float rho = length(ray.origin.xz + t * ray.dir.xz);
    float rp[4];
    int r_pieces = lathe_monotone_pieces(band.radius, rp);
    float f_lo = lathe_cubic(band.radius, rp[0]) - rho;
    for (int k = 1; k < r_pieces; ++k) {
        float f_hi = lathe_cubic(band.radius, rp[k]) - rho;
        if ((f_lo > 0.0) != (f_hi > 0.0)) {
            t_hit = t;
            s = lathe_height_root(band.radius, rho, rp[k - 1], rp[k], f_lo, f_hi);
            return true;
        }
        f_lo = f_hi;
    }
    return false;
}

// The ray's stretch (lo, hi) within (t_min, t_max) through the segment's band: its slab and its
// bounding cylinder, both widened by the rounding of the ray's height (rays from far away); tm
// the t nearest the axis (0 for a ray along it). False where there is none; a flat ring's is
// where the ray crosses its plane.
bool lathe_band_stretch(LatheBand band, float largest, Ray ray, float t_min, float t_max, float across, out float lo,
                        out float hi, out float tm) {
    vec3 d = ray.dir;
    lo = t_min;
    hi = t_max;
    tm = 0.0;
    float widen = 1e-5 * largest + 2.4e-7 * abs(ray.origin.y);
    if (d.y != 0.0) {
        float a = (band.band.y - widen - ray.origin.y) / d.y, b = (band.band.z + widen - ray.origin.y) / d.y;
        lo = max(lo, min(a, b));
        hi = min(hi, max(a, b));
    } else if (band.band.y == band.band.z || ray.origin.y < band.band.y - widen || ray.origin.y > band.band.z + widen) {
        return false;
    }
    float R = band.band.x * 1.00001 + widen;
    if (across > 0.0) {
        tm = -dot(ray.origin.xz, d.xz) / across;
        vec2 nearest = ray.origin.xz + tm * d.xz;
        float reach2 = (R * R - dot(nearest, nearest)) / across;
        if (!(reach2 >= 0.0)) return false;
        float reach = sqrt(reach2);
        lo = max(lo, tm - reach);
        hi = min(hi, tm + reach);
    } else if (dot(ray.origin.xz, ray.origin.xz) > R * R) {
        return false;
    }
    return lo <= hi;
}

// A linear lathe (its segments straight: POV-Ray's linear_spline) is a stack of cone frusta and
// flat rings, each met in closed form, not by the search above. With a segment's midpoint (rm,
// ym), h = y1 - y0 and dr = r1 - r0 (both divided by the larger, L), its cone is (h/L)^2 (x^2 +
// z^2) = ((rm h + dr (y - ym))/L)^2: a quadratic in t, solved in the form that loses no digits to
// cancellation, about the ray's point nearest the lathe's centre. A root is the segment's where
// it lies on the nappe of radii >= 0 and its s (from the height, or from the radius for a segment
// nearer level than upright) is in [0, 1] within a few of float's steps, as the search's Newton
// step allows. A ray within rounding of touching the cone (the discriminant within 8 roundings of
// 0) touches it.
bool lathe_linear_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv) {
    float best = t_max;
    bool hit = false;
    vec3 d = ray.dir;
    float m = -dot(ray.origin, d);  // d is a unit vector (placement.glsl)
    vec3 o = ray.origin + m * d;
    float across = dot(d.xz, d.xz), along = dot(o.xz, d.xz), rho2 = dot(o.xz, o.xz);
    uint count = uint(p.p1.x);
    for (uint i = 0u; i < count; ++i) {
        LatheBand band = lathe_band_at(p.data + i);
        float s;
        if (band.band.y == band.band.z) {
            if (lathe_ring_hit(band, ray, t_min, best, best, s)) {
                hit = true;
                uv = vec2(float(i), s);
            }
            continue;
        }
        float L = max(abs(band.height.y), abs(band.radius.y));
        float h = band.height.y / L, dr = band.radius.y / L;
        float Y = o.y - band.height.x;
        float P = band.radius.x * h + dr * Y, Q = dr * d.y;
        float A = h * h * across - Q * Q, B = 2.0 * (h * h * along - P * Q), C = h * h * rho2 - P * P;
        float disc = B * B - 4.0 * A * C;
        if (disc < 0.0) {
            if (disc < -4.8e-7 * (B * B + 4.0 * abs(A * C))) continue;
            disc = 0.0;
        }
        float q = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
        vec2 roots = vec2(A != 0.0 ? q / A : INFINITY, q != 0.0 ? C / q : INFINITY);
        for (int k = 0; k < 2; ++k) {
            float t = roots[k];
            // The cone's other nappe (h rho = -(rm h + dr (y - ym)): a radius < 0) is not the lathe's.
            if (!(t + m > t_min && t + m < best) || (P + Q * t) * h < 0.0) continue;
            float r_s = abs(h) >= abs(dr) ? (Y + t * d.y) / band.height.y : (length(o.xz + t * d.xz) - band.radius.x) / band.radius.y;
            if (!(abs(r_s) <= 0.5 + 2e-7)) continue;
            best = t + m;
            hit = true;
            uv = vec2(float(i), clamp(0.5 + r_s, 0.0, 1.0));
        }
    }
    t_hit = best;
    return hit;
}

// A lathe of a quadratic, cubic or Bezier spline: the search described at the top of this file.
bool lathe_curved_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv) {
    float best = t_max;
    bool hit = false;
    vec3 d = ray.dir;
    float across = dot(d.xz, d.xz);
    bool steep = d.y * d.y >= across;
    uint count = uint(p.p1.x);
    int degree = int(p.p0.w);
    // The segments in groups of 32: first those whose band the ray crosses (slab and cylinder),
    // then only those searched, the flat rings in a loop of their own (lavapipe runs a loop's
    // body, both sides of each if, for every lane while one lane needs another trip).
    for (uint base = 0u; base < count; base += 32u) {
        uint flats = 0u, curves = 0u;
        for (uint j = base; j < min(count, base + 32u); ++j) {
            LatheBand band = lathe_band_at(p.data + j);
            float lo, hi, tm;
            if (!lathe_band_stretch(band, p.p0.z, ray, t_min, t_max, across, lo, hi, tm)) continue;
            if (band.band.y == band.band.z) flats |= 1u << (j - base); else curves |= 1u << (j - base);
        }
        for (; flats != 0u; flats &= flats - 1u) {
            uint i = base + uint(findLSB(flats));
            float s;
            if (lathe_ring_hit(lathe_band_at(p.data + i), ray, t_min, best, best, s)) {
                hit = true;
                uv = vec2(float(i), s);
            }
        }
        for (; curves != 0u; curves &= curves - 1u) {
            uint i = base + uint(findLSB(curves));
            LatheBand band = lathe_band_at(p.data + i);
            float lo, hi, tm;  // about the original origin
            if (!lathe_band_stretch(band, p.p0.z, ray, t_min, best, across, lo, hi, tm)) continue;
            if (!(lo < hi)) continue;
            // Rebased at the stretch's middle: o = origin + m d, and t about it.
            float m = 0.5 * (lo + hi);
            vec3 o = ray.origin + m * d;
            float rho2 = 0.0;
            if (across > 0.0) {
                vec2 nearest = ray.origin.xz + tm * d.xz;
                rho2 = dot(nearest, nearest);
            }
            tm -= m;
            float t_lo = lo - m, t_hi = hi - m;
            float bp[4];
            int pieces = lathe_monotone_pieces(band.height, bp);
            // Each half of the stretch about the point nearest the axis (one where the ray is steep).
            int parts = steep ? 1 : 2;  // (a bound the compiler cannot unroll: the body is large)
            for (int part = 0; part < parts; ++part) {
                float ta = t_lo, tb = t_hi, side = 1.0;
                if (!steep) {
                    side = part == 0 ? -1.0 : 1.0;
                    if (part == 0) tb = min(tb, tm); else ta = max(ta, tm);
                }
                if (!(ta <= tb) || ta + m >= best) continue;
                float Ya = o.y + ta * d.y, Yb = o.y + tb * d.y;
                float Ylo = min(Ya, Yb), Yhi = max(Ya, Yb);
                for (int k = 1; k < pieces; ++k) {
                    float s0 = bp[k - 1], s1 = bp[k];
                    float y0 = lathe_cubic(band.height, s0), y1 = lathe_cubic(band.height, s1);
                    bool rising = y1 >= y0;
                    float ylo = min(y0, y1), yhi = max(y0, y1);
                    if (yhi < Ylo || ylo > Yhi) continue;
                    // The piece's s where y is within [Ylo, Yhi].
                    float sa = s0, sb = s1;
                    float ends[2];
                    for (int e = 0; e < pieces - k + 1 && e < 2; ++e) {  // (one call site: a bound not unrolled)
                        float Y = e == 0 ? Ylo : Yhi;
                        bool beyond = e == 0 ? ylo < Ylo : yhi > Yhi;
                        ends[e] = beyond ? lathe_height_root(band.height, Y, s0, s1, y0 - Y, y1 - Y) : ((e == 0) == rising ? s0 : s1);
                    }
                    float slo = ends[0], shi = ends[1];
                    // Widened by a few of float's steps in s: the ends are found within them, and F's
                    // root (its constant term rounded to the ray's heights) may lie a little beyond.
                    sa = max(s0, min(slo, shi) - 4e-7);
                    sb = min(s1, max(slo, shi) + 4e-7);
                    // t grows with s where y does and the ray rises, or neither.
                    bool forward = rising == (d.y >= 0.0);
                    float s_root = -1.0;
                    float w = 0.5 * (sb - sa), sm = 0.5 * (sa + sb);
                    if (w > 1e-6) {
                        // F about sm in x = (s - sm) / w, x in [-1, 1]: its factors' Taylor coefficients.
                        float u = sm - 0.5;
                        vec4 yc = band.height, rc = band.radius;
                        vec4 Y = vec4(((yc.w * u + yc.z) * u + yc.y) * u + yc.x - o.y, (3.0 * yc.w * u + 2.0 * yc.z) * u + yc.y,
                                      3.0 * yc.w * u + yc.z, yc.w);
                        vec4 Rr = vec4(((rc.w * u + rc.z) * u + rc.y) * u + rc.x, (3.0 * rc.w * u + 2.0 * rc.z) * u + rc.y,
                                       3.0 * rc.w * u + rc.z, rc.w);
                        vec4 scale = vec4(1.0, w, w * w, w * w * w);
                        if (!forward) scale.yw = -scale.yw;  // x -> -x: the first root in t's order
                        Y *= scale;
                        Rr *= scale;
                        vec4 A = Y * d.x, B = Y * d.z, E = Rr * d.y;
                        A.x += d.y * o.x;
                        B.x += d.y * o.z;
                        float c[7];
                        for (int j = 0; j < 7; ++j) c[j] = 0.0;
                        for (int a = 0; a <= degree; ++a)
                            for (int b = 0; b <= degree; ++b) c[a + b] += A[a] * A[b] + B[a] * B[b] - E[a] * E[b];
                        // No root in [-1, 1] where the constant term outweighs all the others.
                        float others = 0.0;
                        for (int j = 1; j <= 2 * degree; ++j) others += abs(c[j]);
                        if (abs(c[0]) > others) continue;
                        float x = lathe_first_root(c, 2 * degree);
                        if (x == INFINITY) continue;
                        s_root = sm + (forward ? x : -x) * w;
                    } else {
                        // A piece narrow within float's s: the ray is level there within rounding.
                        if (steep) {
                            if ((lathe_f(band, o, d, sa) > 0.0) == (lathe_f(band, o, d, sb) > 0.0)) continue;
                            s_root = sm;
                        } else {
                            float r = lathe_cubic(band.radius, sm);
                            if (r * r < rho2) continue;
                            float t = lathe_circle_t(r, tm, rho2, across, side);
                            // s where y(s) is the ray's height there: the piece's chord (its s within float's).
                            float Y = o.y + t * d.y, va = lathe_cubic(band.height, sa) - Y, vb = lathe_cubic(band.height, sb) - Y;
                            s_root = (va > 0.0) == (vb > 0.0) ? (abs(va) < abs(vb) ? sa : sb)
                                                              : clamp(sa + va / (va - vb) * (sb - sa), sa, sb);
                        }
                    }
                    float t;
                    if (steep) {
                        t = (lathe_cubic(band.height, s_root) - o.y) / d.y;
                    } else {
                        float r = lathe_cubic(band.radius, s_root);
                        t = lathe_circle_t(r, tm, rho2, across, side);
                        // A narrow piece was not solved but taken whole: its circle must meet the
                        // half where the half is (else the curve's height is the ray's there only
                        // because the half is short, cut by a nearer hit, and the crossing is elsewhere).
                        float slack = 0.01 * (tb - ta) + 1e-6 * (abs(m) + p.p0.z);
                        if (w <= 1e-6 && (r * r < rho2 || t < ta - slack || t > tb + slack)) continue;
                        // The circle's t takes the ray at r(s) whatever its height there: one Newton
                        // step on (s, t) for y(s) = the ray's height and r(s) = its distance from the
                        // axis. A small step that leaves the segment says the crossing is beyond its
                        // end (a ray grazing a corner within rounding, which meets the next segment).
                        float ys = lathe_cubic(band.height, s_root);
                        vec2 at = o.xz + t * d.xz;
                        float g1 = ys - (o.y + t * d.y), g2 = dot(at, at) - r * r;
                        float j11 = lathe_cubic_slope(band.height, s_root);
                        float j21 = -2.0 * r * lathe_cubic_slope(band.radius, s_root);
                        float j12 = -d.y, j22 = 2.0 * dot(at, d.xz);
                        float det = j11 * j22 - j12 * j21;
                        if (det != 0.0) {
                            float ds = -(g1 * j22 - j12 * g2) / det, dt = -(j11 * g2 - j21 * g1) / det;
                            if (abs(ds) < 1e-3) {
                                float s_new = s_root + ds;
                                if (s_new < -2e-7 || s_new > 1.0 + 2e-7) continue;
                                s_root = clamp(s_new, 0.0, 1.0);
                                t += dt;
                            }
                        }
                    }
                    t = clamp(t, ta, tb) + m;
                    if (t > t_min && t < best) {
                        best = t;
                        hit = true;
                        uv = vec2(float(i), s_root);
                    }
                }
            }
        }
    }
    t_hit = best;
    return hit;
}

// The closed form where every lathe of the scene is linear (LATHE_DEGREES); where some is curved,
// the search for all of them: lavapipe would run both for every lane of a SIMD group that meets
// either (bench/extrusions.toml, a linear bowl beside a cubic goblet, took 1.06-1.09 times as long).
const bool ONLY_LINEAR_LATHES = LATHE_DEGREES == 2u;

bool lathe_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    if (ONLY_LINEAR_LATHES) return lathe_linear_intersect(p, ray, t_min, t_max, t_hit, uv);
    return lathe_curved_intersect(p, ray, t_min, t_max, t_hit, uv);
}

// Whether a point is inside (CSG's walked leaves, csg.glsl; its reader lets only a closed lathe
// in): POV-Ray's even-odd rule, the crossings of the curve by the half-line from the point away
// from the axis at its height, one per monotone piece of y(s) whose ends lie either side of it.
bool lathe_inside(Primitive p, vec3 point) {
    if (p.p1.y == 0.0 || point.y < p.p0.x || point.y > p.p0.y) return false;
    float rho = length(point.xz);
    uint count = uint(p.p1.x);
    int crossings = 0;
    for (uint i = 0u; i < count; ++i) {
        LatheBand band = lathe_band_at(p.data + i);
        if (point.y < band.band.y || point.y > band.band.z || rho >= band.band.x) continue;
        float bp[4];
        int pieces = lathe_monotone_pieces(band.height, bp);
        float f_lo = lathe_cubic(band.height, bp[0]) - point.y;
        for (int k = 1; k < pieces; ++k) {
            float f_hi = lathe_cubic(band.height, bp[k]) - point.y;
            if ((f_lo > 0.0) != (f_hi > 0.0)) {
                float s = lathe_height_root(band.height, point.y, bp[k - 1], bp[k], f_lo, f_hi);
                if (lathe_cubic(band.radius, s) > rho) ++crossings;
            }
            f_lo = f_hi;
        }
    }
    return (crossings & 1) != 0;
}

// The hit's error (Hit.error): the polynomial is formed about the stretch's middle from the
// ray's point there (a few roundings of |o| + t) and the segment's cubics (of the lathe's size),
// its root found within 1.2e-7 of its piece, and a level ray's circle taken at the ray's height
// within rounding: as the torus's and the sor's, 64 roundings of max |o| + t + the lathe's size.
float lathe_hit_error(Primitive p, Ray ray, float t) {
    return rounding_bound(64.0, max_abs(ray.origin) + t + max(p.p0.z, max(abs(p.p0.x), abs(p.p0.y))));
}

// The outward normal: the curve's (y'(s), -r'(s)) on the segment's side, turned about the axis
// to the point (uv = (segment, s)); on the axis, along it.
vec3 lathe_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = lathe_hit_error(p, ray, t);
    LatheBand band = lathe_band_at(p.data + uint(uv.x));
    float rp = lathe_cubic_slope(band.radius, uv.y), yp = lathe_cubic_slope(band.height, uv.y);
    if (rp == 0.0 && yp == 0.0) {
        rp = lathe_cubic(band.radius, 1.0) - lathe_cubic(band.radius, 0.0);
        yp = lathe_cubic(band.height, 1.0) - lathe_cubic(band.height, 0.0);
    }
    float nr = band.band.w * yp, ny = -band.band.w * rp;
    float rho = length(point.xz);
    vec3 n = rho > 0.0 ? vec3(nr * point.x / rho, ny, nr * point.z / rho) : vec3(0.0, ny, 0.0);
    float len = length(n);
    return len > 0.0 ? n / len : -ray.dir;
}

// Texture (u, v): the angle about y from +x toward +z over 2 pi (torus.glsl's turn), and
// POV-Ray's v: (segment + s) over the segment count.
vec2 lathe_texture_uv(Primitive p, Hit hit, vec3 point) {
    return vec2(torus_turn(point.z, point.x), clamp((hit.uv.x + hit.uv.y) / p.p1.x, 0.0, 1.0));
}
