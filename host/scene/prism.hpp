#pragma once
// Building a prism (scene.hpp's Prism) from closed contours of 2-D Bezier segments: for the
// prism's reader (parse_prism.cpp, POV-Ray's splines converted to Bezier form) and for anything
// that makes outlines of its own (a font's glyphs: quadratic and cubic contours).
#include <stdexcept>
#include <vector>

#include "scene/scene.hpp"

namespace lancer {

// A ready prism: `segments` as closed contours (each segment starts exactly where the one before
// it ends, and each contour's last segment ends exactly at its first's start: contours follow one
// another in the list), extruded along y between the two heights (either order), capped unless
// `open`; its box and tree set (prepare_prism). Throws std::invalid_argument where a degree is
// not 1, 2 or 3, a number is not finite, a contour does not close, or the heights are equal.
Prism make_prism(std::vector<PrismSegment> segments, double height1, double height2, bool open = false);

// Sets what a prism keeps beside its segments: the outline's box and the tree over the segments'
// boxes (the CPU reference's). make_prism calls it; call it again after changing the segments.
void prepare_prism(Prism& o);

// Where the contours fail to close: the index of the first segment whose contour does not close,
// or -1 where all do (make_prism's check).
long prism_open_contour(const std::vector<PrismSegment>& segments);

}  // namespace lancer
