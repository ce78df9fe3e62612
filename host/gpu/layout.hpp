#pragma once
// The host's view of shaders/layout.h: the same structs, compiled as C++, and the tables of
// resources and specialisation constants turned into C++ types.
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "layout.h"  // shaders/ is on the include path

namespace lancer::gpu {

// The shader's specialisation constants (LANCER_FEATURES). Optional features are compiled out
// of pipelines whose scene lacks them.
struct ShaderFeatures {
#define LANCER_FEATURE_MEMBER(NAME, id, type, member, fallback) type member{};
    LANCER_FEATURES(LANCER_FEATURE_MEMBER)
#undef LANCER_FEATURE_MEMBER
    auto operator<=>(const ShaderFeatures&) const = default;

    // The sets of shape types (bit t for type t) in scene_shapes, boxed_families, split_families.
    bool has_shape(uint type) const { return (scene_shapes >> type) & 1u; }
    void add_shape(uint type) { scene_shapes |= 1u << type; }
    bool family_boxed(uint type) const { return (boxed_families >> type) & 1u; }
    bool family_split(uint type) const { return (split_families >> type) & 1u; }
};

struct FeatureSpec {
    const char* name;  // the GLSL constant
    uint id;           // its constant_id
    bool is_bool;      // else a uint
};

inline constexpr FeatureSpec kFeatures[] = {
#define LANCER_FEATURE_SPEC(NAME, id, type, member, fallback) {#NAME, id, std::is_same_v<type, bool>},
    LANCER_FEATURES(LANCER_FEATURE_SPEC)
#undef LANCER_FEATURE_SPEC
};
inline constexpr std::size_t kFeatureCount = std::size(kFeatures);

// The value of kFeatures[i] in `features`, as the 32-bit word Vulkan specialises it with.
constexpr std::uint32_t feature_value(const ShaderFeatures& features, std::size_t i) {
    std::size_t k = 0;
#define LANCER_FEATURE_VALUE(NAME, id, type, member, fallback) \
    if (k++ == i) return static_cast<std::uint32_t>(features.member);
    LANCER_FEATURES(LANCER_FEATURE_VALUE)
#undef LANCER_FEATURE_VALUE
    return 0;
}

// FrameParams' per-shape uints (family_end, family_split), four to a uvec4.
constexpr uint& per_shape(uvec4* quads, uint type) { return quads[type / 4][type % 4]; }
constexpr uint per_shape(const uvec4* quads, uint type) { return quads[type / 4][type % 4]; }

// One descriptor of the tracer's set (LANCER_RESOURCES).
struct ResourceSpec {
    const char* name;  // "PRIMITIVES": the binding constant's suffix and the debug name's
    uint binding;
    uint kind;                  // RESOURCE_*
    std::size_t element_bytes;  // sizeof(Element)
    const char* what;           // "Bezier patch leaves", for messages
};

inline constexpr ResourceSpec kResources[] = {
#define LANCER_RESOURCE_SPEC(NAME, slot, kind, Element, member, reader, what) {#NAME, slot, kind, sizeof(Element), what},
    LANCER_RESOURCES(LANCER_RESOURCE_SPEC)
#undef LANCER_RESOURCE_SPEC
};
inline constexpr std::size_t kResourceCount = std::size(kResources);

// The resource at `binding`. The table's bindings are 0, 1, ..., N - 1, each once, so arrays
// of buffers or descriptors can be indexed by binding.
constexpr const ResourceSpec& resource(uint binding) {
    for (const ResourceSpec& r : kResources)
        if (r.binding == binding) return r;
    throw "no resource at this binding";
}
constexpr bool bindings_are_dense() {
    for (uint b = 0; b < kResourceCount; ++b) {
        std::size_t found = 0;
        for (const ResourceSpec& r : kResources) found += r.binding == b;
        if (found != 1) return false;
    }
    return true;
}
static_assert(bindings_are_dense(), "LANCER_RESOURCES: bindings must be 0..N-1, each once");

// The scene's read-only arrays (LANCER_SCENE_ARRAYS), in table order.
enum class SceneArray : std::size_t {
#define LANCER_SCENE_ARRAY_ENUM(NAME, slot, kind, Element, member, reader, what) NAME,
    LANCER_SCENE_ARRAYS(LANCER_SCENE_ARRAY_ENUM)
#undef LANCER_SCENE_ARRAY_ENUM
};
inline constexpr ResourceSpec kSceneArrays[] = {
#define LANCER_SCENE_ARRAY_SPEC(NAME, slot, kind, Element, member, reader, what) {#NAME, slot, kind, sizeof(Element), what},
    LANCER_SCENE_ARRAYS(LANCER_SCENE_ARRAY_SPEC)
#undef LANCER_SCENE_ARRAY_SPEC
};
inline constexpr std::size_t kSceneArrayCount = std::size(kSceneArrays);
inline constexpr const ResourceSpec& spec(SceneArray a) { return kSceneArrays[static_cast<std::size_t>(a)]; }

// Bytes per texel of a texel-buffer kind (RGBA32UI rows, or R32 words); 0 for the others.
constexpr std::size_t texel_bytes(uint kind) {
    return kind == RESOURCE_ROWS ? 16 : (kind == RESOURCE_UINT || kind == RESOURCE_INT) ? 4 : 0;
}

}  // namespace lancer::gpu
