#version 450
// Builds the hashed grid of a pass's photons (photon_grid.glsl) by a counting sort, in steps the
// host dispatches in order with barriers between them (GpuRenderer's photon pass):
//   GRID_CLEAR    per bucket: its count to 0;
//   GRID_COUNT    per photon: count it in its bucket;
//   GRID_SCAN     per block of PHOTON_WORKGROUP buckets: the exclusive prefix sums of the counts
//                 within the block, into cell_start, and the block's total into block_sums;
//   GRID_BLOCKS   one workgroup: the exclusive prefix sums of the block totals, in place;
//   GRID_OFFSET   per bucket: add its block's offset to cell_start; the last one also writes
//                 the total after the last bucket;
//   GRID_SCATTER  per photon: into the next free place of its bucket (counting its bucket's
//                 count down), so that bucket k holds [cell_start[k], cell_start[k + 1]).
// Within a bucket the photons' order depends on the atomics, which the gather's exact integer
// sums do not see: the image is the same, bit for bit, whatever the order.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "interface.glsl"

layout(local_size_x = PHOTON_WORKGROUP, local_size_y = 1, local_size_z = 1) in;
layout(push_constant) uniform GridBlock { GridStep step; };

#include "block_scan.glsl"
#include "photon_grid.glsl"

uint photon_bucket(uint i) {
    Photon ph = photons[i];
    uint map = uint(ph.position.w);
    return bucket_of(grid_cell(ph.position.xyz, map), map);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint stored = min(photon_counter[0], photon_params.capacity);
    uint buckets = 2u * photon_params.table_size;
    if (step.kind == GRID_CLEAR) {
        if (i < buckets) cell_count[i] = 0u;
    } else if (step.kind == GRID_COUNT) {
        if (i < stored) atomicAdd(cell_count[photon_bucket(i)], 1u);
    } else if (step.kind == GRID_SCAN) {
        uint total;
        uint before = workgroup_exclusive_sum(i < buckets ? cell_count[i] : 0u, total);
        if (i < buckets) cell_start[i] = before;
        if (gl_LocalInvocationIndex == 0u) block_sums[gl_WorkGroupID.x] = total;
    } else if (step.kind == GRID_BLOCKS) {
        scan_block_sums((buckets + PHOTON_WORKGROUP - 1u) / PHOTON_WORKGROUP);
    } else if (step.kind == GRID_OFFSET) {
        if (i >= buckets) return;
        uint start = cell_start[i] + block_sums[i / PHOTON_WORKGROUP];
        cell_start[i] = start;
        if (i == buckets - 1u) cell_start[buckets] = start + cell_count[i];
    } else if (step.kind == GRID_SCATTER) {
        if (i >= stored) return;
        uint bucket = photon_bucket(i);
        uint place = cell_start[bucket] + atomicAdd(cell_count[bucket], 0xffffffffu) - 1u;  // count down
        photons_sorted[place] = photons[i];
    }
}
