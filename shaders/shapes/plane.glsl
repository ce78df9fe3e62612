// Ray/infinite plane. Twin of host/cpu/shapes/plane.cpp.
// p0 = (point, 0), p1 = (unit normal, 0).
bool plane_intersect(Primitive pl, Ray ray, float t_min, float t_max, out float t_hit) {
    vec3 n = pl.p1.xyz;
    float denom = dot(n, ray.dir);
    if (denom == 0.0) return false;  // parallel: no hit, even if the ray lies in the plane
    float t = dot(pl.p0.xyz - ray.origin, n) / denom;
    if (t <= t_min || t >= t_max) return false;
    t_hit = t;
    return true;
}

vec3 plane_normal(Primitive pl) {
    return pl.p1.xyz;
}
