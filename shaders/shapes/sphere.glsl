// Ray/sphere. Twin of host/cpu/shapes/sphere.cpp. Each file of shapes/ implements the same three
// functions for its shape (shapes.h, docs/adding-a-shape.md): <name>_intersect, <name>_hit_normal
// and <name>_texture_uv.
// p0 = (center, radius), p1, p2 = (the sphere's own x and y axes: its texture's frame, 0). Uses
// the cancellation-free discriminant of Ray Tracing Gems ch. 7: r^2 - |f - (f.d)d|^2 instead of
// b^2 - c, which loses all precision for distant spheres.
//
// A sphere far larger than its distance from the camera (a ground of radius 10^6 under the scene,
// a POV-Ray habit) has a centre float cannot place to within the picture's detail. Where the
// scene has one (SPHERES_BY_NEAR_POINTS), every sphere is packed by its point q nearest the GPU's
// origin (the anchor near the camera) instead, with n, the unit normal there: p0 = (q, radius),
// p1 = (x axis, n.x), p2 = (y axis, n.y), data = n.z's bits. With e = o - q and f = e + r n
// never formed, |f|^2 - r^2 = |e|^2 + 2 r e.n and r^2 - |perp|^2 = r^2 (n.d)^2 - 2 r e'.n' - |e'|^2
// (e', n' across the ray) hold only terms of the picture's scale, or squares.
vec3 sphere_near_normal(Primitive s) { return vec3(s.p1.w, s.p2.w, uintBitsToFloat(s.data)); }

// The nearer root in (t_min, t_max) of t^2 + 2 b t + c = 0 whose discriminant b^2 - c the caller
// computed without cancellation (disc >= 0), if any (CSG asks from t_min = -infinity). The larger
// root in magnitude, q, comes without cancellation; the other is c / q.
bool sphere_root(float b, float disc, float c, float t_min, float t_max, out float t) {
    float q = -b - sign(b) * sqrt(disc);
    if (b == 0.0) q = -sqrt(disc);
    float t0 = c / q;
    float t1 = q;
    if (t0 > t1) { float tmp = t0; t0 = t1; t1 = tmp; }
    t = t0 > t_min && t0 < t_max ? t0 : t1;
    return t > t_min && t < t_max;
}

bool sphere_intersect(Primitive s, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    float r = s.p0.w;
    float b, disc, c;
    if (SPHERES_BY_NEAR_POINTS) {
        vec3 e = ray.origin - s.p0.xyz, n = sphere_near_normal(s);
        float ed = dot(e, ray.dir), nd = dot(n, ray.dir);
        vec3 e_across = e - ed * ray.dir, n_across = n - nd * ray.dir;
        b = ed + r * nd;
        disc = (r * nd) * (r * nd) - 2.0 * r * dot(e_across, n_across) - dot(e_across, e_across);
        c = dot(e, e) + 2.0 * r * dot(e, n);
    } else {
        vec3 f = ray.origin - s.p0.xyz;
        b = dot(f, ray.dir);
        vec3 perp = f - b * ray.dir;
        disc = r * r - dot(perp, perp);
        c = dot(f, f) - r * r;
    }
    return disc >= 0.0 && sphere_root(b, disc, c, t_min, t_max, t_hit);
}

// The hit's error (Hit.error): f = o - c and perp carry rounding errors of a few |f| ulps; near
// a tangent their effect on t grows as 1 / cos, the cosine between the ray and the normal, but
// the hit point's distance from the sphere is that t error times cos again, so it stays a few
// roundings of |f| <= |o| + |c|. With the centre's and radius's own rounding and the hit
// point's (hit_point_rounding): 32 roundings of |o| + |c| + r + t. By the near point: the same
// with |q| for |c| + r, the roundings of r n being relative to the terms they enter.
float sphere_hit_error(Primitive s, Ray ray, float t) {
    return rounding_bound(32.0, max_abs(ray.origin) + max_abs(s.p0.xyz) + (SPHERES_BY_NEAR_POINTS ? 0.0 : s.p0.w) + t);
}

// The unit vector from the centre to p.
vec3 sphere_direction(Primitive s, vec3 p) {
    return SPHERES_BY_NEAR_POINTS ? (p - s.p0.xyz) / s.p0.w + sphere_near_normal(s) : (p - s.p0.xyz) / s.p0.w;
}

// The unit normal at the hit at t (point p), and the hit's error bound.
vec3 sphere_hit_normal(Primitive s, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = sphere_hit_error(s, ray, t);
    return sphere_direction(s, p);
}

// Longitude and latitude of the unit direction d in the sphere's own frame.
vec2 sphere_direction_uv(vec3 d) {
    const float PI = 3.14159265358979;
    float longitude = (d.x == 0.0 && d.z == 0.0) ? 0.0 : atan(d.x, -d.z);  // atan(0, 0) is undefined in GLSL
    return vec2(0.5 + longitude / (2.0 * PI), 0.5 + asin(clamp(d.y, -1.0, 1.0)) / PI);
}

// Texture (u, v): longitude and latitude in the sphere's own frame (p1, p2 = its x and y axes):
// u = 0.5 faces -z and grows toward +x; v runs from 0 at the south pole to 1 at the north pole.
vec2 sphere_texture_uv(Primitive s, Hit hit, vec3 p) {
    vec3 w = sphere_direction(s, p);
    return sphere_direction_uv(vec3(dot(w, s.p1.xyz), dot(w, s.p2.xyz), dot(w, cross(s.p1.xyz, s.p2.xyz))));
}
