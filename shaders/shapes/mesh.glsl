// Ray/triangle mesh: one primitive per placement of a mesh, traced in the mesh file's own
// coordinates (its object's frame carries the ray there: placement.glsl), through the mesh's
// own tree (MESH_NODES) over its triangles (MESH_TRIANGLES), each by the watertight test of
// Woop, Benthin and Wald (JCGT 2013). Twin of host/cpu/shapes/mesh.cpp (which has its own tree).
// p.data = the mesh (MeshInfo); p.p0.x = 1 where it is shaded smooth, p.p0.y = 1 where the
// triangles take the file's own materials (MeshInfo::first_material). Every triangle of a mesh
// takes its vertices from the same floats, so the edge functions of a shared edge are the same
// numbers negated: a ray through the edge is inside one triangle or both (zero counts as
// inside), never neither. uv.x = which triangle of the mesh (a whole number: exact in float
// below 2^24, limits.hpp's kMaxMeshTriangles), for the normal, the shading and the texture.

// The ray sheared so that it runs along +z from the origin (the paper's kx, ky, kz and S).
struct ShearedRay {
    ivec3 k;
    vec3 s;
};

void shear_axes(vec3 d, out ivec3 k, out vec3 s) {
    vec3 ad = abs(d);
    int kz = ad.x >= ad.y && ad.x >= ad.z ? 0 : (ad.y >= ad.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0) {  // keeps the winding
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    k = ivec3(kx, ky, kz);
    s = vec3(d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
}

// Triangle (a, b, c) relative to the ray's origin: its t in (t_min, t_max), or -1.
float triangle_hit(ShearedRay r, vec3 a, vec3 b, vec3 c, float t_min, float t_max) {
    float ax = a[r.k.x] - r.s.x * a[r.k.z], ay = a[r.k.y] - r.s.y * a[r.k.z];
    float bx = b[r.k.x] - r.s.x * b[r.k.z], by = b[r.k.y] - r.s.y * b[r.k.z];
    float cx = c[r.k.x] - r.s.x * c[r.k.z], cy = c[r.k.y] - r.s.y * c[r.k.z];
    // The same products in the same order for a shared edge, whichever triangle asks (no fused
    // multiply-add may change one side's rounding: `precise`).
    precise float u = cx * by - cy * bx;
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return -1.0;
    float det = u + v + w;
    if (det == 0.0) return -1.0;  // edge-on
    float t = (u * (r.s.z * a[r.k.z]) + v * (r.s.z * b[r.k.z]) + w * (r.s.z * c[r.k.z])) / det;
    return t > t_min && t < t_max ? t : -1.0;
}

float mesh_element_hit(uint triangle, vec3 origin, ivec3 k, vec3 s, float t_min, float t_max) {
    MeshTriangle tr = mesh_triangle_at(triangle);
    return triangle_hit(ShearedRay(k, s), tr.v0.xyz - origin, tr.v1.xyz - origin, tr.v2.xyz - origin, t_min, t_max);
}

bool mesh_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    return element_set_intersect(p, false, shadow_ray_any_hit, ray, t_min, t_max, t_hit, uv);
}

MeshTriangle mesh_hit_triangle(Primitive p, vec2 uv) { return mesh_triangle_at(mesh_at(p.data).first_element + uint(uv.x)); }

// The hit's error (Hit.error): t comes from the vertices relative to the origin, each rounded a
// few times in the shear and the edge functions, as a plane's from its point (plane.glsl), so
// 32 roundings of |o| + the largest vertex + t bound the hit's distance from the triangle's plane
// (in the file's coordinates: primitive_normal carries it to the world's).
vec3 mesh_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    MeshTriangle tr = mesh_hit_triangle(p, uv);
    float reach = max(max_abs(tr.v0.xyz), max(max_abs(tr.v1.xyz), max_abs(tr.v2.xyz)));
    error = rounding_bound(32.0, max_abs(ray.origin) + reach + t);
    vec3 e1 = tr.v1.xyz - tr.v0.xyz, e2 = tr.v2.xyz - tr.v0.xyz;
    float s = unit_scale(max(max_abs(e1), max_abs(e2)));  // the cross product neither overflows nor vanishes
    return unit_vector(cross(s * e1, s * e2));
}

// Barycentric weights of vertices 1 and 2 at point q of the triangle (the file's coordinates).
vec2 mesh_barycentric(MeshTriangle tr, vec3 q) {
    vec3 e1 = tr.v1.xyz - tr.v0.xyz, e2 = tr.v2.xyz - tr.v0.xyz;
    float s = unit_scale(max(max_abs(e1), max_abs(e2)));
    e1 *= s;
    e2 *= s;
    vec3 d = s * (q - tr.v0.xyz);
    vec3 n = cross(e1, e2);
    float nn = dot(n, n);
    return clamp(vec2(dot(cross(d, e2), n), dot(cross(e1, d), n)) / nn, 0.0, 1.0);
}

// The vertex normals interpolated at q (the file's coordinates), in the GPU's through frame f,
// on the side of the faced normal n; n itself where they cancel.
vec3 mesh_shading_normal(Primitive p, vec2 uv, vec3 q, ObjectFrame f, vec3 n) {
    MeshTriangle tr = mesh_hit_triangle(p, uv);
    vec2 b = mesh_barycentric(tr, q);
    vec3 s = (1.0 - b.x - b.y) * tr.n0.xyz + b.x * tr.n1.xyz + b.y * tr.n2.xyz;
    if (!(dot(s, s) > 0.0)) return n;
    s = unit_vector(world_gradient(f, s));
    return dot(s, n) < 0.0 ? -s : s;
}

// Texture (u, v): the file's, interpolated at the hit (point: the file's coordinates).
vec2 mesh_texture_uv(Primitive p, Hit hit, vec3 point) {
    MeshTriangle tr = mesh_hit_triangle(p, hit.uv);
    vec2 b = mesh_barycentric(tr, point);
    float b0 = 1.0 - b.x - b.y;
    return vec2(b0 * tr.v0.w + b.x * tr.v1.w + b.y * tr.v2.w, b0 * tr.n0.w + b.x * tr.n1.w + b.y * tr.n2.w);
}
