#pragma once
// GLSL for a scene's parametric surfaces: the replacement of shaders/surface_functions.glsl.
// One function per surface, value and exact partial derivatives by forward differentiation of
// the parsed expression trees (surface/expr/glsl_emitter), and a dispatcher by surface index.
// User text never reaches the shader: only the trees are printed.
#include <string>

#include "scene/scene.hpp"

namespace lancer::gpu {

// "" when the scene has no parametric surfaces (the tracer then uses the file as shipped).
// Surface k is the k-th ParametricObject of scene.objects, the index the packer gives it.
std::string surface_functions_glsl(const Scene& scene);

}  // namespace lancer::gpu
