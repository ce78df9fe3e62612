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
// With `conic`, POV-Ray's conic_sweep: the outline scaled by y (the heights must not lie on both
// sides of 0).
Prism make_prism(std::vector<PrismSegment> segments, double height1, double height2, bool open = false, bool conic = false);

// Sets what a prism keeps beside its segments: the outline's box and the tree over the segments'
// boxes (the CPU reference's). make_prism calls it; call it again after changing the segments.
void prepare_prism(Prism& o);

// The heights both backends trace between: the prism's, but a conic sweep's end at its apex (y = 0)
// moved 1e-7 of the other end toward it (the outline plane's image of y = 0 is at infinity): a
// sliver of the cone at its apex, 1e-7 of its height, is not drawn. cap0 and cap1: whether the
// ends at y0 and y1 have caps (not where open, nor at an apex).
void prism_walk_heights(const Prism& o, double& y0, double& y1, bool& cap0, bool& cap1);

// Where the contours fail to close: the index of the first segment whose contour does not close,
// or -1 where all do (make_prism's check).
long prism_open_contour(const std::vector<PrismSegment>& segments);

}  // namespace lancer
