#pragma once
// Ken Perlin's improved noise (SIGGRAPH 2002, and his reference Java code), in double
// precision, with its exact gradient. The shader's twin is shaders/noise.glsl.
#include <glm/vec3.hpp>

namespace lancer::cpu {

struct NoiseSample {
    double value;           // in [-1, 1]; 0 at every point with integer coordinates
    glm::dvec3 gradient;    // d value / d p
};

NoiseSample perlin_noise(const glm::dvec3& p);

}  // namespace lancer::cpu
