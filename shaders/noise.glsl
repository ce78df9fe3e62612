// Ken Perlin's improved noise (SIGGRAPH 2002), written as his reference code writes it: seven
// nested lerps of the corners' gradient dot products. Each value carries its gradient along
// (a vec4: xyz = gradient, w = value), so the result is the noise and its exact derivative.
// Twin of host/cpu/noise.cpp, which sums the corners' weighted terms in double precision.
#ifndef LANCER_NOISE_GLSL
#define LANCER_NOISE_GLSL

// The reference's p[i] (its table holds the permutation twice, for i < 512): Ken Perlin's
// permutation of 0..255 (host/core/perlin_permutation.hpp), read from a buffer, not a constant
// array: lavapipe copies a constant array into every function that indexes it, which made the
// pipeline take minutes to compile.
int perlin_perm(int i) { return permutation_at(uint(i & 255)); }

// The reference's grad(hash, x, y, z) = g . (x, y, z), as (g, g . r).
vec4 perlin_corner(int hash, vec3 r) {
    int h = hash & 15;
    float u = h < 8 ? r.x : r.y;
    float v = h < 4 ? r.y : (h == 12 || h == 14 ? r.x : r.z);
    vec3 gu = h < 8 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 gv = h < 4 ? vec3(0.0, 1.0, 0.0) : (h == 12 || h == 14 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0));
    float su = (h & 1) == 0 ? 1.0 : -1.0;
    float sv = (h & 2) == 0 ? 1.0 : -1.0;
    return vec4(su * gu + sv * gv, su * u + sv * v);
}

// lerp(t, a, b) of (gradient, value) pairs, where t has gradient dt.
vec4 perlin_lerp(float t, vec3 dt, vec4 a, vec4 b) {
    return vec4(mix(a.xyz, b.xyz, t) + (b.w - a.w) * dt, mix(a.w, b.w, t));
}

// xyz = gradient, w = noise in [-1, 1]; 0 where p has integer coordinates.
vec4 perlin_noise(vec3 p) {
    vec3 cell = floor(p);
    vec3 f = p - cell;
    ivec3 i = ivec3(cell) & 255;
    vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec3 dw = 30.0 * f * f * (f - 1.0) * (f - 1.0);
    int A = perlin_perm(i.x) + i.y, AA = perlin_perm(A) + i.z, AB = perlin_perm(A + 1) + i.z;
    int B = perlin_perm(i.x + 1) + i.y, BA = perlin_perm(B) + i.z, BB = perlin_perm(B + 1) + i.z;
    vec3 dx = vec3(dw.x, 0.0, 0.0), dy = vec3(0.0, dw.y, 0.0), dz = vec3(0.0, 0.0, dw.z);
    vec4 near = perlin_lerp(w.y, dy,
                            perlin_lerp(w.x, dx, perlin_corner(perlin_perm(AA), f),
                                        perlin_corner(perlin_perm(BA), f - vec3(1.0, 0.0, 0.0))),
                            perlin_lerp(w.x, dx, perlin_corner(perlin_perm(AB), f - vec3(0.0, 1.0, 0.0)),
                                        perlin_corner(perlin_perm(BB), f - vec3(1.0, 1.0, 0.0))));
    vec4 far = perlin_lerp(w.y, dy,
                           perlin_lerp(w.x, dx, perlin_corner(perlin_perm(AA + 1), f - vec3(0.0, 0.0, 1.0)),
                                       perlin_corner(perlin_perm(BA + 1), f - vec3(1.0, 0.0, 1.0))),
                           perlin_lerp(w.x, dx, perlin_corner(perlin_perm(AB + 1), f - vec3(0.0, 1.0, 1.0)),
                                       perlin_corner(perlin_perm(BB + 1), f - vec3(1.0, 1.0, 1.0))));
    return perlin_lerp(w.z, dz, near, far);
}

#endif
