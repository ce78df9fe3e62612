// Ray/infinite plane. Twin of host/cpu/shapes/plane.cpp.
// p0 = (point, u there), p1 = (unit normal, v there), p2 = (texture u axis, 0): the point is the
// plane's nearest the GPU's origin (the anchor near the camera), which keeps the error bound at
// the picture's scale, with its texture coordinates.
bool plane_intersect(Primitive pl, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec3 n = pl.p1.xyz;
    float denom = dot(n, ray.dir);
    if (denom == 0.0) return false;  // parallel: no hit, even if the ray lies in the plane
    float t = dot(pl.p0.xyz - ray.origin, n) / denom;
    if (t <= t_min || t >= t_max) return false;
    t_hit = t;
    return true;
}

// The hit's error (Hit.error): t = (p0 - o).n / d.n, so o + t d misses the plane by the rounding
// of the numerator (4 roundings of |p0 - o|) plus t times that of the denominator (3): the cosine
// between ray and plane cancels. With the normal's own rounding (a tilt of an ulp, moving the
// plane by that much of the hit's distance from p0) and the hit point's: 16 roundings of
// |o| + |p0| + t.
float plane_hit_error(Primitive pl, Ray ray, float t) {
    return rounding_bound(16.0, max_abs(ray.origin) + max_abs(pl.p0.xyz) + t);
}

vec3 plane_hit_normal(Primitive pl, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = plane_hit_error(pl, ray, t);
    return pl.p1.xyz;
}

// Texture (u, v): distances from the plane's point along its texture axes (p2 = u, v = u x n).
vec2 plane_texture_uv(Primitive pl, Hit hit, vec3 p) {
    vec3 d = p - pl.p0.xyz;
    return vec2(dot(d, pl.p2.xyz) + pl.p0.w, dot(d, cross(pl.p2.xyz, pl.p1.xyz)) + pl.p1.w);
}
