#pragma once
// GLSL for a scene's expression surfaces: the replacement of shaders/surface_functions.glsl.
// One function per parametric surface (value and exact partial derivatives by forward
// differentiation of the parsed expression trees, gpu/shaders/glsl_emitter), three per implicit
// surface (value and directional derivative, gradient, interval enclosure), and dispatchers by
// surface index. User text never reaches the shader: only the trees are printed.
#include <string>

#include "scene/scene.hpp"

namespace lancer::gpu {

// "" when the scene has no expression surfaces (the tracer then uses the file as shipped).
// Parametric surface k is the k-th ParametricObject of scene.objects, the index of its
// SurfaceInfo; implicit surface k the k-th ImplicitObject, the index of its ImplicitInfo
// (scene_packing.cpp).
// `float64`: the device runs double precision (shaderFloat64), so implicit surfaces get their
// enclosure at a point in double too (LANCER_FLOAT64, shapes/implicit.glsl).
std::string surface_functions_glsl(const Scene& scene, bool float64);

}  // namespace lancer::gpu
