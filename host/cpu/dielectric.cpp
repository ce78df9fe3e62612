#include "cpu/dielectric.hpp"

#include "cpu/ray.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lancer::cpu {

std::optional<std::uint32_t> Media::innermost() const {
    if (count_ == 0) return std::nullopt;
    return materials_[count_ - 1];
}

Media Media::crossed(std::uint32_t material) const {
    Media out = *this;
    for (std::size_t i = count_; i-- > 0;) {
        if (materials_[i] == material) {  // leaving it
            for (std::size_t j = i; j + 1 < count_; ++j) out.materials_[j] = materials_[j + 1];
            --out.count_;
            return out;
        }
    }
    if (out.count_ == kDepth) {  // full: forget the outermost
        for (std::size_t j = 0; j + 1 < kDepth; ++j) out.materials_[j] = out.materials_[j + 1];
        --out.count_;
    }
    out.materials_[out.count_++] = material;
    return out;
}

Fresnel fresnel(double cos_i, double n1, double n2) {
    double sin_i2 = 1.0 - cos_i * cos_i;
    double sin_t2 = (n1 / n2) * (n1 / n2) * sin_i2;
    if (sin_t2 >= 1.0) return {1.0, 0.0};
    double cos_t = std::sqrt(1.0 - sin_t2);
    // Fresnel's amplitude ratios for light polarised perpendicular (s) and parallel (p) to the
    // plane of incidence; unpolarised light reflects their mean power.
    double r_s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    double r_p = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
    return {(r_s * r_s + r_p * r_p) / 2.0, cos_t};
}

dvec3 refract(const dvec3& d, const dvec3& n, double eta, double cos_i, double cos_t) {
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

dvec3 crossing_direction(const dvec3& t, const dvec3& n) {
    const double above = glm::dot(t, n);
    return above > 0.0 ? t - 2.0 * above * n : t;
}

dvec3 beer_lambert(const dvec3& a, double distance) {
    dvec3 left(1.0);
    for (int c = 0; c < 3; ++c)
        if (a[c] > 0.0) left[c] = std::exp(-a[c] * distance);
    return left;
}

dvec3 past_surface(const dvec3& p, const dvec3& n, const dvec3& d, double offset) {
    return p + (offset / std::max(std::abs(glm::dot(d, n)), 0.01)) * d;
}

dvec3 past_surface(const Shape& shape, const dvec3& p, const dvec3& n, const dvec3& d, double offset) {
    if (!std::holds_alternative<Mesh>(shape)) return past_surface(p, n, d, offset);
    return p + (glm::dot(d, n) < 0.0 ? -offset : offset) * n;
}

bool is_thin_sheet(const Shape& shape) { return shape_has(shape_type(shape), SHAPE_SHEET); }

}  // namespace lancer::cpu
