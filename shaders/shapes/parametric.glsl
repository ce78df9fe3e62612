// Ray/parametric surface S(u, v) = (x(u,v), y(u,v), z(u,v)) over one cell of its domain, by
// Newton's method from several seeds. Twin of host/cpu/shapes/parametric.cpp, which finds the
// same roots by certified interval Newton in double precision.
//
// The host subdivided the domain into cells whose boxes (interval arithmetic, so guaranteed)
// are in the BVH; a ray reaching a cell solves the two plane equations of the ray,
// n1.(S(u,v) - o) = 0 and n2.(S(u,v) - o) = 0, by Newton from where the ray crosses the cell's
// corner triangles (else from the cell's centre), and keeps a converged root inside the cell.

#include "surface_functions.glsl"

const int NEWTON_STEPS = 12;

// S and its partials in world space.
void surface_world(uint surface, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {
    vec3 p, pu, pv;
    surface_eval(surface, uv, p, pu, pv);
    SurfaceInfo s = surface_at(surface);
    mat3 m = transpose(mat3(s.row0.xyz, s.row1.xyz, s.row2.xyz));
    P = m * p + vec3(s.row0.w, s.row1.w, s.row2.w);
    Pu = m * pu;
    Pv = m * pv;
}

// Where the ray meets the plane of the triangle (a, b, c), as barycentric (b, c) weights; the
// point may lie outside the triangle (weights < 0 or sum > 1), which still makes a fair seed.
vec2 triangle_weights(vec3 a, vec3 b, vec3 c, vec3 o, vec3 d, out bool parallel) {
    vec3 e1 = b - a, e2 = c - a;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    parallel = abs(det) < 1e-20;
    float inv = parallel ? 0.0 : 1.0 / det;
    vec3 s = o - a;
    vec3 q = cross(s, e1);
    return vec2(dot(s, p), dot(d, q)) * inv;
}

// The cell-local (u, v) where the ray crosses the two triangles of the cell's corners,
// clamped to the cell: the seed for Newton.
vec2 corner_seed(ParametricCell c, vec3 o, vec3 d) {
    bool parallel0, parallel1;
    vec2 w0 = triangle_weights(c.p00.xyz, c.p10.xyz, c.p01.xyz, o, d, parallel0);  // lower-left triangle
    vec2 w1 = triangle_weights(c.p11.xyz, c.p01.xyz, c.p10.xyz, o, d, parallel1);  // upper-right triangle
    vec2 s0 = w0, s1 = vec2(1.0) - w1;
    bool in0 = !parallel0 && w0.x + w0.y <= 1.0;
    vec2 seed = parallel0 && parallel1 ? vec2(0.5) : (in0 || parallel1 ? s0 : s1);
    if (any(isnan(seed))) seed = vec2(0.5);  // a corner where the surface is undefined
    return clamp(seed, 0.0, 1.0);
}

// Newton on the two plane equations from `local` (cell coordinates); true when it converged,
// with `local` the root.
bool newton(uint surface, vec4 cell, vec2 size, vec3 origin, vec3 n1, vec3 n2, inout vec2 local) {
    for (int k = 0; k < NEWTON_STEPS; ++k) {
        vec3 P, Pu, Pv;
        surface_world(surface, vec2(cell.x, cell.z) + local * size, P, Pu, Pv);
        vec3 r = P - origin;
        vec2 f = vec2(dot(n1, r), dot(n2, r));
        // Jacobian in the cell's local parameters (scaled by the cell size: better conditioned).
        mat2 j = mat2(dot(n1, Pu) * size.x, dot(n2, Pu) * size.x, dot(n1, Pv) * size.y, dot(n2, Pv) * size.y);
        float det = determinant(j);
        if (abs(det) < 1e-30) return false;
        vec2 step = inverse(j) * f;
        local -= step;
        if (any(lessThan(local, vec2(-0.5))) || any(greaterThan(local, vec2(1.5)))) return false;  // wandered off
        // Quadratic convergence: after a step this small the error is ~1e-8, below float's noise
        // in the residual, which smaller steps would chase.
        if (abs(step.x) + abs(step.y) < 1e-4) return true;
    }
    return false;
}

bool parametric_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit) {
    // The cell's own proved box first (p0, p1): a BVH leaf holds several cells, and a slab test
    // costs far less than Newton's method.
    if (box_entry(prim.p0.xyz, prim.p1.xyz, ray.origin, safe_inverse(ray.dir), t_max) == INFINITY) return false;
    ParametricCell c = cell_at(prim.data);
    uint surface = uint(c.p00.w);
    vec4 cell = c.domain;  // (u0, u1, v0, v1)
    vec2 size = vec2(cell.y - cell.x, cell.w - cell.z);
    vec3 d = ray.dir;
    // Re-origin at the point of the ray nearest the cell's centre: the residuals are then
    // differences of nearby numbers, not of the distance to the camera.
    vec3 centre = 0.25 * (c.p00.xyz + c.p10.xyz + c.p01.xyz + c.p11.xyz);
    float t_shift = dot(centre - ray.origin, d);
    vec3 origin = ray.origin + t_shift * d;
    vec3 a = abs(d.x) <= abs(d.y) && abs(d.x) <= abs(d.z) ? vec3(1.0, 0.0, 0.0)
           : (abs(d.y) <= abs(d.z) ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    vec3 n1 = normalize(cross(d, a));
    vec3 n2 = cross(d, n1);
    // Seeds: where the ray crosses the corners' triangles, then the cell's centre (a ray can
    // miss the corner quad and still hit the surface where it bulges out of it).
    vec2 local = corner_seed(c, origin, d);
    bool converged = newton(surface, cell, size, origin, n1, n2, local);
    if (!converged) {
        local = vec2(0.5);
        converged = newton(surface, cell, size, origin, n1, n2, local);
    }
    // Closed cell, widened a little: neighbours overlap, so no ray falls between cells.
    bool inside = all(greaterThanEqual(local, vec2(-1e-4))) && all(lessThanEqual(local, vec2(1.0 + 1e-4)));
    if (!converged || !inside) return false;
    vec3 P, Pu, Pv;
    vec2 uv = vec2(cell.x, cell.z) + clamp(local, 0.0, 1.0) * size;
    surface_world(surface, uv, P, Pu, Pv);
    float t = t_shift + dot(d, P - origin);
    if (t <= t_min || t >= t_max) return false;
    t_hit = t;
    uv_hit = uv;
    return true;
}

// Unit normal from the exact partials; at poles and collapsed edges (S_u x S_v = 0) the limit
// normal is taken a little toward the inside of the surface's domain.
vec3 parametric_normal(Primitive prim, vec2 uv) {
    uint surface = uint(cell_at(prim.data).p00.w);
    vec3 P, Pu, Pv;
    surface_world(surface, uv, P, Pu, Pv);
    vec3 n = cross(Pu, Pv);
    float scale = dot(Pu, Pu) + dot(Pv, Pv);
    if (dot(n, n) <= 1e-12 * scale * scale) {
        vec4 dom = surface_at(surface).domain;
        vec2 centre = vec2(0.5 * (dom.x + dom.y), 0.5 * (dom.z + dom.w));
        surface_world(surface, mix(uv, centre, 1e-3), P, Pu, Pv);
        n = cross(Pu, Pv);
    }
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

// Texture (u, v): the hit's parameters, the surface's domain mapped to [0, 1] x [0, 1].
vec2 parametric_texture_uv(Primitive prim, vec2 uv) {
    vec4 dom = surface_at(uint(cell_at(prim.data).p00.w)).domain;
    return (uv - dom.xz) / (dom.yw - dom.xz);
}
