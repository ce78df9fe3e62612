// Ray / parametric surface S(u, v) = (x(u,v), y(u,v), z(u,v)) over one cell of its domain: a
// certified search in float, the twin of host/cpu/shapes/parametric.cpp, which runs the same
// search in double precision.
//
// The host cut the domain into cells whose proved boxes are in the BVH. A ray reaching a cell is
// carried into the surface's own coordinates (SurfaceInfo's inverse map; t is kept) from a point
// of it near the cell, so that residuals are differences of nearby numbers. A hit is a root of
// F(u, v) = (n1 . (S - o), n2 . (S - o)) for two planes through the ray, and its t follows from S.
// The cell is examined as a quadtree of parameter boxes, depth first; for each box X, from S and
// its partials at a point c of it and [J], an enclosure of the Jacobian over X:
//   * exclusion: F's enclosure over X (the mean-value form F(c) + [J] (X - c)) keeps away from 0,
//     or every t it allows is beyond the nearest root found so far; or Krawczyk's operator
//     K(X) = c - Y F(c) + (I - Y [J]) (X - c) misses X;
//   * q = |I - Y [J]| < 1 (in the norm weighted by X) proves that F is one-to-one on X, so X holds
//     at most one root, which Newton's method from c, kept in X, finds; each of its steps also
//     narrows where that root can be, so a ray that misses is dropped after a step or two;
//   * otherwise X is split in four, down to PARAMETRIC_LEVELS levels below the cell. A box at the
//     last level that is still undecided (the ray tangent to the surface there, or a pole where
//     S_u x S_v vanishes) is settled by Newton's method from its centre, unproved, its steps
//     allowed half the box's size beyond it (a root near an edge between two such boxes is
//     reached from either).
// [J] comes from bounds the host proved per cell (ParametricCell): the partials' bounds over the
// whole cell, whose centre's S is stored too, so that most cells are decided without evaluating S;
// over a part of the cell, S's partials at its centre and the second partials' bounds.
// So of the two roots of a ray that grazes a curved surface, close together in one cell, the
// nearer is found, and no root is lost because a seed led Newton's method astray.
//
// Each loop iteration makes at most one call of surface_eval (a box's centre, or one Newton
// step): lavapipe inlines every call site into both call sites of trace_scene, so each extra
// call would cost compile time and registers.

#if LANCER_PARAMETRIC_SURFACES

const int PARAMETRIC_LEVELS = 4;          // boxes down to 1/16 of a cell's side
const int PARAMETRIC_ITERATIONS = 128;    // boxes and Newton steps per ray and cell; beyond, the nearest root so far
const int PARAMETRIC_NEWTON_STEPS = 10;   // per root
const float PARAMETRIC_INFLATION = 0.01;  // of a box's width on each side: a root on an edge lies inside a box
const float PARAMETRIC_EDGE = 1e-4;       // of a cell's width: how far outside its cell a root may lie (rounding)
const float PARAMETRIC_CONVERGED = 1e-4;  // Newton's step, in cell widths: quadratic convergence leaves ~1e-8,
                                          // below float's noise in the residual, which smaller steps would chase

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

// The box of the quadtree node `code` (two bits per level, the deepest level lowest; bit 0
// halves u, bit 1 halves v) at `level` below the cell (u0, u1, v0, v1).
vec4 parametric_box(vec4 cell, int level, uint code) {
    uint ui = (code & 1u) | ((code >> 1) & 2u) | ((code >> 2) & 4u) | ((code >> 3) & 8u);
    uint vi = ((code >> 1) & 1u) | ((code >> 2) & 2u) | ((code >> 3) & 4u) | ((code >> 4) & 8u);
    vec2 size = vec2(cell.y - cell.x, cell.w - cell.z) / float(1u << uint(level));
    vec2 lo = vec2(cell.x, cell.z) + vec2(float(ui), float(vi)) * size;
    return vec4(lo.x, lo.x + size.x, lo.y, lo.y + size.y);
}

mat2 parametric_abs(mat2 m) { return mat2(abs(m[0]), abs(m[1])); }

// With any_root, the first root found in (t_min, t_max) ends the search (a shadow ray's).
bool parametric_search(Primitive prim, Ray ray, float t_min, float t_max, bool any_root, out float t_hit, out vec2 uv_hit, inout float error) {
    // The cell's own proved box first (p0, p1): a BVH leaf holds several cells, and a slab test
    // costs far less than the search.
    if (box_entry(prim.p0.xyz, prim.p1.xyz, ray.origin, safe_inverse(ray.dir), t_max) == INFINITY) return false;
    ParametricCell c = cell_at(prim.data);
    uint surface = uint(c.su_lo.w);
    SurfaceInfo info = surface_at(surface);
    vec4 cell = c.domain;  // (u0, u1, v0, v1)
    vec2 cell_size = vec2(cell.y - cell.x, cell.w - cell.z);

    // The ray in the surface's coordinates, from its point nearest the cell's box centre; t is
    // counted from there.
    float t_shift = dot(0.5 * (prim.p0.xyz + prim.p1.xyz) - ray.origin, ray.dir);
    vec3 world_origin = ray.origin + t_shift * ray.dir;
    mat3 rows = mat3(info.inverse0.xyz, info.inverse1.xyz, info.inverse2.xyz);  // columns hold the map's rows
    vec3 o = world_origin * rows + vec3(info.inverse0.w, info.inverse1.w, info.inverse2.w);
    vec3 d = ray.dir * rows;
    float dd = dot(d, d);
    vec3 axis = abs(d.x) <= abs(d.y) && abs(d.x) <= abs(d.z) ? vec3(1.0, 0.0, 0.0)
              : (abs(d.y) <= abs(d.z) ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    vec3 n1 = normalize(cross(d, axis));
    vec3 n2 = normalize(cross(d, n1));
    float t_low = t_min - t_shift;
    float best = t_max - t_shift;  // the nearest root so far, or the end of the ray
    vec2 best_uv = vec2(0.0);
    bool found = false;

    int level = 0;
    uint code = 0u;
    bool newton = false;  // refining a root from x inside the current box, rather than examining it
    vec2 x = vec2(0.0);
    int steps = 0;
    float reach = 1.0;  // a root in the box is within reach (in the norm weighted by the box) of x
    bool unproved = false;        // Newton's method runs in a last-level box that may hold two roots
    bool deflated = false;        // ... looking for the second, away from the first
    vec2 first_root = vec2(0.0);  // the first root found there
    mat2 Jmid = mat2(0.0), Jrad = mat2(0.0);  // [J] over the current box, centre and radius
    vec2 t_slope = vec2(0.0);                 // bounds of |dt/du| and |dt/dv| over it
    for (int iteration = 0; iteration < PARAMETRIC_ITERATIONS; ++iteration) {
        vec4 box = parametric_box(cell, level, code);
        // The box widened, but not beyond the surface's domain (as the host's bounds).
        vec2 half_width = (0.5 + PARAMETRIC_INFLATION) * vec2(box.y - box.x, box.w - box.z);
        vec2 centre = 0.5 * vec2(box.x + box.y, box.z + box.w);
        vec2 low = max(centre - half_width, info.domain.xz), high = min(centre + half_width, info.domain.yw);
        centre = 0.5 * (low + high);
        half_width = 0.5 * (high - low);
        bool examine = !newton;
        if (examine) {
            // From the box's centre; for the whole cell from the cell's centre, where the host
            // stored S (the widened box may hold it off centre at the domain's edge).
            x = level == 0 ? 0.5 * vec2(cell.x + cell.y, cell.z + cell.w) : centre;
            steps = 0;
        }
        vec2 extent = max(x - low, high - x);  // how far the box reaches from x
        // S at x. The whole cell's centre needs no evaluation: S is stored there, and the
        // midpoints of the partials' bounds stand in for the partials (Krawczyk's test holds for
        // any Y, here mid[J]^-1).
        vec3 P, Pu, Pv;
        bool stored = examine && level == 0 && c.centre.w != 0.0;
        if (stored) {
            P = c.centre.xyz;
            Pu = 0.5 * (c.su_lo.xyz + c.su_hi.xyz);
            Pv = 0.5 * (c.sv_lo.xyz + c.sv_hi.xyz);
        } else {
            surface_eval(surface, x, P, Pu, Pv);
        }
        if (examine) {
            // [J] over the box: for the whole cell from the host's bounds of the partials; for a
            // part of it, Taylor: S's partials at its centre, plus the second partials' bounds
            // times its half widths.
            vec3 Uc = Pu, Vc = Pv, Ur, Vr;
            if (level == 0) {
                Ur = 0.5 * (c.su_hi.xyz - c.su_lo.xyz);
                Vr = 0.5 * (c.sv_hi.xyz - c.sv_lo.xyz);
            } else {
                ParametricCell curvature = cell_at(prim.data);
                // (plus a hair for float's rounding of the partials themselves)
                Ur = curvature.suu.xyz * half_width.x + curvature.suv.xyz * half_width.y + 1e-5 * length(Pu);
                Vr = curvature.suv.xyz * half_width.x + curvature.svv.xyz * half_width.y + 1e-5 * length(Pv);
            }
            Jmid = mat2(dot(n1, Uc), dot(n2, Uc), dot(n1, Vc), dot(n2, Vc));  // columns: d/du, d/dv
            Jrad = mat2(dot(abs(n1), Ur), dot(abs(n2), Ur), dot(abs(n1), Vr), dot(abs(n2), Vr));
            t_slope = vec2(abs(dot(d, Uc)) + dot(abs(d), Ur), abs(dot(d, Vc)) + dot(abs(d), Vr));
        }
        vec3 r = P - o;
        vec2 F = vec2(dot(n1, r), dot(n2, r));
        mat2 J = mat2(dot(n1, Pu), dot(n2, Pu), dot(n1, Pv), dot(n2, Pv));
        float det = determinant(J);
        bool invertible = det * det > 1e-24 * dot(Pu, Pu) * dot(Pv, Pv) && !isinf(det);
        mat2 Y = invertible ? inverse(J) : mat2(0.0);
        vec2 step = Y * F;  // Newton's step
        // F(x) as computed strays from the exact F(x) by rounding and by float's evaluation of S.
        float slack = 4e-7 * (dot(abs(P), vec3(1.0)) + dot(abs(o), vec3(1.0))) + c.su_hi.w;
        // (|I - Y mid[J]| + |Y| rad[J]) times the box's half widths: for G(x) = x - Y F(x) and a
        // root z in the box, |G(x) - z| <= spread |x - z| coordinate by coordinate, |x - z| in the
        // norm weighted by the box (the mean value theorem); q = max(spread / half_width).
        vec2 spread = (parametric_abs(mat2(1.0) - Y * Jmid) + parametric_abs(Y) * Jrad) * half_width;
        spread = spread * 1.001 + parametric_abs(Y) * vec2(slack);
        bool bounded = invertible && !any(isnan(spread)) && !any(isinf(spread));
        // So a root in the box lies within reach * spread of x - step. From where the box is
        // examined, reach is how far the box extends (1 from its centre: Krawczyk's exclusion);
        // each step, kept in the box, multiplies it by q.
        if (examine) reach = max(extent.x / half_width.x, extent.y / half_width.y);
        vec2 outside = max(abs(x - step - centre) - half_width, vec2(0.0));
        bool no_root = bounded && !deflated && any(greaterThan(outside, reach * spread));
        reach *= max(spread.x / half_width.x, spread.y / half_width.y);
        if (examine) {
            // The mean-value form: F and t over the box from their values at x and [J].
            vec2 F_spread = (parametric_abs(Jmid) + Jrad) * extent + vec2(slack);
            float tc = dot(d, r) / dd, tr = (dot(t_slope, extent) + slack * length(d)) / dd;
            no_root = no_root || any(greaterThan(abs(F), F_spread)) || tc - tr >= best || tc + tr <= t_low;
            // q < 1: F is one-to-one on the box (F(a) - F(b) = J (a - b) for a J in [J], and Y J is
            // invertible), so the box holds at most one root, and Newton's method, kept in the
            // box, finds it if it is there. Otherwise the box is split, down to the last level,
            // where Newton's method settles it unproved.
            bool proved = bounded && all(lessThan(spread, 0.9 * half_width));
            if (!no_root && !proved && level < PARAMETRIC_LEVELS) {
                level += 1;
                code *= 4u;
                continue;
            }
            unproved = !proved;
            deflated = false;
        }
        if (deflated) {
            // Newton's method on F / |x - first_root|^2 + F, whose roots are F's but the first:
            // the same step, scaled (Farrell, Birkisson and Funke's deflation).
            vec2 w = (x - first_root) / half_width;
            float w2 = max(dot(w, w), 1e-12);
            float m = 1.0 / w2 + 1.0;
            vec2 gradient = -2.0 * w / (half_width * w2 * w2);
            step /= 1.0 + dot(gradient, step) / m;
        }
        bool done_with_box = no_root || !invertible;
        if (!done_with_box) {
            vec2 evaluated = x;
            // Kept in the box; in an unproved one, where J is nearly singular and a root near the
            // box's edge is not reached by steps stopped at it, in the box widened by half its size.
            vec2 reach_low = low, reach_high = high;
            if (unproved) {
                reach_low = max(low - 0.5 * (high - low), info.domain.xz);
                reach_high = min(high + 0.5 * (high - low), info.domain.yw);
            }
            x = clamp(x - step, reach_low, reach_high);
            steps += 1;
            vec2 moved = abs(step) / cell_size;
            // Converged: the step is small, or the residual is at float's noise. (Where the ray is
            // nearly tangent to the surface, J is nearly singular: near a double root Newton's
            // method slows to linear, and near a simple one its steps, J^-1 times F's rounding,
            // stay larger than the step criterion while F itself can shrink no further.)
            bool at_noise = length(F) <= slack;
            bool converged = !stored && (moved.x + moved.y < PARAMETRIC_CONVERGED || at_noise);
            if (at_noise) x = evaluated;  // the root is where S was evaluated
            if (converged) {
                // The root, and the point there to first order (the step is ~1e-4 of a cell).
                vec3 root = at_noise ? P : P - Pu * step.x - Pv * step.y;
                float t = dot(d, root - o) / dd;
                vec2 local = (x - vec2(cell.x, cell.z)) / cell_size;
                bool in_cell = all(greaterThanEqual(local, vec2(-PARAMETRIC_EDGE))) &&
                               all(lessThanEqual(local, vec2(1.0 + PARAMETRIC_EDGE)));
                if (in_cell && t > t_low && t < best) {
                    best = t;
                    best_uv = vec2(cell.x, cell.z) + clamp(local, 0.0, 1.0) * cell_size;
                    found = true;
                }
            }
            if (found && any_root) break;
            // In a box that may hold two roots (a ray tangent to the surface there, within the
            // last level's size), the first root found may be the farther: Newton's method runs
            // again, deflated, from across the box, for the other; the nearer is kept.
            if (converged && unproved && !deflated) {
                first_root = x;
                deflated = true;
                x = clamp(2.0 * centre - x, low, high);
                steps = 0;
                converged = false;
            }
            // A step that the box's edge stopped entirely (x did not move) will be stopped again:
            // the root it heads for lies outside, and the box is left.
            bool stuck = !converged && all(equal(x, evaluated));
            done_with_box = converged || stuck || any(isnan(x)) || steps >= PARAMETRIC_NEWTON_STEPS;
        }
        newton = !done_with_box;
        if (done_with_box) {
            // The next box in depth-first order: up past the last children, then to the next sibling.
            [[unroll]] for (int k = 0; k < PARAMETRIC_LEVELS; ++k) {
                if (level > 0 && (code & 3u) == 3u) {
                    code >>= 2;
                    level -= 1;
                }
            }
            if (level == 0) break;
            code += 1u;
        }
    }
    if (!found) return false;
    t_hit = t_shift + best;
    uv_hit = best_uv;
    return true;
}

// A cell's nearest root, or for a shadow ray (element_tree.glsl's shadow_ray_any_hit) any root.
bool parametric_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit, inout float error) {
    return parametric_search(prim, ray, t_min, t_max, shadow_ray_any_hit, t_hit, uv_hit, error);
}

// The error bound of a parametric surface's hit (Hit.error): how far the hit point
// ray.origin + t * ray.dir, computed in float, can be from the surface. Secondary rays start
// twice this far off it (common.glsl, spawn_offset), so it must not be too small (a ray leaving
// the surface would find it again at t ~ 0: acne) nor much larger than needed (contact shadows,
// thin features).
//
// A conservative bound that holds for any Newton-type intersector in parametric.glsl: the root
// is accepted once Newton's step is below 1e-4 of the cell (in its own parameters, so in space
// below 1e-4 of the cell's extent, which its proved box holds), and quadratic convergence leaves
// far less than the last step; the clamp of a root just outside the cell into it moves the point
// by as much. S(u, v) itself is evaluated in float at coordinates up to the cell box's magnitude
// (64 roundings of it cover the shipped expressions), and the hit point has its own rounding.
// An intersector that knows more (its residual, its last step) can return a tighter bound.
float parametric_hit_error(Primitive prim, Ray ray, float t, vec2 uv) {
    vec3 lo = prim.p0.xyz, hi = prim.p1.xyz;  // the cell's proved box
    return 1e-4 * length(hi - lo) + rounding_bound(64.0, max(max_abs(lo), max_abs(hi))) + hit_point_rounding(ray.origin, t);
}

// Unit normal from the exact partials; at poles and collapsed edges (S_u x S_v = 0) the limit
// normal is taken a little toward the inside of the surface's domain.
vec3 parametric_hit_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    error = parametric_hit_error(prim, ray, t, uv);
    uint surface = uint(cell_at(prim.data).su_lo.w);
    vec3 P, Pu, Pv;
    surface_world(surface, uv, P, Pu, Pv);
    // The partials scaled together by a power of two first (unit_scale): a sphere of radius
    // 1e10 would otherwise square them past float's range.
    float s = unit_scale(max(max_abs(Pu), max_abs(Pv)));
    vec3 u = s * Pu, v = s * Pv;
    vec3 n = cross(u, v);
    float scale = dot(u, u) + dot(v, v);
    if (dot(n, n) <= 1e-12 * scale * scale) {
        vec4 dom = surface_at(surface).domain;
        vec2 centre = vec2(0.5 * (dom.x + dom.y), 0.5 * (dom.z + dom.w));
        surface_world(surface, mix(uv, centre, 1e-3), P, Pu, Pv);
        s = unit_scale(max(max_abs(Pu), max_abs(Pv)));
        n = cross(s * Pu, s * Pv);
    }
    float len = length(n);
    return len > 0.0 && !isinf(len) ? n / len : vec3(0.0, 0.0, 1.0);
}

// Texture (u, v): the hit's parameters, the surface's domain mapped to [0, 1] x [0, 1].
vec2 parametric_texture_uv(Primitive prim, Hit hit, vec3 p) {
    vec4 dom = surface_at(uint(cell_at(prim.data).su_lo.w)).domain;
    return (hit.uv - dom.xz) / (dom.yw - dom.xz);
}

#else
// No parametric surface in the scene: the family's functions exist for the shape table's
// dispatch, which SCENE_HAS_PARAMETRIC (false) leaves out.
bool parametric_search(Primitive prim, Ray ray, float t_min, float t_max, bool any_root, out float t_hit, out vec2 uv_hit, inout float error) {
    return false;
}
bool parametric_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit, inout float error) {
    return false;
}
vec3 parametric_hit_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) { return vec3(0.0, 0.0, 1.0); }
vec2 parametric_texture_uv(Primitive prim, Hit hit, vec3 p) { return hit.uv; }
#endif
