#pragma once
// Scene model -> the GPU structs of shaders/layout.h. Pure data conversion, no Vulkan.
#include <vector>

#include "gpu/layout.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

struct PackedScene {
    std::vector<Primitive> primitives;
    std::vector<Material> materials;
    std::vector<Light> lights;
};

PackedScene pack_scene(const Scene& scene);
FrameParams pack_frame(const Scene& scene);

}  // namespace lancer::gpu
