#pragma once
// Ken Perlin's reference ImprovedNoise.noise (Java, 2002), transcribed line by line: what both
// renderers' noise is checked against.
#include <cmath>

#include <glm/vec3.hpp>

#include "core/perlin_permutation.hpp"

namespace lancer::test {

inline double reference_noise(glm::dvec3 q) {
    auto p = [](int i) { return kPerlinPermutation[static_cast<std::size_t>(i & 255)]; };
    auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
    auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
    auto grad = [](int hash, double x, double y, double z) {
        int h = hash & 15;
        double u = h < 8 ? x : y, v = h < 4 ? y : h == 12 || h == 14 ? x : z;
        return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
    };
    int X = static_cast<int>(std::floor(q.x)) & 255, Y = static_cast<int>(std::floor(q.y)) & 255,
        Z = static_cast<int>(std::floor(q.z)) & 255;
    double x = q.x - std::floor(q.x), y = q.y - std::floor(q.y), z = q.z - std::floor(q.z);
    double u = fade(x), v = fade(y), w = fade(z);
    int A = p(X) + Y, AA = p(A) + Z, AB = p(A + 1) + Z, B = p(X + 1) + Y, BA = p(B) + Z, BB = p(B + 1) + Z;
    return lerp(w,
                lerp(v, lerp(u, grad(p(AA), x, y, z), grad(p(BA), x - 1, y, z)),
                     lerp(u, grad(p(AB), x, y - 1, z), grad(p(BB), x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(p(AA + 1), x, y, z - 1), grad(p(BA + 1), x - 1, y, z - 1)),
                     lerp(u, grad(p(AB + 1), x, y - 1, z - 1), grad(p(BB + 1), x - 1, y - 1, z - 1))));
}

}  // namespace lancer::test
