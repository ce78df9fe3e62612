// Ray/parallelogram corner + a*edge_u + b*edge_v, a, b in [0, 1].
// Twin of host/cpu/shapes/rectangle.cpp. p0 = (its point (a0, b0), a0), p1 = (edge_u, b0),
// p2 = (edge_v, 0): the point is about its nearest the GPU's origin (the anchor near the
// camera), so that the error bound stays at the picture's scale however far the corners are.
bool rectangle_intersect(Primitive r, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv, inout float error) {
    // Edges scaled together by a power of two (unit_scale): their cross product and its square
    // stay finite for edges up to lancer's 1e12, and t, a and b are ratios that do not change.
    float s = unit_scale(max(max_abs(r.p1.xyz), max_abs(r.p2.xyz)));
    vec3 eu = s * r.p1.xyz;
    vec3 ev = s * r.p2.xyz;
    vec3 n = cross(eu, ev);
    float denom = dot(n, ray.dir);
    if (denom == 0.0) return false;
    vec3 rel = r.p0.xyz - ray.origin;
    float t = dot(rel, n) / denom;
    if (t <= t_min || t >= t_max) return false;
    // Parallelogram coordinates of the hit, from p - corner = a eu + b ev.
    vec3 q = s * (ray.dir * t - rel);
    float nn = dot(n, n);
    float a = r.p0.w + dot(cross(q, ev), n) / nn;
    float b = r.p1.w + dot(cross(eu, q), n) / nn;
    if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return false;
    t_hit = t;
    uv = vec2(a, b);
    return true;
}

// The hit's error (Hit.error) is the plane's (plane.glsl), with the normal cross(edge_u, edge_v),
// whose rounding tilts it by a few ulps about the rectangle's point: at the hit, a few ulps of
// its distance from there, which the plane's bound already counts; the edges' length does not.
vec3 rectangle_hit_normal(Primitive r, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = plane_hit_error(r, ray, t);
    float s = unit_scale(max(max_abs(r.p1.xyz), max_abs(r.p2.xyz)));
    return normalize(cross(s * r.p1.xyz, s * r.p2.xyz));
}

// Texture (u, v): (a, b) along its edges, as the intersection found them.
vec2 rectangle_texture_uv(Primitive r, Hit hit, vec3 p) { return hit.uv; }
