// Ray/sphere. Twin of host/cpu/shapes/sphere.cpp.
// p0 = (center, radius). Uses the cancellation-free discriminant of Ray Tracing Gems ch. 7:
// r^2 - |f - (f.d)d|^2 instead of b^2 - c, which loses all precision for distant spheres.
bool sphere_intersect(Primitive s, Ray ray, float t_min, float t_max, out float t_hit) {
    vec3 f = ray.origin - s.p0.xyz;
    float r = s.p0.w;
    float b = dot(f, ray.dir);
    vec3 perp = f - b * ray.dir;
    float disc = r * r - dot(perp, perp);
    if (disc < 0.0) return false;
    float c = dot(f, f) - r * r;
    float q = -b - sign(b) * sqrt(disc);
    if (b == 0.0) q = -sqrt(disc);
    float t0 = c / q;
    float t1 = q;
    if (t0 > t1) { float tmp = t0; t0 = t1; t1 = tmp; }
    if (t0 > t_min && t0 < t_max) { t_hit = t0; return true; }
    if (t1 > t_min && t1 < t_max) { t_hit = t1; return true; }
    return false;
}

vec3 sphere_normal(Primitive s, vec3 p) {
    return (p - s.p0.xyz) / s.p0.w;
}
