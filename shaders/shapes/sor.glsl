// Ray/sor (POV-Ray's surface of revolution), exactly, in float, in its own coordinates (it is
// always placed: placement.glsl carries rays there, with unit directions). Twin of
// host/cpu/shapes/sor.cpp (which isolates the roots by Bernstein subdivision in double).
// p.p0 = (bottom, top, largest radius, 1 where open), p.p1 = (base's r^2, cap's r^2, segment
// count), p.data its first segment (SOR_BANDS).
//
// On a segment, the surface is f = x^2 + z^2 - r^2(y) = 0 with r^2 a cubic in u = y - y0, so
// along the ray f is a cubic in t. Each segment's stretch of the ray (inside its slab y0 <= y <=
// y1 and its bounding cylinder) is re-based at its middle m, s = t - m in [-w, w], and the
// cubic's first root found by polynomial.glsl's quartic_first_root. Segments are tried in turn,
// each only before the nearest hit so far; the discs at the bottom and top close it unless open.

// f along P + s d about a point P of the segment whose bottom is y0: the cubic's coefficients
// in s (k0, and k = (s, s^2, s^3, 0)).
void sor_cubic(SorBand band, vec3 P, vec3 d, out float k0, out vec4 k) {
    vec4 c = band.coefficients;  // r^2 = ((a u + b) u + c) u + d
    float u = P.y - band.span.x;
    float r2 = ((c.x * u + c.y) * u + c.z) * u + c.w;
    float slope = (3.0 * c.x * u + 2.0 * c.y) * u + c.z;  // d(r^2)/du
    float half_curvature = 3.0 * c.x * u + c.y;           // its derivative over 2
    k0 = P.x * P.x + P.z * P.z - r2;
    k = vec4(2.0 * (P.x * d.x + P.z * d.z) - slope * d.y, d.x * d.x + d.z * d.z - half_curvature * d.y * d.y,
             -c.x * d.y * d.y * d.y, 0.0);
}

// The ray's stretch through the cylinder of radius r about the y axis, narrowed from (lo, hi);
// lo >= hi where it misses. From the ray's point nearest the axis, as sphere.glsl's.
vec2 sor_cylinder_span(Ray ray, float r, float lo, float hi) {
    float across = dot(ray.dir.xz, ray.dir.xz);
    if (across > 0.0) {
        float tc = -dot(ray.origin.xz, ray.dir.xz) / across;
        vec2 nearest = ray.origin.xz + tc * ray.dir.xz;
        float disc = (r * r - dot(nearest, nearest)) / across;
        if (!(disc >= 0.0)) return vec2(1.0, 0.0);
        float root = sqrt(disc);
        return vec2(max(lo, tc - root), min(hi, tc + root));
    }
    return dot(ray.origin.xz, ray.origin.xz) <= r * r ? vec2(lo, hi) : vec2(1.0, 0.0);
}

bool sor_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    float best = t_max;
    bool hit = false;
    // The discs: the base (uv.x = -1) and the cap (-2).
    if (p.p0.w == 0.0 && ray.dir.y != 0.0) {
        for (int end = 0; end < 2; ++end) {
            float t = ((end == 0 ? p.p0.x : p.p0.y) - ray.origin.y) / ray.dir.y;
            vec2 at = ray.origin.xz + t * ray.dir.xz;
            if (t > t_min && t < best && dot(at, at) <= (end == 0 ? p.p1.x : p.p1.y)) {
                best = t;
                hit = true;
                uv.x = end == 0 ? -1.0 : -2.0;
            }
        }
    }
    uint count = uint(p.p1.z);
    for (uint i = 0u; i < count; ++i) {
        SorBand band = sor_band_at(p.data + i);
        float lo = t_min, hi = best;
        if (ray.dir.y != 0.0) {
            float a = (band.span.x - ray.origin.y) / ray.dir.y, b = (band.span.y - ray.origin.y) / ray.dir.y;
            lo = max(lo, min(a, b));
            hi = min(hi, max(a, b));
        } else if (ray.origin.y < band.span.x || ray.origin.y > band.span.y) {
            continue;
        }
        // Widened: where the radius is the largest (a cylinder's whole side) the surface is the bound.
        vec2 span = sor_cylinder_span(ray, band.span.z * 1.00001, lo, hi);
        if (!(span.x < span.y)) continue;
        float m = 0.5 * (span.x + span.y), w = 0.5 * (span.y - span.x);
        float k0;
        vec4 k;
        sor_cubic(band, ray.origin + m * ray.dir, ray.dir, k0, k);
        float s = quartic_first_root(k0, k, w, 1.2e-7 * (abs(m) + w));
        if (s == INFINITY) continue;
        float t = clamp(m + s, span.x, span.y);
        if (t > t_min && t < best) {
            best = t;
            hit = true;
            uv.x = float(i);
        }
    }
    t_hit = best;
    return hit;
}

// r^2 at height y (0 outside the segments), and its derivative: from the segment holding y.
float sor_radius2(Primitive p, float y, out float slope) {
    slope = 0.0;
    uint count = uint(p.p1.z);
    for (uint i = 0u; i < count; ++i) {
        SorBand band = sor_band_at(p.data + i);
        if (y < band.span.x || (y > band.span.y && i + 1u < count)) continue;
        vec4 c = band.coefficients;
        float u = y - band.span.x;
        slope = (3.0 * c.x * u + 2.0 * c.y) * u + c.z;
        return ((c.x * u + c.y) * u + c.z) * u + c.w;
    }
    return 0.0;
}

// Whether a point is inside (CSG's walked leaves, csg.glsl; its reader lets only a closed sor in).
bool sor_inside(Primitive p, vec3 point) {
    float slope;
    return point.y > p.p0.x && point.y < p.p0.y && dot(point.xz, point.xz) < sor_radius2(p, point.y, slope);
}

// The hit's error (Hit.error): the cubic is formed about m from the ray's point there (a few
// roundings of |o| + t) and the segment's coefficients (of r_max^2 and its heights), and Newton
// stops within 1.2e-7 of |m| + w: as the torus's, 64 roundings of max |o| + t + the sor's size.
float sor_hit_error(Primitive p, Ray ray, float t) {
    return rounding_bound(64.0, max_abs(ray.origin) + t + max(p.p0.z, max(abs(p.p0.x), abs(p.p0.y))));
}

// The outward normal: the discs' axis, or the gradient (2x, -d(r^2)/dy, 2z) of f on the curve.
vec3 sor_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = sor_hit_error(p, ray, t);
    if (uv.x == -1.0) return vec3(0.0, -1.0, 0.0);
    if (uv.x == -2.0) return vec3(0.0, 1.0, 0.0);
    SorBand band = sor_band_at(p.data + uint(uv.x));
    vec4 c = band.coefficients;
    float u = point.y - band.span.x;
    vec3 g = vec3(2.0 * point.x, -((3.0 * c.x * u + 2.0 * c.y) * u + c.z), 2.0 * point.z);
    float len = length(g);
    return len > 0.0 ? g / len : vec3(0.0, 1.0, 0.0);
}

// Texture (u, v): the angle about y from +x toward +z over 2 pi (torus.glsl's turn), the height
// from bottom to top.
vec2 sor_texture_uv(Primitive p, Hit hit, vec3 point) {
    return vec2(torus_turn(point.z, point.x), clamp((point.y - p.p0.x) / (p.p0.y - p.p0.x), 0.0, 1.0));
}
