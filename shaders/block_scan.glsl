// Prefix sums over the invocations of a workgroup, and over the totals of many workgroups' blocks:
// the counting sort of the photon grid (photon_grid.comp) and the list of pixels adaptive
// anti-aliasing refines (refine_select.comp) are both built on them. A block is one workgroup's
// invocations, in local index order, one value each; block_sums (LANCER_RESOURCES) holds the
// blocks' totals between the two steps. Include after the shader's one-dimensional local size,
// which sizes the shared array. Every invocation of the workgroup must make the calls (barriers).
#ifndef LANCER_BLOCK_SCAN_GLSL
#define LANCER_BLOCK_SCAN_GLSL

shared uint scan_lanes[gl_WorkGroupSize.x];

// The sum of `value` over the invocations before this one, and in `total` over the whole
// workgroup: Hillis and Steele's inclusive scan in shared memory, shifted to exclusive.
uint workgroup_exclusive_sum(uint value, out uint total) {
    uint lane = gl_LocalInvocationIndex;
    barrier();  // every lane has read what an earlier call left
    scan_lanes[lane] = value;
    barrier();
    for (uint offset = 1u; offset < gl_WorkGroupSize.x; offset *= 2u) {
        uint add = lane >= offset ? scan_lanes[lane - offset] : 0u;
        barrier();
        scan_lanes[lane] += add;
        barrier();
    }
    total = scan_lanes[gl_WorkGroupSize.x - 1u];
    return scan_lanes[lane] - value;
}

// Run by a single workgroup: block_sums[0, blocks) from the blocks' totals to the sums of the
// blocks before each (in place), and block_sums[blocks] = the sum of all. A chunk of the
// workgroup's size at a time, so that no invocation loops once per block (lavapipe cuts an
// invocation's loops off after 65535 iterations; trace.comp's loop_limit_reached).
void scan_block_sums(uint blocks) {
    uint carry = 0u;
    for (uint first = 0u; first < blocks; first += gl_WorkGroupSize.x) {
        uint b = first + gl_LocalInvocationIndex;
        uint total;
        uint before = workgroup_exclusive_sum(b < blocks ? block_sums[b] : 0u, total);
        if (b < blocks) block_sums[b] = carry + before;
        carry += total;
    }
    if (gl_LocalInvocationIndex == 0u) block_sums[blocks] = carry;
}

#endif
