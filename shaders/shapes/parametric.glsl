// Ray/parametric surface S(u, v) = (x(u,v), y(u,v), z(u,v)) over one cell of its domain, by
// Newton's method from several seeds. Twin of host/cpu/shapes/parametric.cpp, which finds the
// same roots by certified interval Newton in double precision.
//
// The host subdivided the domain into cells whose boxes (interval arithmetic, so guaranteed)
// are in the BVH; a ray reaching a cell solves the two plane equations of the ray,
// n1.(S(u,v) - o) = 0 and n2.(S(u,v) - o) = 0, from the cell's centre and the centres of its
// quadrants, and keeps the nearest converged root inside the cell.

layout(std430, set = 0, binding = BINDING_SURFACES) readonly buffer SurfaceBlock { SurfaceInfo surfaces[]; };

#include "surface_functions.glsl"

const int NEWTON_STEPS = 12;

// S and its partials in world space.
void surface_world(uint surface, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {
    vec3 p, pu, pv;
    surface_eval(surface, uv, p, pu, pv);
    SurfaceInfo s = surfaces[surface];
    mat3 m = transpose(mat3(s.row0.xyz, s.row1.xyz, s.row2.xyz));
    P = m * p + vec3(s.row0.w, s.row1.w, s.row2.w);
    Pu = m * pu;
    Pv = m * pv;
}

bool parametric_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit) {
    vec4 cell = prim.p0;  // (u0, u1, v0, v1)
    vec2 size = vec2(cell.y - cell.x, cell.w - cell.z);
    vec3 d = ray.dir;
    // Re-origin at the point of the ray nearest the cell (p1 = the centre of its box): the
    // residuals are then differences of nearby numbers, not of the distance to the camera.
    float t_shift = dot(prim.p1.xyz - ray.origin, d);
    vec3 origin = ray.origin + t_shift * d;
    vec3 a = abs(d.x) <= abs(d.y) && abs(d.x) <= abs(d.z) ? vec3(1.0, 0.0, 0.0)
           : (abs(d.y) <= abs(d.z) ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    vec3 n1 = normalize(cross(d, a));
    vec3 n2 = cross(d, n1);
    float best = t_max;
    bool found = false;
    // Seeds: the cell's centre, then the centres of its quadrants.
    for (int s = 0; s < 5; ++s) {
        vec2 local = s == 0 ? vec2(0.5) : vec2(0.25 + 0.5 * float((s - 1) & 1), 0.25 + 0.5 * float((s - 1) >> 1));
        int state = 0;  // 0: iterating, 1: converged, 2: failed
        for (int k = 0; k < NEWTON_STEPS; ++k) {
            if (state == 0) {
                vec3 P, Pu, Pv;
                surface_world(prim.data, vec2(cell.x, cell.z) + local * size, P, Pu, Pv);
                vec3 r = P - origin;
                vec2 f = vec2(dot(n1, r), dot(n2, r));
                // Jacobian in the cell's local parameters (scaled by the cell size: better conditioned).
                mat2 j = mat2(dot(n1, Pu) * size.x, dot(n2, Pu) * size.x, dot(n1, Pv) * size.y, dot(n2, Pv) * size.y);
                float det = determinant(j);
                if (abs(det) < 1e-30) {
                    state = 2;
                } else {
                    vec2 step = inverse(j) * f;
                    local -= step;
                    if (any(lessThan(local, vec2(-0.5))) || any(greaterThan(local, vec2(1.5)))) {
                        state = 2;  // wandered off
                    } else if (abs(step.x) + abs(step.y) < 1e-4) {
                        // Quadratic convergence: after a step this small the error is ~1e-8,
                        // below float's noise in the residual, which smaller steps would chase.
                        state = 1;
                    }
                }
            }
        }
        // Closed cell, widened a little: neighbours overlap, so no ray falls between cells.
        bool inside = all(greaterThanEqual(local, vec2(-1e-4))) && all(lessThanEqual(local, vec2(1.0 + 1e-4)));
        if (state == 1 && inside) {
            vec3 P, Pu, Pv;
            vec2 uv = vec2(cell.x, cell.z) + clamp(local, 0.0, 1.0) * size;
            surface_world(prim.data, uv, P, Pu, Pv);
            float t = t_shift + dot(d, P - origin);
            if (t > t_min && t < best) {
                best = t;
                uv_hit = uv;
                found = true;
            }
        }
    }
    if (!found) return false;
    t_hit = best;
    return true;
}

// Unit normal from the exact partials; at poles and collapsed edges (S_u x S_v = 0) the limit
// normal is taken a little toward the inside of the surface's domain.
vec3 parametric_normal(Primitive prim, vec2 uv) {
    vec3 P, Pu, Pv;
    surface_world(prim.data, uv, P, Pu, Pv);
    vec3 n = cross(Pu, Pv);
    float scale = dot(Pu, Pu) + dot(Pv, Pv);
    if (dot(n, n) <= 1e-12 * scale * scale) {
        vec4 dom = surfaces[prim.data].domain;
        vec2 centre = vec2(0.5 * (dom.x + dom.y), 0.5 * (dom.z + dom.w));
        surface_world(prim.data, mix(uv, centre, 1e-3), P, Pu, Pv);
        n = cross(Pu, Pv);
    }
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}
