// Ray/cone and ray/cylinder (POV-Ray's cone and cylinder: one shape, a cylinder has equal radii).
// Twin of host/cpu/shapes/cone.cpp, which works in frame coordinates; this file in world vectors.
// p0 = (point, base radius), p1 = (unit axis, cap's z), p2 = (texture u axis, cap radius), data =
// the base's z negated (a float >= 0) with its lowest bit replaced by 1 for an open cone (a
// change of an ulp of z, within its own rounding). z is measured along the axis from the point,
// the axis segment's point nearest the GPU's origin (the anchor near the camera), so that the
// error bound stays at the picture's scale along a long cylinder; the base is at z0 <= 0, the
// cap at z1 >= 0, and the radius runs linearly from r0 at z0 to r1 at z1 (one may be 0: a
// pointed cone). Each end of non-zero radius is closed by a disc across the axis unless open.
//
// The side |p across the axis|^2 = r(z)^2 along o + t d: with f = o - point split into fz along
// the axis and fp across it (likewise dz, dp for d), R = r(fz) and K = k dz (k the slope):
// A t^2 + 2 b t + C = 0, A = |dp|^2 - K^2, b = fp.dp - R K, C = |fp|^2 - R^2. Its discriminant
// b^2 - A C equals |R dp - K fp|^2 - ((fp x dp).a)^2: no b^2 against A C, which for a distant
// origin cancel to nothing (as sphere.glsl's r^2 - |perp|^2). A and C are formed as (x - y)(x + y)
// of lengths, and the roots as q / A and C / q with q = -(b + sign(b) sqrt(disc)): no root is a
// difference of nearly equal numbers. A = 0 (a ray along the side's slope, or along a cylinder's
// axis) leaves one root, C / q, or none.
float cone_base_z(Primitive c) { return -uintBitsToFloat(c.data & ~1u); }
bool cone_is_open(Primitive c) { return (c.data & 1u) != 0u; }
float cone_slope(Primitive c) { return (c.p2.w - c.p0.w) / (c.p1.w - cone_base_z(c)); }

// Keeps a root t in (t_min, best) where z = fz + t dz lies in [z0, z1]: the side's part 0 (t, t_min
// and best measured from the ray's point at tc: cone_intersect).
void cone_keep_side(float t, float fz, float dz, float z0, float z1, float t_min, inout float best, inout float part) {
    float z = fz + t * dz;
    if (t > t_min && t < best && z >= z0 && z <= z1) {
        best = t;
        part = 0.0;
    }
}

bool cone_intersect(Primitive c, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec3 a = c.p1.xyz;
    float z0 = cone_base_z(c), z1 = c.p1.w, r0 = c.p0.w, r1 = c.p2.w;
    float k = (r1 - r0) / (z1 - z0);
    // From the ray's point nearest the packed point (at t = tc), so that every term is of the
    // shape's size for a ray that can hit it, however far its origin: roots t' from there.
    vec3 f = ray.origin - c.p0.xyz;
    float tc = -dot(f, ray.dir);
    f += tc * ray.dir;
    float fz = dot(f, a), dz = dot(ray.dir, a);
    vec3 fp = f - fz * a, dp = ray.dir - dz * a;
    float R = r0 + k * (fz - z0), K = k * dz;
    float best = t_max - tc, part = -1.0, t_low = t_min - tc;
    vec3 e = R * dp - K * fp;
    float cr = dot(cross(fp, dp), a);
    float disc = dot(e, e) - cr * cr;
    if (disc >= 0.0) {
        float lf = length(fp), ld = length(dp), aR = abs(R), aK = abs(K);
        float A = (ld - aK) * (ld + aK);
        float b = dot(fp, dp) - R * K;
        float C = (lf - aR) * (lf + aR);
        float s = sqrt(disc);
        float q = b < 0.0 ? s - b : -b - s;
        if (A != 0.0) cone_keep_side(q / A, fz, dz, z0, z1, t_low, best, part);
        if (q != 0.0) cone_keep_side(C / q, fz, dz, z0, z1, t_low, best, part);
    }
    // The ends: the planes z = z0 and z = z1, within their radius.
    if (!cone_is_open(c) && dz != 0.0) {
        for (int end = 0; end < 2; ++end) {
            float r = end == 0 ? r0 : r1;
            if (!(r > 0.0)) continue;
            float t = ((end == 0 ? z0 : z1) - fz) / dz;
            vec3 w = fp + t * dp;
            if (t > t_low && t < best && dot(w, w) <= r * r) {
                best = t;
                part = float(end + 1);
            }
        }
    }
    if (part < 0.0) return false;
    t_hit = tc + best;
    if (!(t_hit > t_min && t_hit < t_max)) return false;  // rounding of the sum
    uv = vec2(part, 0.0);  // which part: 0 the side, 1 the base's disc, 2 the cap's
    return true;
}

// The hit's error (Hit.error). The data's own rounding: the point's (|point|), the radii's and
// the axis's, a tilt of an ulp about the point, which moves the surface at the hit by that much
// of its distance from the point, at most |o| + |point| + t. f and its parts along and across the
// axis carry a few roundings of |f| <= |o| + |point|. R = r0 + k (fz - z0) carries roundings of
// r0 + |k| (|fz| + |z0|), but it moves the side only by its error over sqrt(1 + k^2) (the side's
// slope), and |k| |z0| <= |r1 - r0| as |z0| is at most the axis's length: a few roundings of
// max(r0, r1) + |f|. The roots: q and C / q are products and quotients of those terms (relative
// roundings); a root's error along the ray grows as 1 / cos near a tangent, but the hit point's
// distance from the surface is that error times cos again (as the sphere's). The ends, as the
// plane's: t = (z_end - fz) / dz misses the plane by the rounding of the numerator (|z_end| <=
// the hit's distance from the point) and of the unit axis. With the hit point's rounding: 32
// roundings of |o| + |point| + max(r0, r1) + t, as the sphere's.
float cone_hit_error(Primitive c, Ray ray, float t) {
    return rounding_bound(32.0, max_abs(ray.origin) + max_abs(c.p0.xyz) + max(c.p0.w, c.p2.w) + t);
}

// The unit normal: -axis and +axis on the base's and the cap's discs; on the side the gradient of
// |p across|^2 - r(z)^2, the outward direction across the axis minus k times the axis (a pointed
// cone's apex, where there is no direction across, takes the texture's u axis for it).
vec3 cone_hit_normal(Primitive c, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = cone_hit_error(c, ray, t);
    vec3 a = c.p1.xyz;
    if (uv.x > 1.5) return a;
    if (uv.x > 0.5) return -a;
    vec3 w = (ray.origin - c.p0.xyz) + t * ray.dir;
    vec3 across = w - dot(w, a) * a;
    float s = unit_scale(max_abs(across));
    float rho = length(s * across);
    vec3 outward = rho > 0.0 ? (s * across) / rho : c.p2.xyz;
    return normalize(outward - cone_slope(c) * a);
}

// Texture (u, v): u the angle about the axis from the u axis toward v = u x axis over 2 pi, in
// [0, 1); on the side v = 0 at the base, 1 at the cap; on an end's disc v = 0 at its centre, 1
// at its rim (polar, as the disc's).
vec2 cone_texture_uv(Primitive c, Hit hit, vec3 p) {
    const float PI = 3.14159265358979;
    vec3 a = c.p1.xyz, u_axis = c.p2.xyz;
    vec3 w = p - c.p0.xyz;
    float x = dot(w, u_axis), y = dot(w, cross(u_axis, a));
    float angle = (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x);  // atan(0, 0) is undefined in GLSL
    float u = angle < 0.0 ? 1.0 + angle / (2.0 * PI) : angle / (2.0 * PI);
    if (u >= 1.0) u = 0.0;
    float z0 = cone_base_z(c), z1 = c.p1.w;
    if (hit.uv.x < 0.5) return vec2(u, (dot(w, a) - z0) / (z1 - z0));
    float s = unit_scale(max(abs(x), abs(y)));
    float rho = length(vec2(s * x, s * y)) / s;
    return vec2(u, rho / (hit.uv.x > 1.5 ? c.p2.w : c.p0.w));
}
