// Ray/axis-aligned box by slabs. Twin of host/cpu/shapes/box.cpp. p0 = min, p1 = max.
// A ray starting inside hits the far side (t_exit), so reflections and shadows from inside work.
// uv: the outward normal's axis (0, 1, 2) and sign of the slab that gave t: at an edge, the face
// the hit is on is the one whose slab the ray crossed there, whatever the hit point's rounding
// (in a turned box's coordinates that rounding is the map's, larger than the box's own).
bool box_intersect(Primitive b, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec3 inv = 1.0 / ray.dir;  // +-inf for axis-parallel rays; the slab test stays correct
    vec3 t0 = (b.p0.xyz - ray.origin) * inv;
    vec3 t1 = (b.p1.xyz - ray.origin) * inv;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float t_enter = max(max(tn.x, tn.y), tn.z);
    float t_exit = min(min(tf.x, tf.y), tf.z);
    if (t_enter > t_exit) return false;
    float side;
    if (t_enter > t_min && t_enter < t_max) {
        t_hit = t_enter;
        uv.x = t_enter == tn.x ? 0.0 : (t_enter == tn.y ? 1.0 : 2.0);
        side = -1.0;  // entering: the face turned toward the ray
    } else if (t_exit > t_min && t_exit < t_max) {
        t_hit = t_exit;
        uv.x = t_exit == tf.x ? 0.0 : (t_exit == tf.y ? 1.0 : 2.0);
        side = 1.0;
    } else {
        return false;
    }
    uv.y = ray.dir[int(uv.x)] < 0.0 ? -side : side;
    return true;
}

// The face of the slab that gave t (uv), and the hit's error (Hit.error): on the face of axis
// i, o_i + t d_i misses the face by the rounding of (b_i - o_i) / d_i (3 roundings, relative: the
// cosine d_i cancels) and of the hit point: 16 roundings of |o| + |b_i| + t, b_i the face's
// coordinate (the box's other corners, however far, do not count).
vec3 box_hit_normal(Primitive b, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    vec3 n = vec3(0.0);
    n[int(uv.x)] = uv.y;
    vec3 face = mix(b.p0.xyz, b.p1.xyz, greaterThan(n, vec3(0.0)));
    error = rounding_bound(16.0, max_abs(ray.origin) + abs(dot(face, abs(n))) + t);
    return n;
}

// Texture (u, v): the whole image on each face, upright seen from outside. Side faces have v
// up (+y) and u to the right; the top has u = +x, v = +z; the bottom u = +x, v = -z.
vec2 box_texture_uv(Primitive b, Hit hit, vec3 p) {
    vec3 face_normal = hit.normal;
    vec3 f = (p - b.p0.xyz) / (b.p1.xyz - b.p0.xyz);  // 0 at min, 1 at max, per axis
    if (face_normal.x > 0.5) return vec2(f.z, f.y);
    if (face_normal.x < -0.5) return vec2(1.0 - f.z, f.y);
    if (face_normal.z > 0.5) return vec2(1.0 - f.x, f.y);
    if (face_normal.y > 0.5) return vec2(f.x, f.z);
    if (face_normal.y < -0.5) return vec2(f.x, 1.0 - f.z);
    return vec2(f.x, f.y);  // -z, the face toward a default camera
}
