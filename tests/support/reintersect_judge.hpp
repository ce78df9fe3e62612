#pragma once
// The CPU reference's verdict on what the device's intersector answered for rays through one
// object, and for the rays it restarted from each hit (tests/render/reintersect_test.cpp).
// Everything is in the GPU's coordinates (relative to its anchor), in double, from the float
// values the device had.
//
// Verdicts, for every ray the device traced (the ray, and the two restarted from its hit):
//   bound      a hit point lies within its reported error bound of the reference's surface,
//              measured along the normal line through it (from both sides, so that a point
//              exactly on the surface is found too; where that line meets nothing, a point
//              within rounding of an edge, along the coordinate axes too);
//   nearest    the reference's nearest hit is not nearer than the device's, beyond the device's
//              error along the ray (error / |n.d|);
//   spurious   the device's hit is not nearer than the reference's, beyond the same: a restarted
//              ray that does so within kNearZero of its origin met the surface it left (re-hit);
//   missed     the device misses where the reference hits.
// nearest, spurious and missed are excused where the ray passes within float's reach of a
// silhouette or an edge: the reference's answer changes when the ray is moved sideways by
// kSilhouette of its magnitude (|origin| + t + the object's), or by twice the device's error
// bound. Re-hits are never excused. Rays excused are counted: at most 3% of each kind, 40% of
// the grazing ones (aimed near silhouettes on purpose).
// For each restarted origin:
//   offset     it is at most 3 times the hit's error bound off the hit point, along the normal of
//              the side it leaves to (2 bounds, plus the rounding of the origin, which the
//              bound exceeds);
//   clearance  the reference's surface (the crossing of the line back nearest to the hit point)
//              is between 1 and 4 error bounds behind it, along that normal: on the right side,
//              and clear of the hit's error. Judged where the origin is within 1e-4 of the
//              object's size of the hit point, so that the surface is flat between them.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/aabb.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/scene.hpp"

namespace lancer::test {

struct DeviceRay {
    dvec3 origin{0.0}, dir{0.0};
    double t = -1.0;  // < 0: no hit
    double error = 0.0;
    dvec3 normal{0.0};  // at the hit
};

struct DeviceHits {
    DeviceRay ray;  // origin and direction as the device had them
    bool cut_short = false;  // lavapipe ended the invocation early: nothing to judge
    dvec3 point{0.0};        // the hit point as the tracer computes it (float)
    DeviceRay leaving;       // restarted toward the side the ray came from
    DeviceRay through;       // restarted through the surface, in the ray's direction
};

class ReintersectJudge {
public:
    explicit ReintersectJudge(const Object& object);

    const Aabb& region() const { return region_; }  // the object's box (around a plane: a piece of it)
    double size() const { return size_; }            // the region's largest extent

    // The reference's nearest hit in (t_min, inf) of the ray from o along d (normalised here).
    std::optional<cpu::SurfaceHit> reference_hit(const dvec3& o, const dvec3& d, double t_min) const;

    // Judges one ray of kind `kind` (an index into the kinds the summary lists).
    void judge(const DeviceHits& h, std::size_t kind);

    std::string summary() const;
    // One test failure per check that failed, with its examples.
    void expect_all_pass(const std::string& name) const;

    int failures() const;

private:
    enum Check { Bound, Nearest, Spurious, Rehit, Missed, Offset, Clearance, kChecks };
    struct Tally {
        int rays = 0, hits = 0, cut_short = 0, excused = 0;
        int started_on_surface = 0;  // restarted rays not judged: the ray began within its hit's bound of the surface
        std::array<int, kChecks> failed{};
    };

    void judge_ray(const DeviceRay& r, bool restarted, std::size_t kind);
    void judge_origin(const dvec3& origin, const dvec3& side, const dvec3& point, double error, std::size_t kind,
                      const std::string& ray);
    double distance_to_surface(const dvec3& p, const dvec3& n, double reach) const;
    bool near_silhouette(const dvec3& o, const dvec3& d, double t_min, double t_scale, double error) const;
    void fail(Check check, std::size_t kind, const std::string& example);

    const Object& object_;
    Aabb region_;
    double size_ = 1.0;
    double magnitude_ = 1.0;  // the largest coordinate of the region
    std::vector<Tally> tallies_;
    std::array<std::vector<std::string>, kChecks> examples_;
    double worst_bound_ratio_ = 0.0;  // distance from the surface / error bound
    double worst_offset_ratio_ = 0.0;
    double least_clearance_ratio_ = 1e300, most_clearance_ratio_ = 0.0;
    std::vector<double> error_per_old_offset_;  // the hit's offset / the fixed rule's 1e-4 max(1, |p|)
};

}  // namespace lancer::test
