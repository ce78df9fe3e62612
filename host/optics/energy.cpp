#include "optics/energy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include <glm/geometric.hpp>

#include "optics/ggx.hpp"

namespace lancer::optics {
namespace {

// The quadrature over (u1, u2), the numbers that sample_visible_normal maps to the visible
// normals: E(mu) to about 1e-4 (against 4 times as many points). The integrand is smooth
// and periodic in u2, so fewer points suffice there.
constexpr int kPointsU1 = 128;
constexpr int kPointsU2 = 48;

// E(mu) = the mean over the normals wo sees of G2(wo, wi) / G1(wo), wi the mirror of wo about
// them (0 where wi points into the surface): the single-scattering albedo with Fresnel 1.
// GGX has long tails: the normals steep enough to send light into the surface, a share of about
// alpha^2, sit at u1 near 1, so u1 = 1 - (1 - t)^4 with t on a midpoint grid resolves them.
double albedo(double mu, double alpha) {
    mu = std::max(mu, 1e-4);  // the limit at grazing incidence
    dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
    double g1 = smith_g1(mu, alpha);
    double sum = 0.0;
    for (int i = 0; i < kPointsU1; ++i) {
        double t = (i + 0.5) / kPointsU1;
        double u1 = 1.0 - std::pow(1.0 - t, 4.0), weight = 4.0 * std::pow(1.0 - t, 3.0);
        double row = 0.0;
        for (int j = 0; j < kPointsU2; ++j) {
            dvec3 m = sample_visible_normal(wo, alpha, u1, (j + 0.5) / kPointsU2);
            dvec3 wi = 2.0 * glm::dot(wo, m) * m - wo;
            if (wi.z > 0.0) row += smith_g2(mu, wi.z, alpha);
        }
        sum += weight * row / g1;
    }
    return sum / (kPointsU1 * kPointsU2);
}

}  // namespace

double EnergyTable::at(double mu) const {
    double x = std::clamp(mu, 0.0, 1.0) * (kSize - 1);
    int i = std::min(static_cast<int>(x), kSize - 2);
    double f = x - i;
    return e[i] + f * (e[i + 1] - e[i]);
}

EnergyTable ggx_energy(double alpha) {
    // A table takes ~0.1 s; animations and the viewer ask for the same ones again and again.
    static std::mutex mutex;
    static std::map<double, EnergyTable> cache;
    std::lock_guard lock(mutex);
    if (auto found = cache.find(alpha); found != cache.end()) return found->second;
    EnergyTable t;
    for (int i = 0; i < EnergyTable::kSize; ++i) t.e[i] = std::min(1.0, albedo(double(i) / (EnergyTable::kSize - 1), alpha));
    // 2 int E(mu) mu dmu over each segment of the linear interpolant, exactly:
    // on [a, b] with E = e0 + (e1 - e0)(mu - a)/h, int E mu = h (e0 (2a + b) + e1 (a + 2b)) / 6.
    const double h = 1.0 / (EnergyTable::kSize - 1);
    double sum = 0.0;
    for (int i = 0; i + 1 < EnergyTable::kSize; ++i) {
        double a = i * h, b = (i + 1) * h;
        sum += h * (t.e[i] * (2.0 * a + b) + t.e[i + 1] * (a + 2.0 * b)) / 6.0;
    }
    t.e_avg = 2.0 * sum;
    cache.emplace(alpha, t);
    return t;
}

glm::dvec3 multiple_scattering_tint(const glm::dvec3& f_avg, double e_avg) {
    return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
}

glm::dvec3 conductor_fresnel_average(const glm::dvec3& eta, const glm::dvec3& k) {
    // Simpson's rule on 2 F(mu) mu over [0, 1]; F is smooth in mu.
    constexpr int n = 256;
    glm::dvec3 sum(0.0);
    for (int i = 0; i <= n; ++i) {
        double mu = double(i) / n;
        double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * 2.0 * mu * conductor_fresnel(mu, eta, k);
    }
    return sum / (3.0 * n);
}

}  // namespace lancer::optics
