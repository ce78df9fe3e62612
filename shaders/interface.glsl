// The shader's side of the host interface, declared from the tables in layout.h: every
// descriptor of set 0 with the function that reads it, and every specialisation constant.
// Nothing here is written by hand per struct or per buffer.
#ifndef LANCER_INTERFACE_GLSL
#define LANCER_INTERFACE_GLSL

// texelFetch on a textureBuffer without a sampler: SPIR-V 1.6 (Vulkan 1.3) forbids a sampled
// image of Dim Buffer, which is what a samplerBuffer becomes.
#extension GL_EXT_samplerless_texture_functions : require

#include "layout.h"

// Reading a struct from a texel buffer: one RGBA32UI texel per row of layout.h's list, in order.
// A member the caller never uses is never fetched (texel fetches have no side effects, so the
// compiler drops them).
void lancer_unpack(uint word, out uint value) { value = word; }
void lancer_unpack(uint word, out int value) { value = int(word); }
void lancer_unpack(uint word, out float value) { value = uintBitsToFloat(word); }

#define LANCER_READ_VEC4(name) r.name = uintBitsToFloat(texelFetch(texels, k++));
#define LANCER_READ_VEC4S(name, n) \
    [[unroll]] for (int j = 0; j < (n); ++j) r.name[j] = uintBitsToFloat(texelFetch(texels, k++));
#define LANCER_READ_UVEC4S(name, n) \
    [[unroll]] for (int j = 0; j < (n); ++j) r.name[j] = texelFetch(texels, k++);
#define LANCER_READ_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) \
    {                                                        \
        uvec4 w = texelFetch(texels, k++);                   \
        lancer_unpack(w.x, r.n0);                            \
        lancer_unpack(w.y, r.n1);                            \
        lancer_unpack(w.z, r.n2);                            \
        lancer_unpack(w.w, r.n3);                            \
    }

// X(NAME, slot, kind, Element, member, reader, what) -> the declaration for its kind.
#define LANCER_DECLARE(NAME, slot, kind, Element, member, reader, what) LANCER_DECLARE_##kind(NAME, slot, Element, member, reader)

#define LANCER_DECLARE_RESOURCE_UNIFORM(NAME, slot, Element, member, reader) \
    layout(std140, set = 0, binding = slot) uniform NAME##_Block { Element member; };

#define LANCER_DECLARE_RESOURCE_OUTPUT(NAME, slot, Element, member, reader) \
    layout(std430, set = 0, binding = slot) buffer NAME##_Block { Element member[]; };

#define LANCER_DECLARE_RESOURCE_ROWS(NAME, slot, Element, member, reader)                        \
    layout(set = 0, binding = slot) uniform utextureBuffer NAME##_texels;                          \
    Element reader##_in(utextureBuffer texels, uint i) {                                           \
        Element r;                                                                                 \
        int k = int(i * Element##_ROWS);                                                           \
        LANCER_ROWS_##Element(LANCER_READ_VEC4, LANCER_READ_VEC4S, LANCER_READ_SCALARS, LANCER_READ_UVEC4S) \
        return r;                                                                                  \
    }                                                                                              \
    Element reader(uint i) { return reader##_in(NAME##_texels, i); }

#define LANCER_DECLARE_RESOURCE_UINT(NAME, slot, Element, member, reader) \
    layout(set = 0, binding = slot) uniform utextureBuffer NAME##_texels; \
    uint reader(uint i) { return texelFetch(NAME##_texels, int(i)).x; }

#define LANCER_DECLARE_RESOURCE_INT(NAME, slot, Element, member, reader) \
    layout(set = 0, binding = slot) uniform itextureBuffer NAME##_texels; \
    int reader(uint i) { return texelFetch(NAME##_texels, int(i)).x; }

LANCER_RESOURCES(LANCER_DECLARE)

#define LANCER_DECLARE_FEATURE(NAME, id, type, member, fallback) layout(constant_id = id) const type NAME = fallback;
LANCER_FEATURES(LANCER_DECLARE_FEATURE)

// The shape types this module can trace: all of them, or (LANCER_BUILT_SHAPES, a module built
// beside the whole tracer) fewer, for scenes of those types alone. Every test of a shape set
// below masks with it; glslang folds the mask, and SPIRV-Tools removes what a zero mask leaves
// dead (host/gpu/shaders/spirv_prune.cpp).
#ifndef LANCER_BUILT_SHAPES
#define LANCER_BUILT_SHAPES 0xffffffffu
#endif
const uint BUILT_SHAPES = LANCER_BUILT_SHAPES;
#define BUILT_BIT(type) (BUILT_SHAPES & (1u << (type)))

// Each shape type's flags, from the sets above: SCENE_HAS_<NAME> (the scene has the shape),
// <NAME>_BOXED and <NAME>_SPLIT (its family outside the BVH has a box, or one per half),
// CSG_HAS_<NAME> (some CSG leaf is one: only those families' tests are compiled into the walk),
// TRACES_<NAME> (some primitive outside CSG is one: its family's loop and its case of the
// primitives' intersection, which lavapipe runs masked for every primitive, are compiled in).
// Specialisation-constant expressions: the host folds them with the constants.
#define LANCER_DECLARE_SHAPE_FLAGS(NAME, name, Type, type, traits)       \
    const bool SCENE_HAS_##NAME = (SCENE_SHAPES & BUILT_BIT(SHAPE_##NAME)) != 0u; \
    const bool TRACES_##NAME = ((SCENE_SHAPES & ~LEAF_ONLY_SHAPES) & BUILT_BIT(SHAPE_##NAME)) != 0u; \
    const bool NAME##_BOXED = (BOXED_FAMILIES & BUILT_BIT(SHAPE_##NAME)) != 0u;   \
    const bool NAME##_SPLIT = (SPLIT_FAMILIES & BUILT_BIT(SHAPE_##NAME)) != 0u;   \
    const bool CSG_HAS_##NAME = (CSG_LEAF_SHAPES & BUILT_BIT(SHAPE_##NAME)) != 0u;
LANCER_SHAPES(LANCER_DECLARE_SHAPE_FLAGS)

#endif
