#include "cpu/pattern.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/constants.hpp"

namespace lancer::cpu {
namespace {

// Perlin's turbulence: the sum over octaves i of omega^i |noise(lambda^i q)|.
NoiseSample turbulence(const Pattern& pattern, const dvec3& q) {
    NoiseSample sum{0.0, dvec3(0.0)};
    double amplitude = 1.0, frequency = 1.0;
    for (int i = 0; i < pattern.octaves; ++i) {
        NoiseSample n = perlin_noise(frequency * q);
        double sign = n.value < 0.0 ? -1.0 : 1.0;
        sum.value += amplitude * std::abs(n.value);
        sum.gradient += amplitude * frequency * sign * n.gradient;
        amplitude *= pattern.omega;
        frequency *= pattern.lambda;
    }
    return sum;
}

}  // namespace

NoiseSample pattern_value(const Pattern& pattern, const dvec3& q) {
    switch (pattern.type) {
        case PatternType::Noise: {
            NoiseSample n = perlin_noise(q);
            return {0.5 + 0.5 * n.value, 0.5 * n.gradient};
        }
        case PatternType::Turbulence: return turbulence(pattern, q);
        case PatternType::Marble: {
            // Bands across x, one light-to-dark-to-light period per unit, bent by turbulence.
            NoiseSample t = turbulence(pattern, q);
            double phase = 2.0 * kPi * (q.x + pattern.turbulence * t.value);
            dvec3 dphase = 2.0 * kPi * (dvec3(1.0, 0.0, 0.0) + pattern.turbulence * t.gradient);
            return {0.5 + 0.5 * std::sin(phase), 0.5 * std::cos(phase) * dphase};
        }
        case PatternType::Wood: {
            // Rings around the z axis, one per unit of radius, as a triangle wave (0 at the ring
            // boundary, 1 half way), their radius bent by turbulence.
            NoiseSample t = turbulence(pattern, q);
            double radius = std::sqrt(q.x * q.x + q.y * q.y);
            dvec3 dradius = radius > 0.0 ? dvec3(q.x / radius, q.y / radius, 0.0) : dvec3(0.0);
            double r = radius + pattern.turbulence * t.value;
            dvec3 dr = dradius + pattern.turbulence * t.gradient;
            double fraction = r - std::floor(r);
            return {1.0 - 2.0 * std::abs(fraction - 0.5), (fraction < 0.5 ? 2.0 : -2.0) * dr};
        }
    }
    return {0.0, dvec3(0.0)};
}

dvec3 ramp_color(const std::vector<ColorStop>& ramp, double t) {
    dvec3 color = ramp.front().color;
    for (std::size_t i = 1; i < ramp.size(); ++i) {
        const ColorStop& a = ramp[i - 1];
        const ColorStop& b = ramp[i];
        if (t >= b.position) {
            color = b.color;
        } else {
            if (t > a.position) color = glm::mix(a.color, b.color, (t - a.position) / (b.position - a.position));
            break;
        }
    }
    return color;
}

namespace {

dvec3 to_pattern_space(const Pattern& pattern, const dvec3& p) {
    return dvec3(glm::inverse(pattern.to_world) * glm::dvec4(p, 1.0));
}

}  // namespace

dvec3 pattern_color(const Pattern& pattern, const dvec3& p) {
    return ramp_color(pattern.colors, pattern_value(pattern, to_pattern_space(pattern, p)).value);
}

dvec3 bumped_normal(const Bump& bump, const dvec3& p, const dvec3& n, const glm::dmat3& object_to_world) {
    NoiseSample f = pattern_value(bump.pattern, to_pattern_space(bump.pattern, p));
    // The world gradient of f, times the pattern's mean scale (its own and its object's): so a
    // bump keeps its depth when the pattern or its object is scaled (POV-Ray's rule).
    glm::dmat3 linear = object_to_world * glm::dmat3(bump.pattern.to_world);
    dvec3 g = glm::transpose(glm::inverse(linear)) * f.gradient * std::cbrt(std::abs(glm::determinant(linear)));
    dvec3 tilted = n - bump.amount * (g - glm::dot(g, n) * n);
    return glm::normalize(tilted);
}

}  // namespace lancer::cpu
