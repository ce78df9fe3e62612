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
#if LANCER_PARAMETRIC_SURFACES

float parametric_hit_error(Primitive prim, Ray ray, float t, vec2 uv) {
    vec3 lo = prim.p0.xyz, hi = prim.p1.xyz;  // the cell's proved box
    return 1e-4 * length(hi - lo) + rounding_bound(64.0, max(max_abs(lo), max_abs(hi))) + hit_point_rounding(ray.origin, t);
}

#endif
