#include "cpu/photon_map.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/constants.hpp"

namespace lancer::cpu {
KdTree::KdTree(std::vector<Photon> photons) : photons_(std::move(photons)), axis_(photons_.size(), 0) {
    build(0, photons_.size());
}

void KdTree::build(std::size_t lo, std::size_t hi) {
    if (hi - lo <= 1) return;
    // Split along the axis of the range's widest extent, at the median.
    dvec3 box_lo(INFINITY), box_hi(-INFINITY);
    for (std::size_t i = lo; i < hi; ++i) {
        box_lo = glm::min(box_lo, photons_[i].position);
        box_hi = glm::max(box_hi, photons_[i].position);
    }
    dvec3 extent = box_hi - box_lo;
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    std::size_t mid = (lo + hi) / 2;
    std::nth_element(photons_.begin() + lo, photons_.begin() + mid, photons_.begin() + hi,
                     [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
    axis_[mid] = static_cast<std::uint8_t>(axis);
    build(lo, mid);
    build(mid + 1, hi);
}

void KdTree::gather(std::size_t lo, std::size_t hi, const dvec3& p, const dvec3& n, double r2, dvec3& sum) const {
    while (hi > lo) {
        std::size_t mid = (lo + hi) / 2;
        const Photon& ph = photons_[mid];
        dvec3 d = ph.position - p;
        if (glm::dot(d, d) <= r2 && glm::dot(ph.direction, n) < 0.0) sum += ph.power;
        if (hi - lo == 1) return;
        int axis = axis_[mid];
        double delta = p[axis] - ph.position[axis];
        // Visit the side p is on; the other only if the sphere reaches across the plane.
        std::size_t near_lo = delta < 0.0 ? lo : mid + 1, near_hi = delta < 0.0 ? mid : hi;
        std::size_t far_lo = delta < 0.0 ? mid + 1 : lo, far_hi = delta < 0.0 ? hi : mid;
        if (delta * delta <= r2) gather(far_lo, far_hi, p, n, r2, sum);
        lo = near_lo;
        hi = near_hi;
    }
}

dvec3 KdTree::power_within(const dvec3& p, const dvec3& n, double radius) const {
    dvec3 sum(0.0);
    gather(0, photons_.size(), p, n, radius * radius, sum);
    return sum;
}

PhotonMaps::PhotonMaps(std::vector<Photon> caustic, std::vector<Photon> global, double caustic_radius,
                       double global_radius)
    : caustic_(std::move(caustic)), global_(std::move(global)), caustic_radius_(caustic_radius),
      global_radius_(global_radius) {}

dvec3 PhotonMaps::irradiance(const dvec3& p, const dvec3& n) const {
    dvec3 e(0.0);
    if (caustic_.size()) e += caustic_.power_within(p, n, caustic_radius_) / (kPi * caustic_radius_ * caustic_radius_);
    if (global_.size()) e += global_.power_within(p, n, global_radius_) / (kPi * global_radius_ * global_radius_);
    return e;
}

}  // namespace lancer::cpu
