#version 450
// Adaptive anti-aliasing's choice of the pixels to refine, on the device (the host's definition:
// pixels_to_refine and the spread rule, image/adaptive.hpp and render/adaptive_render.cpp). The
// picture so far stays here, with each pixel's sRGB codes and flags, and the chosen pixels are
// compacted into refine_list, in increasing index order, for the next refining trace to dispatch
// over. Steps the host dispatches in order, with barriers between them (gpu/passes/refine_selection.cpp):
//   SELECT_ENCODE   per pixel: the codes of the first picture; every pixel a candidate;
//   SELECT_MERGE    per entry of a refined band (pixels[], as trace.comp wrote it): its colour
//                   and rays into the picture, its codes, and with the spread whether its
//                   samples spread by more than the threshold;
//   SELECT_FLAG     per pixel: whether it goes on (a candidate that differs from a neighbour, or
//                   whose samples spread), into refine_flags; and per block of SELECT_BLOCK
//                   pixels how many go on, into block_sums;
//   SELECT_BLOCKS   one workgroup: the block counts' prefix sums, the total in block_sums[blocks];
//   SELECT_SCATTER  per pixel that goes on: its index into refine_list at its block's offset plus
//                   the pixels before it in its block.
// Every decision is an exact comparison or integer arithmetic on tables the host computed with
// its own functions (image/difference_tables.hpp), so both sides choose the same pixels.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "interface.glsl"

layout(local_size_x = SELECT_WORKGROUP, local_size_y = 1, local_size_z = 1) in;
layout(push_constant) uniform SelectBlock { SelectStep selection; };

#include "block_scan.glsl"

// encode_srgb8() of a linear value: the highest level whose first value it reaches, or 0 (NaN
// reaches none). The curve in float lands on that level or next to it; the level starts then
// settle it exactly, with a fetch or two.
uint srgb8(float linear) {
    uint code = 0u;
    if (linear > 0.0) {
        float c = min(linear, 1.0);
        float encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
        code = uint(clamp(round(encoded * 255.0), 0.0, 255.0));
    }
    while (code < 255u && linear >= uintBitsToFloat(srgb_level_start(code + 1u))) ++code;
    while (code > 0u && linear < uintBitsToFloat(srgb_level_start(code))) --code;
    return code;
}

uint encode_colour(vec3 c) { return srgb8(c.r) | (srgb8(c.g) << 8) | (srgb8(c.b) << 16); }

// color_difference() of two encoded colours > the threshold.
bool differs(uint a, uint b) {
    ivec3 ca = ivec3(a & 255u, (a >> 8) & 255u, a >> 16), cb = ivec3(b & 255u, (b >> 8) & 255u, b >> 16);
    uvec3 d = uvec3(abs(ca - cb));
    return d.b >= blue_difference_floor(d.r * 256u + d.g);
}

// Whether candidate i goes on, given its row neighbours' codes (`left`, `right`: those of the
// pixels before and after it in memory, which are its neighbours where the row goes on).
bool differs_from_a_neighbour(uint i, uint c, uint left, uint right) {
    uint x = i % selection.width, y = i / selection.width;
    return (x > 0u && differs(c, left)) || (x + 1u < selection.width && differs(c, right)) ||
           (y > 0u && differs(c, picture_codes[i - selection.width])) ||
           (y + 1u < selection.height && differs(c, picture_codes[i + selection.width]));
}

// SELECT_FLAG over pixels [first, end): writes their flags, returns how many go on.
uint flag_run(uint first, uint end) {
    uint chosen = 0u;
    uint left = first > 0u ? picture_codes[first - 1u] : 0u, c = first < end ? picture_codes[first] : 0u;
    for (uint i = first; i < end; ++i) {
        uint right = i + 1u < selection.width * selection.height ? picture_codes[i + 1u] : 0u;
        uint flags = refine_flags[i];
        bool goes_on = (flags & REFINE_CANDIDATE) != 0u &&
                       (selection.every_candidate != 0u || (selection.spread != 0u && (flags & REFINE_SPREAD) != 0u) ||
                        differs_from_a_neighbour(i, c, left, right));
        refine_flags[i] = goes_on ? REFINE_CANDIDATE : 0u;
        chosen += goes_on ? 1u : 0u;
        left = c;
        c = right;
    }
    return chosen;
}

uint chosen_in_run(uint first, uint end) {
    uint chosen = 0u;
    for (uint i = first; i < end; ++i) chosen += refine_flags[i] & REFINE_CANDIDATE;
    return chosen;
}

void merge_entry(uint i) {
    uint p = refine_list[selection.first + i];
    vec4 c = pixels[i];
    // The rgb is the last grid's; the rays add up (render/adaptive_render.cpp).
    picture[p] = vec4(c.rgb, picture[p].a + c.a);
    picture_codes[p] = encode_colour(c.rgb);
    if (selection.spread != 0u &&
        differs(encode_colour(pixels[selection.count + i].rgb), encode_colour(pixels[2u * selection.count + i].rgb)))
        refine_flags[p] |= REFINE_SPREAD;
}

// Each invocation takes a run of SELECT_RUN consecutive pixels (or list entries), so that one
// prefix sum over a workgroup, with its barriers, covers a block of SELECT_BLOCK pixels: lavapipe
// pays far more for a workgroup's barriers than for the loop (a pixel per invocation: 0.3 s a pass
// at 1280x720 instead of 20-40 ms; docs/performance.md).

void main() {
    uint block = gl_WorkGroupID.x;
    uint first = (block * SELECT_WORKGROUP + gl_LocalInvocationIndex) * SELECT_RUN;
    uint pixel_count = selection.width * selection.height;
    uint blocks = (pixel_count + SELECT_BLOCK - 1u) / SELECT_BLOCK;
    uint end = min(first + SELECT_RUN, pixel_count);
    if (selection.kind == SELECT_ENCODE) {
        for (uint i = first; i < end; ++i) {
            picture_codes[i] = encode_colour(picture[i].rgb);
            refine_flags[i] = REFINE_CANDIDATE;
        }
    } else if (selection.kind == SELECT_MERGE) {
        for (uint i = first; i < min(first + SELECT_RUN, selection.count); ++i) merge_entry(i);
    } else if (selection.kind == SELECT_FLAG) {
        uint total;
        workgroup_exclusive_sum(flag_run(first, end), total);
        if (block < blocks && gl_LocalInvocationIndex == 0u) block_sums[block] = total;
    } else if (selection.kind == SELECT_BLOCKS) {
        scan_block_sums(blocks);
    } else if (selection.kind == SELECT_SCATTER) {
        uint total;
        uint place = workgroup_exclusive_sum(chosen_in_run(first, end), total);
        if (block < blocks) place += block_sums[block];
        for (uint i = first; i < end; ++i)
            if ((refine_flags[i] & REFINE_CANDIDATE) != 0u) refine_list[place++] = i;
    }
}
