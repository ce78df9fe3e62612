#include "scene/prism.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace lancer {

long prism_open_contour(const std::vector<PrismSegment>& segments) {
    std::size_t first = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const bool last_of_contour = i + 1 == segments.size() || segments[i + 1].start() != segments[i].end();
        if (!last_of_contour) continue;
        if (segments[i].end() != segments[first].start()) return static_cast<long>(first);
        first = i + 1;
    }
    return -1;
}

void prism_walk_heights(const Prism& o, double& y0, double& y1, bool& cap0, bool& cap1) {
    y0 = o.y0;
    y1 = o.y1;
    cap0 = cap1 = !o.open;
    if (!o.conic) return;
    if (y0 == 0.0) {
        y0 = 1e-7 * y1;
        cap0 = false;
    }
    if (y1 == 0.0) {
        y1 = 1e-7 * y0;
        cap1 = false;
    }
}

void prepare_prism(Prism& o) {
    o.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    o.hi = -o.lo;
    for (const PrismSegment& s : o.segments)
        for (int i = 0; i <= s.degree; ++i) {
            o.lo = glm::min(o.lo, s.p[i]);
            o.hi = glm::max(o.hi, s.p[i]);
        }
    // Each segment's box (its control points' hull holds it), in x and z, widened by a little of the
    // outline's size; y spans [-1, 1]: the reference walks the outline's plane along y = 0.
    const double size = std::max({std::abs(o.lo.x), std::abs(o.lo.y), std::abs(o.hi.x), std::abs(o.hi.y), 1e-300});
    const double pad = 1e-9 * size;
    o.tree = std::make_shared<const ElementTree>(
        build_element_tree(static_cast<std::uint32_t>(o.segments.size()), [&](std::uint32_t k, glm::dvec3& lo, glm::dvec3& hi) {
            const PrismSegment& s = o.segments[k];
            for (int i = 0; i <= s.degree; ++i) {
                lo = glm::min(lo, glm::dvec3(s.p[i].x - pad, -1.0, s.p[i].y - pad));
                hi = glm::max(hi, glm::dvec3(s.p[i].x + pad, 1.0, s.p[i].y + pad));
            }
        }));
}

Prism make_prism(std::vector<PrismSegment> segments, double height1, double height2, bool open, bool conic) {
    if (segments.empty()) throw std::invalid_argument("a prism needs at least one segment");
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const PrismSegment& s = segments[k];
        if (s.degree < 1 || s.degree > 3)
            throw std::invalid_argument("prism segment " + std::to_string(k) + ": degree " + std::to_string(s.degree) +
                                        " (1, 2 or 3)");
        for (int i = 0; i <= s.degree; ++i)
            if (!std::isfinite(s.p[i].x) || !std::isfinite(s.p[i].y))
                throw std::invalid_argument("prism segment " + std::to_string(k) + ": a control point is not finite");
    }
    if (const long open_at = prism_open_contour(segments); open_at >= 0)
        throw std::invalid_argument("prism: the contour from segment " + std::to_string(open_at) +
                                    " does not close (its last segment must end exactly where its first starts)");
    if (!std::isfinite(height1) || !std::isfinite(height2) || height1 == height2)
        throw std::invalid_argument("prism: the heights must be finite and differ");
    if (conic && height1 * height2 < 0.0)
        throw std::invalid_argument("prism: a conic sweep's heights must not lie on both sides of 0 (its apex)");
    Prism o;
    o.segments = std::move(segments);
    o.y0 = std::min(height1, height2);
    o.y1 = std::max(height1, height2);
    o.open = open;
    o.conic = conic;
    prepare_prism(o);
    return o;
}

}  // namespace lancer
