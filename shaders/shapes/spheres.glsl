// Ray/sphere set: one primitive per placement of a point set's spheres, traced in the file's own
// coordinates (its object's frame carries the ray there: placement.glsl) through the set's own
// tree (shapes/element_tree.glsl) over its spheres (SET_SPHERES), each as shapes/sphere.glsl's.
// Twin of host/cpu/shapes/spheres.cpp (which has its own tree). p.data = the set (MeshInfo);
// p.p0.y = 1 where the spheres take the file's colours (MeshInfo::first_material). uv.x = which
// sphere of the set (a whole number: exact in float below 2^24, limits.hpp's kMaxSetSpheres).

// Sphere `sphere` (an absolute index): its t in (t_min, t_max), or -1; sphere.glsl's
// cancellation-free discriminant.
float spheres_element_hit(uint sphere, Ray ray, float t_min, float t_max) {
    vec4 s = set_sphere_at(sphere).sphere;
    vec3 f = ray.origin - s.xyz;
    float b = dot(f, ray.dir);
    vec3 perp = f - b * ray.dir;
    float disc = s.w * s.w - dot(perp, perp);
    float t;
    return disc >= 0.0 && sphere_root(b, disc, dot(f, f) - s.w * s.w, t_min, t_max, t) ? t : -1.0;
}

bool spheres_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    return element_set_intersect(p, true, shadow_ray_any_hit, ray, t_min, t_max, t_hit, uv);
}

vec4 spheres_hit_sphere(Primitive p, vec2 uv) { return set_sphere_at(mesh_at(p.data).first_element + uint(uv.x)).sphere; }

// The unit normal, and the hit's error bound: sphere.glsl's, 32 roundings of |o| + |c| + r + t
// (in the file's coordinates: primitive_normal carries it to the world's).
vec3 spheres_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    vec4 s = spheres_hit_sphere(p, uv);
    error = rounding_bound(32.0, max_abs(ray.origin) + max_abs(s.xyz) + s.w + t);
    return (point - s.xyz) / s.w;
}

// Texture (u, v): a sphere's (sphere.glsl), in the file's axes.
vec2 spheres_texture_uv(Primitive p, Hit hit, vec3 point) {
    vec4 s = spheres_hit_sphere(p, hit.uv);
    return sphere_direction_uv((point - s.xyz) / s.w);
}
