#pragma once
// Objects' placements as the shader's ObjectFrames (shaders/placement.glsl).
#include "gpu/layout.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// The frame of object o of a scene rebased on `anchor`: the GPU's coordinates -> the object's
// own (an object without a transform has the world's: the GPU's plus the anchor).
ObjectFrame object_frame(const Object& o, const dvec3& anchor);

}  // namespace lancer::gpu
