// Light helpers of the scene model (scene.hpp).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.hpp"
#include "scene/scene.hpp"

namespace lancer {
namespace {

// The spot factor at angle theta from the axis (docs/scene-format.md, "type = spot").
double spot_at(const Light& l, double theta) {
    constexpr double kDegree = kPi / 180.0;
    double c = std::cos(theta);
    double cos_outer = std::cos(l.outer_angle_deg * kDegree);
    double cos_inner = std::cos(l.inner_angle_deg * kDegree);
    if (c <= 0.0 || c < cos_outer) return 0.0;
    double f = std::pow(c, l.tightness);
    if (c >= cos_inner) return f;
    double t = (c - cos_outer) / (cos_inner - cos_outer);
    return f * t * t * (3.0 - 2.0 * t);
}

}  // namespace

void aim_spot(Light& light) {
    if (light.type != LightType::Spot || !light.point_at) return;
    dvec3 axis = *light.point_at - light.position;
    if (glm::length(axis) > 0.0) light.direction = glm::normalize(axis);  // else keep the last direction
}

double spot_solid_angle(const Light& light) {
    // 2 pi int_0^outer spot(theta) sin(theta) dtheta by Simpson's rule; the integrand is smooth
    // apart from the cone's edges, where it is continuous (a hard edge, inner = outer, is a jump
    // at the last node, which the fine grid makes negligible: 1e-7 relative).
    const double outer = light.outer_angle_deg * kPi / 180.0;
    constexpr int n = 20000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        double theta = outer * i / n;
        double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * spot_at(light, std::min(theta, outer * (1.0 - 1e-12))) * std::sin(theta);
    }
    return 2.0 * kPi * sum * outer / (3.0 * n);
}

std::optional<dvec3> radiant_flux(const Light& light) {
    if (light.falloff != Falloff::InverseSquare) return std::nullopt;
    // Intensity (W/sr): pi times the colour at d0, times d0^2.
    dvec3 intensity = kPi * light.emitted() * light.falloff_distance * light.falloff_distance;
    double solid_angle = light.type == LightType::Spot ? spot_solid_angle(light) : 4.0 * kPi;
    return intensity * solid_angle;
}

}  // namespace lancer
