// Ray/blob (POV-Ray's blob), exactly, in float. Twin of host/cpu/shapes/blob.cpp (which isolates
// the roots by Bernstein subdivision in double). p.p0.x = the threshold; p.p1.xyz, p.p2.xyz the
// box of the components of positive strength; p.data the blob's MeshInfo: a tree (MESH_NODES)
// over its components (BLOB_ELEMENTS, in leaf order).
//
// A component's field is s (1 - d^2 / r^2)^2 within r of its segment from a to b (a sphere where
// a = b), d the distance to the segment. Along the ray, d^2 is a quadratic in t on each of the
// component's pieces (the ball about a, the cylinder between the end planes, the ball about b),
// so between the points where the ray enters or leaves a component or crosses an end plane, the
// field's sum is one quartic in t. Each such stretch is re-based at its middle m (s = t - m in
// [-w, w]) and its quartic's first root found by polynomial.glsl's quartic_first_root. A ray
// within rounding of touching the surface may be called a hit or a miss either way.
//
// The components a ray meets are gathered from the tree in windows of at most BLOB_MAX_OVERLAP,
// nearest entry first: a window is complete up to the first entry it had to leave out (`cut`),
// and the next starts there. Its reader (host/scene/parse_blob.cpp) refuses a blob where more
// than BLOB_MAX_OVERLAP components could hold one point, so that each window reaches past the
// last's start.
const int BLOB_WINDOW = int(BLOB_MAX_OVERLAP);

// The most a component of positive strength gives at the least q = d^2 / r^2 the line reaches.
float blob_peak(BlobElement e, float q_least) {
    float most = max(1.0 - q_least, 0.0);
    return max(e.b.w, 0.0) * most * most;
}

// The ray's stretch (t0, t1) inside component e's support (the capsule of radius r about its
// segment: convex, so the union of its pieces' stretches), and where it crosses the end planes
// (ta at a, tb at b; INFINITY for a sphere or a ray along the planes), and the most its field
// is anywhere along the line (`peak`). False where it misses.
bool blob_support(BlobElement e, Ray ray, out float t0, out float t1, out float ta, out float tb, out float peak) {
    float r2 = e.a.w * e.a.w;
    peak = 0.0;
    vec3 f = ray.origin - e.a.xyz;
    t0 = INFINITY;
    t1 = -INFINITY;
    ta = INFINITY;
    tb = INFINITY;
    // The ball about a (and about b): |f + t d|^2 < r^2, from the point nearest its centre.
    float beta = dot(f, ray.dir);
    vec3 perp = f - beta * ray.dir;
    float disc = r2 - dot(perp, perp);
    if (disc >= 0.0) {
        float root = sqrt(disc);
        t0 = -beta - root;
        t1 = -beta + root;
    }
    vec3 axis = e.b.xyz - e.a.xyz;
    float length2 = dot(axis, axis);
    if (length2 == 0.0) {
        peak = blob_peak(e, dot(perp, perp) / r2);
        return t0 < t1;
    }
    vec3 g = ray.origin - e.b.xyz;
    beta = dot(g, ray.dir);
    perp = g - beta * ray.dir;
    disc = r2 - dot(perp, perp);
    if (disc >= 0.0) {
        float root = sqrt(disc);
        t0 = min(t0, -beta - root);
        t1 = max(t1, -beta + root);
    }
    // The cylinder between the end planes: the parts of f and d across the axis, from the ray's
    // point nearest a (t = near), as the balls' are from theirs: from the origin, C and B^2 would
    // be of |f|^2 and cancel to nothing in float for a ray from far off.
    float near = -dot(f, ray.dir);
    vec3 u = axis / sqrt(length2);
    vec3 fn = f + near * ray.dir;
    float fu = dot(fn, u), du = dot(ray.dir, u), len = sqrt(length2);
    vec3 fp = fn - fu * u, dp = ray.dir - du * u;
    float A = dot(dp, dp), B = dot(fp, dp), C = dot(fp, fp) - r2;
    float s0 = -INFINITY, s1 = INFINITY;  // the slab between the end planes
    if (du != 0.0) {
        ta = near - fu / du;
        tb = near + (len - fu) / du;
        s0 = min(ta, tb);
        s1 = max(ta, tb);
    } else if (fu < 0.0 || fu > len) {
        s1 = s0;  // along the planes, outside the slab
    }
    if (A > 0.0) {
        float d2 = B * B - A * C;
        if (d2 >= 0.0) {
            float q = -(B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(d2));
            float c0 = near + q / A, c1 = q != 0.0 ? near + C / q : c0;
            s0 = max(s0, min(c0, c1));
            s1 = min(s1, max(c0, c1));
        } else {
            s1 = s0;  // misses the cylinder
        }
    } else if (C >= 0.0) {
        s1 = s0;  // along the axis, outside the cylinder
    }
    if (s0 < s1) {
        t0 = min(t0, s0);
        t1 = max(t1, s1);
    }
    // The line comes no nearer the segment than the axis's line.
    peak = blob_peak(e, (A > 0.0 ? max(dot(fp, fp) - B * B / A, 0.0) : dot(fp, fp)) / r2);
    return t0 < t1;
}

// Component e's field along the ray about m, as A + B s + C s^2 = 1 - d^2 / r^2 in s = t - m,
// on the piece that holds the point at m.
vec3 blob_piece(BlobElement e, Ray ray, float m) {
    vec3 point = ray.origin + m * ray.dir;
    vec3 axis = e.b.xyz - e.a.xyz;
    vec3 rel = point - e.a.xyz, dir = ray.dir;
    float length2 = dot(axis, axis);
    if (length2 > 0.0) {
        float h = dot(rel, axis) / length2;
        if (h >= 1.0) {
            rel = point - e.b.xyz;
        } else if (h > 0.0) {
            vec3 u = axis / sqrt(length2);
            rel -= dot(rel, u) * u;
            dir -= dot(dir, u) * u;
        }
    }
    float inv_r2 = 1.0 / (e.a.w * e.a.w);
    return vec3(1.0 - dot(rel, rel) * inv_r2, -2.0 * dot(rel, dir) * inv_r2, -dot(dir, dir) * inv_r2);
}

// A window of the components the ray meets, nearest entry first (the gathered stretches).
struct BlobWindow {
    float t0[BLOB_WINDOW], t1[BLOB_WINDOW], ta[BLOB_WINDOW], tb[BLOB_WINDOW], peak[BLOB_WINDOW];
    uint element[BLOB_WINDOW];
    int count;
    float cut;  // every component entered before it and left after `from` is in the window
};

// The ray's stretch through a tree node's box, as (enter, leave); enter > leave where it misses.
vec2 blob_box_span(vec3 lo, vec3 hi, Ray ray, vec3 inv_dir) {
    vec3 a = (lo - ray.origin) * inv_dir, b = (hi - ray.origin) * inv_dir;
    vec3 near = min(a, b), far = max(a, b);
    return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

// The window being searched: one per invocation, not copied between the functions below.
BlobWindow blob_window;

// Gathers into `blob_window` the components that hold some point of the ray in (from, until), entered first.
void blob_gather(MeshInfo info, Ray ray, float from, float until) {
    blob_window.count = 0;
    blob_window.cut = until;
    vec3 inv_dir = safe_inverse(ray.dir);
    uint stack[ELEMENT_STACK_SIZE];
    int sp = 0;
    stack[sp++] = info.first_node;
    while (sp > 0) {
        MeshNode n = mesh_node_at(stack[--sp]);
        vec2 span = blob_box_span(n.lo.xyz, n.hi.xyz, ray, inv_dir);
        if (!(span.x <= span.y) || span.y <= from || span.x >= blob_window.cut) continue;
        if (n.count == 0u) {
            if (sp + 2 <= ELEMENT_STACK_SIZE) {
                stack[sp++] = n.first + 1u;
                stack[sp++] = n.first;
            }
            continue;
        }
        for (uint i = n.first; i < n.first + n.count; ++i) {
            float t0, t1, ta, tb, peak;
            if (!blob_support(blob_element_at(i), ray, t0, t1, ta, tb, peak) || t1 <= from || t0 >= blob_window.cut) continue;
            int at = blob_window.count;
            if (blob_window.count == BLOB_WINDOW) {  // full: this one stays out, or the last entered leaves
                if (t0 >= blob_window.t0[BLOB_WINDOW - 1]) {
                    blob_window.cut = t0;
                    continue;
                }
                blob_window.cut = blob_window.t0[BLOB_WINDOW - 1];
                at = BLOB_WINDOW - 1;
            } else {
                ++blob_window.count;
            }
            for (; at > 0 && blob_window.t0[at - 1] > t0; --at) {
                blob_window.t0[at] = blob_window.t0[at - 1];
                blob_window.t1[at] = blob_window.t1[at - 1];
                blob_window.ta[at] = blob_window.ta[at - 1];
                blob_window.tb[at] = blob_window.tb[at - 1];
                blob_window.peak[at] = blob_window.peak[at - 1];
                blob_window.element[at] = blob_window.element[at - 1];
            }
            blob_window.t0[at] = t0;
            blob_window.t1[at] = t1;
            blob_window.ta[at] = ta;
            blob_window.tb[at] = tb;
            blob_window.peak[at] = peak;
            blob_window.element[at] = i;
        }
    }
}

// The first root of the field's sum less the threshold in (lo, hi), a stretch with no entry,
// exit or end plane of the window's components inside it, or INFINITY.
float blob_stretch_root(Ray ray, float threshold, float lo, float hi) {
    float m = 0.5 * (lo + hi), w = 0.5 * (hi - lo);
    if (!(w > 0.0)) return INFINITY;
    float peaks = 0.0;  // first without fetching a component: their most along the whole line
    for (int i = 0; i < blob_window.count; ++i)
        if (blob_window.t0[i] < m && m < blob_window.t1[i]) peaks += blob_window.peak[i];
    if (peaks < threshold) return INFINITY;
    float k0 = -threshold, reach = 0.0;
    vec4 k = vec4(0.0);
    for (int i = 0; i < blob_window.count; ++i) {
        if (!(blob_window.t0[i] < m && m < blob_window.t1[i])) continue;
        BlobElement e = blob_element_at(blob_window.element[i]);
        vec3 q = blob_piece(e, ray, m);
        float s = e.b.w;
        k0 += s * q.x * q.x;
        k += s * vec4(2.0 * q.x * q.y, q.y * q.y + 2.0 * q.x * q.z, 2.0 * q.y * q.z, q.z * q.z);
        // The most this component gives on the stretch: at its point nearest the segment.
        float nearest = q.z < 0.0 ? clamp(-0.5 * q.y / q.z, -w, w) : 0.0;
        float most = q.x + (q.y + q.z * nearest) * nearest;
        if (s > 0.0) reach += s * most * most;
    }
    if (reach < threshold) return INFINITY;  // no point of the stretch reaches the threshold
    float s = quartic_first_root(k0, k, w, 1.2e-7 * (abs(m) + w));
    return s == INFINITY ? INFINITY : m + s;
}

bool blob_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec2 span = blob_box_span(p.p1.xyz, p.p2.xyz, ray, safe_inverse(ray.dir));
    float from = max(t_min, span.x), until = min(t_max, span.y);
    MeshInfo info = mesh_at(p.data);
    // Each window reaches past the last's start (its reader's overlap limit); a bound all the same.
    for (uint window = 0u; window <= info.element_count && from < until; ++window) {
        blob_gather(info, ray, from, until);
        float end = blob_window.cut;
        float at = from;
        for (int step = 0; step <= 4 * BLOB_WINDOW && at < end; ++step) {
            float next = end;
            for (int i = 0; i < blob_window.count; ++i) {
                if (blob_window.t0[i] > at) next = min(next, blob_window.t0[i]);
                if (blob_window.t1[i] > at) next = min(next, blob_window.t1[i]);
                if (blob_window.ta[i] > at) next = min(next, blob_window.ta[i]);
                if (blob_window.tb[i] > at) next = min(next, blob_window.tb[i]);
            }
            float t = blob_stretch_root(ray, p.p0.x, at, next);
            if (t < INFINITY) {
                t_hit = clamp(t, at, next);
                return t_hit > t_min && t_hit < t_max;
            }
            at = next;
        }
        if (end <= from) break;  // cannot happen within the overlap limit
        from = end;
    }
    return false;
}

// The field at x and its gradient, from the components whose boxes hold x.
float blob_field(MeshInfo info, vec3 x, out vec3 gradient) {
    float field = 0.0;
    gradient = vec3(0.0);
    uint stack[ELEMENT_STACK_SIZE];
    int sp = 0;
    stack[sp++] = info.first_node;
    while (sp > 0) {
        MeshNode n = mesh_node_at(stack[--sp]);
        if (any(lessThan(x, n.lo.xyz)) || any(greaterThan(x, n.hi.xyz))) continue;
        if (n.count == 0u) {
            if (sp + 2 <= ELEMENT_STACK_SIZE) {
                stack[sp++] = n.first;
                stack[sp++] = n.first + 1u;
            }
            continue;
        }
        for (uint i = n.first; i < n.first + n.count; ++i) {
            BlobElement e = blob_element_at(i);
            vec3 axis = e.b.xyz - e.a.xyz;
            float length2 = dot(axis, axis);
            float h = length2 > 0.0 ? clamp(dot(x - e.a.xyz, axis) / length2, 0.0, 1.0) : 0.0;
            vec3 v = x - (e.a.xyz + h * axis);
            float inv_r2 = 1.0 / (e.a.w * e.a.w);
            float q = 1.0 - dot(v, v) * inv_r2;
            if (q <= 0.0) continue;
            field += e.b.w * q * q;
            gradient -= (4.0 * e.b.w * q * inv_r2) * v;
        }
    }
    return field;
}

// Whether a point is inside (the field above the threshold: CSG's walked leaves, csg.glsl).
bool blob_inside(Primitive p, vec3 point) {
    vec3 gradient;
    return blob_field(mesh_at(p.data), point, gradient) > p.p0.x;
}

// The hit's error (Hit.error): the stretch's quartic is formed about m from points and
// components in float (a few roundings of |o| + t and the components' coordinates, each over
// r^2 through the squares), and Newton stops within 1.2e-7 of |m| + w; the root moves by those
// over the field's slope, which at the surface is of the threshold over r. As the torus's, a
// dozen or so roundings of the scale: 64 of max |o| + t + the box's coordinates.
float blob_hit_error(Primitive p, Ray ray, float t) {
    return rounding_bound(64.0, max_abs(ray.origin) + t + max(max_abs(p.p1.xyz), max_abs(p.p2.xyz)));
}

// The outward normal: down the field's gradient.
vec3 blob_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = blob_hit_error(p, ray, t);
    vec3 gradient;
    blob_field(mesh_at(p.data), point, gradient);
    float len = length(gradient);
    return len > 0.0 ? -gradient / len : -ray.dir;
}

// Texture (u, v): the hit's x and y across the box, as an implicit surface's.
vec2 blob_texture_uv(Primitive p, Hit hit, vec3 point) { return (point.xy - p.p1.xy) / (p.p2.xy - p.p1.xy); }
