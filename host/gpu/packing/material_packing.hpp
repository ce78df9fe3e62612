#pragma once
// Materials, their textures and patterns, lights and photon emitters to the shader's arrays.
#include "gpu/packing/scene_packing.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// The scene's materials with their images, patterns and energy tables, and the sky's pattern,
// into `out`; solid checkers are phased for the GPU's coordinates, relative to `anchor`.
void pack_materials(const Scene& scene, const glm::dvec3& anchor, PackedScene& out);

Light pack_light(const lancer::Light& light);

// Photon mapping's view of the lights (layout.h, Emitter): each photon's power and the
// cumulative probabilities by which photons choose a light (proportional to its power), as the
// CPU reference's photon tracer (host/cpu/photon_tracer.cpp).
void pack_emitters(const Scene& scene, PackedScene& out);

}  // namespace lancer::gpu
