// The photon maps' estimate at a diffuse hit (docs/scene-format.md, "[photons]"): per map, the
// power of the photons within its radius r that arrived on the side the surface faces, over
// pi r^2. The photons come from the hashed grid (photon_grid.glsl): a sphere of radius r
// touches at most the 2 x 2 x 2 cells of side 2r around it. The sum is exact integer
// arithmetic (each photon's power in quanta of photon_params.radii.z, 64 bits as two words), so
// it does not depend on the order the sort left the photons in. Twin of the CPU reference's
// kd-tree gather (host/cpu/photon_map.cpp): different code, the same estimate.
#ifndef LANCER_PHOTON_GATHER_GLSL
#define LANCER_PHOTON_GATHER_GLSL

#include "photon_grid.glsl"

// 64-bit unsigned sums as (high, low) words.
void add_quanta(inout uvec3 high, inout uvec3 low, vec3 power) {
    uvec3 q = uvec3(min(power / photon_params.radii.z + 0.5, vec3(2147483648.0)));
    uvec3 carry;
    low = uaddCarry(low, q, carry);
    high += carry;
}

vec3 photon_irradiance(vec3 p, vec3 n) {
    vec3 e = vec3(0.0);
    for (uint map = 0u; map < 2u; ++map) {
        float r = map_radius(map);
        ivec3 lo = grid_cell(p - r, map), hi = grid_cell(p + r, map);
        uvec3 high = uvec3(0u), low = uvec3(0u);
        uint seen[8];
        uint count = 0u;
        for (int z = lo.z; z <= hi.z; ++z) {
            for (int y = lo.y; y <= hi.y; ++y) {
                for (int x = lo.x; x <= hi.x; ++x) {
                    uint bucket = bucket_of(ivec3(x, y, z), map);
                    // Two cells may share a bucket: each bucket is read once.
                    bool again = false;
                    for (uint k = 0u; k < count; ++k) again = again || seen[k] == bucket;
                    if (again) continue;
                    seen[count++] = bucket;
                    uint end = gather_start_at(bucket + 1u);
                    for (uint i = gather_start_at(bucket); i < end; ++i) {
                        Photon ph = gather_photon_at(i);
                        vec3 d = ph.position.xyz - p;
                        if (dot(d, d) <= r * r && dot(ph.direction.xyz, n) < 0.0)
                            add_quanta(high, low, ph.power.rgb);
                    }
                }
            }
        }
        vec3 power = (vec3(high) * 4294967296.0 + vec3(low)) * photon_params.radii.z;
        e += power / (MICROFACET_PI * r * r);
    }
    return e;
}

#endif
