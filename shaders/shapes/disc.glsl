// Ray/disc (POV-Ray's disc: hole_radius <= distance from the centre <= radius, in the plane
// through the centre across the normal). Twin of host/cpu/shapes/disc.cpp.
// p0 = (point, radius), p1 = (unit normal, hole radius), p2 = (texture u axis, alpha), data =
// beta's bits: the point is about the disc's nearest the GPU's origin (the anchor near the
// camera), as the rectangle's, so that the error bound stays at the picture's scale however far
// the centre is; the centre is point + alpha u + beta v (v = u x n, the plane's texture axes).
float disc_beta(Primitive d) { return uintBitsToFloat(d.data); }

bool disc_intersect(Primitive d, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec3 n = d.p1.xyz;
    float denom = dot(n, ray.dir);
    if (denom == 0.0) return false;  // parallel: no hit, even if the ray lies in the disc's plane
    vec3 rel = d.p0.xyz - ray.origin;
    float t = dot(rel, n) / denom;
    if (t <= t_min || t >= t_max) return false;
    // The hit from the centre, in the disc's axes: (hit - point) minus (alpha, beta). Scaled by
    // a power of two with the radius (unit_scale) before squaring: exact, and finite for radii
    // up to lancer's 1e12.
    vec3 q = ray.dir * t - rel;
    vec3 u = d.p2.xyz;
    float x = dot(q, u) - d.p2.w;
    float y = dot(q, cross(u, n)) - disc_beta(d);
    float s = unit_scale(d.p0.w);
    float r2 = (s * x) * (s * x) + (s * y) * (s * y);
    float outer = s * d.p0.w, inner = s * d.p1.w;
    if (r2 > outer * outer || r2 < inner * inner) return false;
    t_hit = t;
    uv = vec2(x, y);  // texture_uv turns them into polar coordinates
    return true;
}

// The hit's error (Hit.error) is the plane's (plane.glsl: the derivation is there): the radius,
// hole and centre only decide whether there is a hit (their rounding moves the edges by ulps of
// the radius), not how far the hit is from the plane.
vec3 disc_hit_normal(Primitive d, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = plane_hit_error(d, ray, t);
    return d.p1.xyz;
}

// Texture (u, v): polar, from the hit's (x, y) about the centre that the intersection found:
// u the angle from the u axis toward v = u x n over 2 pi, in [0, 1); v from 0 at the hole's edge
// (the centre without a hole) to 1 at the rim.
vec2 disc_texture_uv(Primitive d, Hit hit, vec3 p) {
    const float PI = 3.14159265358979;
    float x = hit.uv.x, y = hit.uv.y;
    float angle = (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x);  // atan(0, 0) is undefined in GLSL
    float u = angle < 0.0 ? 1.0 + angle / (2.0 * PI) : angle / (2.0 * PI);
    if (u >= 1.0) u = 0.0;
    float s = unit_scale(d.p0.w);
    float r = length(vec2(s * x, s * y)) / s;
    return vec2(u, (r - d.p1.w) / (d.p0.w - d.p1.w));
}
