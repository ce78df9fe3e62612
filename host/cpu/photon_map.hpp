#pragma once
// The CPU reference's photon maps: photons where they landed on diffuse surfaces, in a balanced
// kd-tree, and the density estimate of the irradiance at a point (Jensen, "Realistic image
// synthesis using photon mapping"). The GPU gathers from a hashed grid instead
// (shaders/photon_gather.glsl): different code, the same estimate.
#include <cstdint>
#include <vector>

#include "scene/scene.hpp"

namespace lancer::cpu {

struct Photon {
    dvec3 position;
    dvec3 direction;  // unit, the way it travelled
    dvec3 power;      // watts
};

// A kd-tree stored as the photons themselves in a permuted order: the median of each range
// [lo, hi) is at (lo + hi) / 2 and splits it along `axis`.
class KdTree {
public:
    KdTree() = default;
    explicit KdTree(std::vector<Photon> photons);

    // The sum of the power of the photons within `radius` of p that arrived on the side the unit
    // normal n faces (travelling against it).
    dvec3 power_within(const dvec3& p, const dvec3& n, double radius) const;

    std::size_t size() const { return photons_.size(); }

private:
    void build(std::size_t lo, std::size_t hi);
    void gather(std::size_t lo, std::size_t hi, const dvec3& p, const dvec3& n, double r2, dvec3& sum) const;

    std::vector<Photon> photons_;
    std::vector<std::uint8_t> axis_;  // per median: the split axis of its range
};

// A pass's two maps with their gather radii: the caustic map (light that reached the surface
// only through mirrors, glass and metals) and the global map (light that bounced off a diffuse
// surface before). Light that arrives straight from a light is left to shadow rays.
class PhotonMaps {
public:
    PhotonMaps(std::vector<Photon> caustic, std::vector<Photon> global, double caustic_radius, double global_radius);

    // The irradiance (W/m^2) at p on a surface facing n: the power within each map's radius,
    // over pi r^2.
    dvec3 irradiance(const dvec3& p, const dvec3& n) const;

private:
    KdTree caustic_, global_;
    double caustic_radius_, global_radius_;
};

}  // namespace lancer::cpu
