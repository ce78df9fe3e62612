#include "cpu/lights.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace lancer::cpu {

double unit_interval(std::uint32_t h) { return double(h >> 8) / 16777216.0; }

// POV-Ray's spotlight: cos^tightness of the angle between the axis and the direction from the
// light, times the cubic 3t^2 - 2t^3 rising from outer_angle (t = 0) to inner_angle (t = 1).
double spot_factor(const Light& light, const dvec3& from_light) {
    constexpr double kDegree = M_PI / 180.0;
    double c = glm::dot(from_light, light.direction);
    double cos_outer = std::cos(light.outer_angle_deg * kDegree);
    double cos_inner = std::cos(light.inner_angle_deg * kDegree);
    if (c <= 0.0 || c < cos_outer) return 0.0;
    double f = std::pow(c, light.tightness);
    if (c >= cos_inner) return f;
    double t = (c - cos_outer) / (cos_inner - cos_outer);
    return f * t * t * (3.0 - 2.0 * t);
}

std::uint32_t hash_u32(std::uint32_t v) {
    std::uint32_t state = v * 747796405u + 2891336453u;
    std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

std::uint32_t camera_sample_seed(std::uint32_t x, std::uint32_t y, std::uint32_t k) {
    return hash_u32(hash_u32(hash_u32(x) ^ y) ^ k);
}

PassSample photon_pass_sample(std::uint32_t x, std::uint32_t y, std::uint32_t n, std::uint32_t pass) {
    std::uint32_t j = pass % (n * n), round = pass / (n * n);
    std::uint32_t seed = camera_sample_seed(x, y, j);
    double xi = 0.5, eta = 0.5;
    if (round > 0) {
        seed = hash_u32(seed ^ hash_u32(round));
        std::uint32_t g = hash_u32(seed);
        xi = unit_interval(g);
        eta = unit_interval(hash_u32(g));
    }
    return {(j % n + xi) / n, (j / n + eta) / n, seed};
}

int light_sample_count(const Light& light) { return light.type == LightType::Area ? light.samples * light.samples : 1; }

dvec3 light_sample_position(const Light& light, std::uint32_t index, int s, std::uint32_t seed) {
    if (light.type != LightType::Area) return light.position;
    const int n = light.samples;
    double du = 0.5, dv = 0.5;  // where in its cell: the centre, or hashed
    if (light.jitter) {
        std::uint32_t h = hash_u32(seed ^ hash_u32((index << 8) | std::uint32_t(s)));
        du = unit_interval(h);
        dv = unit_interval(hash_u32(h));
    }
    double a = (s % n + du) / n - 0.5;
    double b = (s / n + dv) / n - 0.5;
    return light.position + a * light.edge_u + b * light.edge_v;
}

dvec3 light_intensity(const Light& light, const dvec3& q, const dvec3& p, int count) {
    dvec3 c = light.emitted() / double(count);
    if (light.type == LightType::Spot) c *= spot_factor(light, glm::normalize(p - q));
    if (light.falloff == Falloff::InverseSquare) {
        double d = glm::length(p - q);
        c *= (light.falloff_distance * light.falloff_distance) / (d * d);
    } else if (light.falloff == Falloff::PovFade) {
        c *= 2.0 / (1.0 + std::pow(glm::length(p - q) / light.falloff_distance, light.fade_power));
    }
    return c;
}

}  // namespace lancer::cpu
