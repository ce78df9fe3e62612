#pragma once
// Scene model -> the GPU structs of shaders/layout.h: primitives ordered for the BVH (bounded
// ones in leaf order, then the unbounded planes), the flattened BVH, materials and lights.
// Pure data conversion, no Vulkan.
#include <vector>

#include "accel/bvh.hpp"
#include "gpu/layout.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// The optional shading features a scene uses: the pipeline compiles out the others.
struct ShadingFeatures {
    bool transparency = false;
    bool area_lights = false;
    bool spot_lights = false;
    bool falloff = false;
    bool blinn = false;
};

struct PackedScene {
    std::vector<Primitive> primitives;
    std::vector<BvhNode> nodes;
    std::vector<PatchLeaf> patches;
    std::vector<SurfaceInfo> surfaces;
    std::vector<ParametricCell> cells;
    std::vector<Material> materials;
    std::vector<TextureInfo> textures;  // one per material with a texture
    std::vector<uint> texels;           // every texture image once, RGBA8
    std::vector<PatternInfo> patterns;  // colour patterns and bumps
    std::vector<int> permutation;       // Ken Perlin's, when there are patterns
    std::vector<Light> lights;
    uint unbounded_count = 0;
    ShadingFeatures features;
};

// With a cache, a BVH over the same boxes as the last one is not built again (animations).
PackedScene pack_scene(const Scene& scene, Acceleration acceleration = Acceleration::Bvh, BvhCache* cache = nullptr);
FrameParams pack_frame(const Scene& scene, const PackedScene& packed);

// float(x) rounded toward -inf / +inf, so float boxes contain their double originals.
float round_down(double x);
float round_up(double x);

}  // namespace lancer::gpu
