// Ray/prism (POV-Ray's prism, linear sweep) for the CPU reference, in double precision, written
// apart from its GLSL.
//
// In the prism's own coordinates the outline lies in the x-z plane: closed contours of 2-D Bezier
// segments (degree 1, 2 or 3), extruded along y between y0 and y1, closed by the caps at y0 and
// y1 unless open. Inside is the even-odd rule: a point of the slab is inside where a half-line
// from it in the plane crosses the outline an odd number of times.
//
// Along the ray o + t d, the outline plane sees the line q + (t - t_q) e, e = (d.x, d.z). A
// segment B(u) meets it where f(u) = n . (B(u) - q) = 0, n = (-e.z, e.x): f is a Bezier of the
// segment's degree in u whose coefficients are n . (P_i - q), its roots isolated by Bernstein
// subdivision (cpu/shapes/bernstein_roots.hpp, the coefficients raised to degree 4), certified.
// The line crosses the outline where the side of the line the outline is on changes, 0 counted
// as positive: the sign of f is sampled at the segment's ends (the control points' own values,
// the same number from both segments that share a vertex) and between its roots, and each change
// is a crossing at the root between the samples. So a vertex on the line is counted once where
// the outline passes through the line there and not at all (or twice at one t) where it turns
// back, and a tangent point not at all: the parity is right for every line.
//
// One walk of the half-line from the ray's entry into the slab (or t_min, if later), through a
// tree over the segments' boxes (host/mesh/element_tree.hpp, the blob's), finds every crossing
// beyond it: the nearest is the first wall where it is before the slab's exit; their count's
// parity says whether the entry point is inside (a cap hit); the count beyond the exit, whether
// the exit point is. A ray along y sees the outline as a point: no walls, its parity from the
// half-line along +x. A wall's normal is the segment's tangent turned in the plane, outward by the
// parity beyond the hit (entering where the count beyond it is odd).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/bernstein_roots.hpp"
#include "cpu/shapes/element_walk.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

using glm::dvec2;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The segment's point at u (de Casteljau).
dvec2 prism_point(const PrismSegment& s, double u) {
    dvec2 w[4];
    for (int i = 0; i <= s.degree; ++i) w[i] = s.p[i];
    for (int k = 1; k <= s.degree; ++k)
        for (int i = 0; i + k <= s.degree; ++i) w[i] = (1.0 - u) * w[i] + u * w[i + 1];
    return w[0];
}

// Its derivative at u (the hodograph's de Casteljau); where it vanishes (a repeated end control
// point), the chord.
dvec2 prism_tangent(const PrismSegment& s, double u) {
    dvec2 w[3];
    for (int i = 0; i < s.degree; ++i) w[i] = double(s.degree) * (s.p[i + 1] - s.p[i]);
    for (int k = 1; k < s.degree; ++k)
        for (int i = 0; i + k < s.degree; ++i) w[i] = (1.0 - u) * w[i] + u * w[i + 1];
    if (w[0] != dvec2(0.0)) return w[0];
    return s.p[s.degree] - s.p[0];
}

// A value of a Bezier of degree `degree` with coefficients c at u (de Casteljau).
double prism_bezier_value(const double* c, int degree, double u) {
    double w[4];
    for (int i = 0; i <= degree; ++i) w[i] = c[i];
    for (int k = 1; k <= degree; ++k)
        for (int i = 0; i + k <= degree; ++i) w[i] = (1.0 - u) * w[i] + u * w[i + 1];
    return w[0];
}

struct PrismCrossing {
    double t;  // along the ray (the line's parameter)
    std::uint32_t segment;
    double u;
};

// The line q + s e in the plane (s = t - t_q), its normal n fixed by the caller (the same for both
// ways along one line, so that the sign convention is one).
struct PrismLine {
    dvec2 q, e, n;
    double t_q;
};

// The crossings of segment `index` with the line whose s is beyond 0 in the direction `way` (+1
// or -1), appended.
void prism_segment_crossings(const Prism& o, std::uint32_t index, const PrismLine& line, double way,
                             std::vector<PrismCrossing>& out) {
    const PrismSegment& seg = o.segments[index];
    const int deg = seg.degree;
    double c[4], mag[4];
    for (int i = 0; i <= deg; ++i) {
        const dvec2 r = seg.p[i] - line.q;
        c[i] = line.n.x * r.x + line.n.y * r.y;
        mag[i] = std::abs(line.n.x) * (std::abs(seg.p[i].x) + std::abs(line.q.x)) +
                 std::abs(line.n.y) * (std::abs(seg.p[i].y) + std::abs(line.q.y));
    }
    // Raised to degree 4 (exactly the same polynomial): b_j = sum_i C(deg, i) C(4 - deg, j - i) / C(4, j) c_i.
    static constexpr double kBinomial[5][5] = {{1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
    bernstein::Quartic b{};
    double magnitude = 0.0;
    for (int j = 0; j <= 4; ++j) {
        double sum = 0.0;
        for (int i = std::max(0, j - (4 - deg)); i <= std::min(deg, j); ++i)
            sum += kBinomial[deg][i] * kBinomial[4 - deg][j - i] / kBinomial[4][j] * c[i];
        b[j] = sum;
    }
    for (int i = 0; i <= deg; ++i) magnitude = std::max(magnitude, mag[i]);
    // A few roundings of the magnitudes per coefficient (the differences, the products, the raise).
    const double error = 32.0 * bernstein::kEpsilon * magnitude;
    std::vector<double> roots;
    auto value = [&](double u) { return prism_bezier_value(c, deg, u); };
    auto accept = [&](double u, double, double) {
        roots.push_back(u);
        return false;
    };
    bernstein::isolate(b, 0.0, 1.0, error, value, accept, true);
    // The sides at the ends and between the roots; each change is a crossing at the root between.
    std::vector<double> samples{0.0};
    for (std::size_t k = 0; k + 1 < roots.size(); ++k) samples.push_back(0.5 * (roots[k] + roots[k + 1]));
    samples.push_back(1.0);
    auto side = [&](std::size_t k) {
        if (k == 0) return c[0] >= 0.0;
        if (k + 1 == samples.size()) return c[deg] >= 0.0;
        return value(samples[k]) >= 0.0;
    };
    bool before = side(0);
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const bool after = side(k);
        if (after == before) continue;
        before = after;
        // The root between samples k - 1 and k (there is one where roots were found; else the
        // change is at an end where f is 0).
        double u = roots.empty() ? (c[0] == 0.0 ? 0.0 : 1.0) : roots[std::min(k - 1, roots.size() - 1)];
        const dvec2 r = prism_point(seg, u) - line.q;
        const double s = (line.e.x * r.x + line.e.y * r.y) / (line.e.x * line.e.x + line.e.y * line.e.y);
        if (!(s * way > 0.0)) continue;
        out.push_back({line.t_q + s, index, u});
    }
}

// Every crossing of the line beyond q in the direction `way`, through the tree.
void prism_crossings(const Prism& o, const PrismLine& line, double way, std::vector<PrismCrossing>& out) {
    if (!o.tree) return;
    const Ray walk{dvec3(line.q.x, 0.0, line.q.y), dvec3(way * line.e.x, 0.0, way * line.e.y)};
    double reach = kInfinity;
    walk_element_tree(*o.tree, walk, reach,
                      [&](std::uint32_t index, double&) { prism_segment_crossings(o, index, line, way, out); });
}

PrismLine prism_line(const Ray& ray, double t) {
    PrismLine line;
    line.t_q = t;
    line.q = dvec2(ray.origin.x + t * ray.dir.x, ray.origin.z + t * ray.dir.z);
    line.e = dvec2(ray.dir.x, ray.dir.z);
    line.n = dvec2(-line.e.y, line.e.x);
    return line;
}

// Whether the outline holds the plane's point q: the parity of the half-line along +x.
bool prism_holds(const Prism& o, const dvec2& q) {
    PrismLine line{q, dvec2(1.0, 0.0), dvec2(0.0, 1.0), 0.0};
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, line, 1.0, crossings);
    return crossings.size() % 2 == 1;
}

// The ray's stretch through the slab (t_in, t_out); false where it misses it.
bool prism_slab(const Prism& o, const Ray& ray, double& t_in, double& t_out) {
    if (ray.dir.y != 0.0) {
        const double a = (o.y0 - ray.origin.y) / ray.dir.y, b = (o.y1 - ray.origin.y) / ray.dir.y;
        t_in = std::min(a, b);
        t_out = std::max(a, b);
        return true;
    }
    t_in = -kInfinity;
    t_out = kInfinity;
    return ray.origin.y > o.y0 && ray.origin.y < o.y1;
}

bool prism_along_y(const Ray& ray) { return ray.dir.x == 0.0 && ray.dir.z == 0.0; }

// The wall's outward normal at a crossing: the tangent turned in the plane, facing against the
// ray where it enters (an odd count of crossings beyond it).
dvec3 prism_wall_normal(const Prism& o, const PrismCrossing& c, const dvec3& d, bool entering) {
    const dvec2 tangent = prism_tangent(o.segments[c.segment], c.u);
    dvec3 n = glm::normalize(dvec3(tangent.y, 0.0, -tangent.x));
    const bool faces_ray = glm::dot(n, d) < 0.0;
    if (faces_ray != entering) n = -n;
    return n;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Prism& o, const Ray& ray, double t_min, double t_max) {
    double t_in, t_out;
    if (o.segments.empty() || !prism_slab(o, ray, t_in, t_out)) return std::nullopt;
    const double start = std::max(t_in, t_min), end = std::min(t_out, t_max);
    if (!(start < end)) return std::nullopt;
    const double bottom_first = ray.dir.y > 0.0 ? -1.0 : 1.0;  // the entry cap's normal's y
    if (prism_along_y(ray)) {
        if (o.open || !prism_holds(o, dvec2(ray.origin.x, ray.origin.z))) return std::nullopt;
        if (t_in > t_min) return SurfaceHit{t_in, dvec3(0.0, bottom_first, 0.0)};
        if (t_out < t_max) return SurfaceHit{t_out, dvec3(0.0, -bottom_first, 0.0)};
        return std::nullopt;
    }
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, prism_line(ray, start), 1.0, crossings);
    std::sort(crossings.begin(), crossings.end(), [](const PrismCrossing& a, const PrismCrossing& b) { return a.t < b.t; });
    if (!o.open && t_in > t_min && crossings.size() % 2 == 1) return SurfaceHit{t_in, dvec3(0.0, bottom_first, 0.0)};
    if (!crossings.empty() && crossings.front().t < end) {
        const bool entering = (crossings.size() - 1) % 2 == 1;
        return SurfaceHit{crossings.front().t, prism_wall_normal(o, crossings.front(), ray.dir, entering)};
    }
    if (!o.open && t_out < t_max) {
        const auto beyond = std::count_if(crossings.begin(), crossings.end(), [&](const PrismCrossing& c) { return c.t > t_out; });
        if (beyond % 2 == 1) return SurfaceHit{t_out, dvec3(0.0, -bottom_first, 0.0)};
    }
    return std::nullopt;
}

std::vector<double> roots_on_line(const Prism& o, const Ray& ray) {
    double t_in, t_out;
    if (o.segments.empty() || !prism_slab(o, ray, t_in, t_out)) return {};
    std::vector<double> roots;
    if (prism_along_y(ray)) {
        if (!o.open && prism_holds(o, dvec2(ray.origin.x, ray.origin.z))) roots = {t_in, t_out};
        return roots;
    }
    // Both ways from a point of the slab, with one normal for the line.
    const double from = std::isfinite(t_in) ? t_in : 0.0;
    const PrismLine line = prism_line(ray, from);
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, line, 1.0, crossings);
    const std::size_t ahead = crossings.size();
    prism_crossings(o, line, -1.0, crossings);
    for (const PrismCrossing& c : crossings)
        if (c.t > t_in && c.t < t_out) roots.push_back(c.t);
    if (!o.open && std::isfinite(t_in)) {
        if (ahead % 2 == 1) roots.push_back(t_in);
        const auto beyond = std::count_if(crossings.begin(), crossings.begin() + std::ptrdiff_t(ahead),
                                          [&](const PrismCrossing& c) { return c.t > t_out; });
        if (beyond % 2 == 1) roots.push_back(t_out);
    }
    std::sort(roots.begin(), roots.end());
    return roots;
}

bool inside(const Prism& o, const dvec3& p) {
    if (o.segments.empty() || !(p.y > o.y0 && p.y < o.y1)) return false;
    return prism_holds(o, dvec2(p.x, p.z));
}

// POV-Ray's default, planar: (x, z) of the prism's own coordinates.
glm::dvec2 texture_uv(const Prism&, const dvec3& p) { return {p.x, p.z}; }

}  // namespace lancer::cpu
