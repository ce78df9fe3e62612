// Ray/triangle, one triangle of a mesh: the watertight test of Woop, Benthin and Wald (JCGT
// 2013). Twin of host/cpu/shapes/mesh.cpp. p0, p1, p2 = (vertex k, its texture v) in the GPU's
// coordinates; data = its MeshCorners row (normals and texture u), numbered along the mesh, so
// that of two triangles hit at their shared edge the same one wins whatever the BVH's order.
// Every triangle of a mesh gets its vertices from the same floats (the packer carries each
// vertex once), so the edge functions of a shared edge are the same numbers negated: a ray
// through the edge is inside one triangle or both (zero counts as inside), never neither.
bool mesh_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec3 ad = abs(ray.dir);
    int kz = ad.x >= ad.y && ad.x >= ad.z ? 0 : (ad.y >= ad.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (ray.dir[kz] < 0.0) {  // keeps the winding
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    float sx = ray.dir[kx] / ray.dir[kz], sy = ray.dir[ky] / ray.dir[kz], sz = 1.0 / ray.dir[kz];
    vec3 a = p.p0.xyz - ray.origin, b = p.p1.xyz - ray.origin, c = p.p2.xyz - ray.origin;
    float ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    float bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    float cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    // The same products in the same order for a shared edge, whichever triangle asks (no fused
    // multiply-add may change one side's rounding: `precise`).
    precise float u = cx * by - cy * bx;
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    float det = u + v + w;
    if (det == 0.0) return false;  // edge-on
    float t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
    if (!(t > t_min && t < t_max)) return false;
    t_hit = t;
    uv = vec2(v, w) / det;  // barycentric weights of vertices 1 and 2
    return true;
}

// The hit's error (Hit.error): t comes from the vertices relative to the origin, each rounded a
// few times in the shear and the edge functions, as a plane's from its point (plane.glsl), so
// 32 roundings of |o| + the largest vertex + t bound the hit's distance from the triangle's plane.
vec3 mesh_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    float reach = max(max_abs(p.p0.xyz), max(max_abs(p.p1.xyz), max_abs(p.p2.xyz)));
    error = rounding_bound(32.0, max_abs(ray.origin) + reach + t);
    vec3 e1 = p.p1.xyz - p.p0.xyz, e2 = p.p2.xyz - p.p0.xyz;
    float s = unit_scale(max(max_abs(e1), max_abs(e2)));  // the cross product neither overflows nor vanishes
    return unit_vector(cross(s * e1, s * e2));
}

// The vertex normals interpolated at the hit, on the side of the faced normal n; n itself where
// the mesh is flat (zero normals) or they cancel.
vec3 mesh_shading_normal(Primitive p, vec2 b, vec3 n) {
    MeshCorners c = mesh_corners_at(p.data);
    vec3 s = (1.0 - b.x - b.y) * c.n0.xyz + b.x * c.n1.xyz + b.y * c.n2.xyz;
    if (!(dot(s, s) > 0.0)) return n;
    s = normalize(s);
    return dot(s, n) < 0.0 ? -s : s;
}

// Texture (u, v): the file's, interpolated (a mesh without them has each vertex's barycentric
// corner, (0, 0), (1, 0), (0, 1), so that it gets the hit's barycentric weights).
vec2 mesh_texture_uv(Primitive p, Hit hit, vec3 point) {
    MeshCorners c = mesh_corners_at(p.data);
    vec2 b = hit.uv;
    float b0 = 1.0 - b.x - b.y;
    return vec2(b0 * c.n0.w + b.x * c.n1.w + b.y * c.n2.w, b0 * p.p0.w + b.x * p.p1.w + b.y * p.p2.w);
}
