#include "gpu/packing/family_boxes.hpp"

#include <algorithm>
#include <limits>

namespace lancer::gpu {
namespace {

// A family gets a box where it has at least this many members and its box's area is at most
// this share of the scene box's (the odds that a ray entering the scene box enters it): families
// of two, and the Cornell box's walls, took 1.05-1.14x the time with one.
constexpr std::size_t kMinBoxed = 3;
constexpr double kMaxAreaShare = 0.5;
// A boxed family of at least this many is cut in two: `seed`'s five spheres 0.97x the time; for
// three or four the second box test costs what the half saves.
constexpr std::size_t kMinSplit = 5;

Aabb bounds(std::span<const PrimitiveWithBox> members) {
    Aabb box;
    for (const auto& [p, b] : members) box.extend(*b);
    return box;
}

}  // namespace

FamilyBoxes box_family(std::span<PrimitiveWithBox> members, const Aabb& scene_box) {
    FamilyBoxes family;
    const std::size_t n = members.size();
    if (n < kMinBoxed || !std::all_of(members.begin(), members.end(), [](const auto& m) { return m.second.has_value(); }))
        return family;
    const Aabb whole = bounds(members);
    if (!(whole.surface_area() <= kMaxAreaShare * scene_box.surface_area())) return family;
    family.boxed = true;
    family.halves = {whole, Aabb{}};
    family.split_at = static_cast<uint>(n);
    if (n < kMinSplit) return family;
    // Along the longest axis, the cut of least area times count (the surface area heuristic).
    const glm::dvec3 extent = whole.extent();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::stable_sort(members.begin(), members.end(),
                     [&](const auto& a, const auto& b) { return a.second->center()[axis] < b.second->center()[axis]; });
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < n; ++k) {
        const Aabb left = bounds(members.first(k)), right = bounds(members.subspan(k));
        const double cost = left.surface_area() * double(k) + right.surface_area() * double(n - k);
        if (cost < best) {
            best = cost;
            family.halves = {left, right};
            family.split_at = static_cast<uint>(k);
        }
    }
    family.split = true;
    return family;
}

}  // namespace lancer::gpu
