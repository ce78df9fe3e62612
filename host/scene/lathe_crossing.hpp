#pragma once
// Whether a lathe's curve meets itself (parse_lathe.cpp refuses it): the lathe's normals face one
// way for the whole curve (its side, from the curve's signed area), so on a curve that crosses
// itself they face inward on the loops that turn the other way, and its inside is ambiguous.
#include <cstddef>
#include <optional>

#include <glm/vec2.hpp>

#include "scene/scene.hpp"

namespace lancer {

struct LatheSelfCrossing {
    std::size_t first = 0, second = 0;  // the two segments that meet, first <= second
    glm::dvec2 near{0.0};               // (r, y) near where they meet
    double crowded = 0.0;               // > 0: not checked, this many pairs overlap (over the limit)
};

// Where the lathe's curve (its segments, o.degree) meets itself other than where consecutive
// segments share their end and start, or where the last ends at the first's start (a closed
// curve); segments that are a single point are passed over, their neighbours joined through them.
// Linear: exact (segment against segment, exact orientation signs). Curved: each segment cut
// where r(s) or y(s) turns, pieces refined by Bezier subdivision until they are proved apart,
// proved to cross, or both under 1e-9 of the curve's size (then taken to meet). Candidate pairs
// come from a sweep over the pieces' boxes along the axis where fewer of them overlap; more than
// limits::kMaxLatheCrossingPairs of them give `crowded` instead.
std::optional<LatheSelfCrossing> find_lathe_crossing(const Lathe& o);

}  // namespace lancer
