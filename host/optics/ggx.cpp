#include "optics/ggx.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <glm/geometric.hpp>

#include "core/constants.hpp"

namespace lancer::optics {
double ggx_distribution(double cos_m, double alpha) {
    if (cos_m <= 0.0) return 0.0;
    double a2 = alpha * alpha;
    double d = cos_m * cos_m * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

double ggx_lambda(double cos_theta, double alpha) {
    double c2 = cos_theta * cos_theta;
    if (c2 <= 0.0) return INFINITY;
    double tan2 = std::max(0.0, 1.0 - c2) / c2;
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

double smith_g1(double cos_theta, double alpha) { return 1.0 / (1.0 + ggx_lambda(cos_theta, alpha)); }

double smith_g2(double cos_o, double cos_i, double alpha) {
    return 1.0 / (1.0 + ggx_lambda(cos_o, alpha) + ggx_lambda(cos_i, alpha));
}

dvec3 sample_visible_normal(const dvec3& wo, double alpha, double u1, double u2) {
    // Stretch the view direction to the configuration of a hemisphere of unit roughness.
    dvec3 v = glm::normalize(dvec3(alpha * wo.x, alpha * wo.y, wo.z));
    // A basis around it, and a point on the disc it sees (the half facing away is squeezed
    // toward the edge as the visible part of the hemisphere's projection).
    double len2 = v.x * v.x + v.y * v.y;
    dvec3 t1 = len2 > 0.0 ? dvec3(-v.y, v.x, 0.0) / std::sqrt(len2) : dvec3(1.0, 0.0, 0.0);
    dvec3 t2 = glm::cross(v, t1);
    double r = std::sqrt(u1);
    double phi = 2.0 * kPi * u2;
    double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    double s = 0.5 * (1.0 + v.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    dvec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
    // Back to the surface's roughness.
    return glm::normalize(dvec3(alpha * n.x, alpha * n.y, std::max(0.0, n.z)));
}

double ggx_reflection(const dvec3& wo, const dvec3& wi, double alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    dvec3 h = glm::normalize(wo + wi);
    return ggx_distribution(h.z, alpha) * smith_g2(wo.z, wi.z, alpha) / (4.0 * wo.z * wi.z);
}

dvec3 conductor_fresnel(double cos_i, const dvec3& eta, const dvec3& k) {
    using complex = std::complex<double>;
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    double sin2_i = 1.0 - cos_i * cos_i;
    dvec3 out;
    for (int c = 0; c < 3; ++c) {
        complex n(eta[c], k[c]);
        complex cos_t = std::sqrt(1.0 - sin2_i / (n * n));  // Snell's law with a complex index
        // Amplitude ratios for light polarised parallel (p) and perpendicular (s) to the plane of
        // incidence; unpolarised light reflects their mean power.
        // Both denominators vanish only at grazing incidence on an index of exactly 1, where
        // there is no interface: nothing is reflected.
        complex p_den = n * cos_i + cos_t, s_den = cos_i + n * cos_t;
        if (std::norm(p_den) == 0.0 || std::norm(s_den) == 0.0) {
            out[c] = 0.0;
            continue;
        }
        complex r_p = (n * cos_i - cos_t) / p_den;
        complex r_s = (cos_i - n * cos_t) / s_den;
        out[c] = 0.5 * (std::norm(r_p) + std::norm(r_s));
    }
    return out;
}

}  // namespace lancer::optics
