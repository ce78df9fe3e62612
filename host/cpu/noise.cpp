// Improved noise as a sum over the 8 corners of the lattice cell: each corner c contributes its
// gradient's dot product with (f - c), weighted by the quintic fade of f along each axis. The
// reference code nests 7 lerps instead; the sum is the same polynomial, and differentiating it
// term by term gives the exact gradient.
#include "cpu/noise.hpp"

#include "core/perlin_permutation.hpp"

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lancer::cpu {
namespace {

// The reference's p[i] for i < 512 (its table holds the permutation twice).
int perm(int i) { return kPerlinPermutation[static_cast<std::size_t>(i & 255)]; }

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double fade_derivative(double t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); }

// The reference's grad(hash, x, y, z) is the dot product of (x, y, z) with this vector: one of
// the 12 edge midpoints of the cube (4 of them twice).
glm::dvec3 gradient_vector(int hash) {
    int h = hash & 15;
    glm::dvec3 g(0.0);
    int u_axis = h < 8 ? 0 : 1;
    int v_axis = h < 4 ? 1 : (h == 12 || h == 14 ? 0 : 2);
    g[u_axis] += (h & 1) == 0 ? 1.0 : -1.0;
    g[v_axis] += (h & 2) == 0 ? 1.0 : -1.0;
    return g;
}

}  // namespace

NoiseSample perlin_noise(const glm::dvec3& p) {
    glm::dvec3 cell = glm::floor(p);
    glm::dvec3 f = p - cell;
    int X = static_cast<int>(static_cast<long long>(cell.x) & 255);
    int Y = static_cast<int>(static_cast<long long>(cell.y) & 255);
    int Z = static_cast<int>(static_cast<long long>(cell.z) & 255);
    glm::dvec3 w(fade(f.x), fade(f.y), fade(f.z));
    glm::dvec3 dw(fade_derivative(f.x), fade_derivative(f.y), fade_derivative(f.z));

    NoiseSample s{0.0, glm::dvec3(0.0)};
    for (int c = 0; c < 8; ++c) {
        glm::ivec3 corner(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        int hash = perm(perm(perm(X + corner.x) + Y + corner.y) + Z + corner.z);
        glm::dvec3 g = gradient_vector(hash);
        double d = glm::dot(g, f - glm::dvec3(corner));
        // Weight of this corner along each axis (fade toward it) and its derivative.
        glm::dvec3 weight, slope;
        for (int a = 0; a < 3; ++a) {
            weight[a] = corner[a] ? w[a] : 1.0 - w[a];
            slope[a] = corner[a] ? dw[a] : -dw[a];
        }
        double W = weight.x * weight.y * weight.z;
        s.value += W * d;
        s.gradient += glm::dvec3(slope.x * weight.y * weight.z, weight.x * slope.y * weight.z, weight.x * weight.y * slope.z) * d +
                      W * g;
    }
    return s;
}

}  // namespace lancer::cpu
