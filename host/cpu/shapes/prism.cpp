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
#include "scene/prism.hpp"

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
    double s;  // along the outline plane's line
    double t;  // along the ray
    std::uint32_t segment;
    double u;
};

// The line q + s e in the outline plane, its normal n fixed by the caller (the same for both ways
// along one line, so that the sign convention is one). A linear sweep's is the ray's projection
// (t = t_q + s); a conic sweep's the ray's central projection from the apex onto y = 1 (the
// plane through the apex and the ray cut with y = 1), where t is where the ray meets the line
// from the apex through (B, 1): x0 + tau d parallel to (B.x, 1, B.z), t = t_q + tau.
struct PrismLine {
    dvec2 q, e, n;
    double t_q;
    bool conic = false;
    bool empty = false;     // no crossings beyond q (a conic sweep's q beyond the outline)
    dvec3 x0{0.0}, d{0.0};  // the ray's point at t_q and its direction (conic)
    double t_of(double s, const dvec2& b) const {
        if (!conic) return t_q + s;
        const dvec3 w(b.x, 1.0, b.y);
        const dvec3 dw = glm::cross(d, w);
        const double den = glm::dot(dw, dw);
        return den > 0.0 ? t_q - glm::dot(glm::cross(x0, w), dw) / den : t_q;
    }
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
        const dvec2 b = prism_point(seg, u);
        const dvec2 r = b - line.q;
        const double s = (line.e.x * r.x + line.e.y * r.y) / (line.e.x * line.e.x + line.e.y * line.e.y);
        if (!(s * way > 0.0)) continue;
        out.push_back({s, line.t_of(s, b), index, u});
    }
}

// Every crossing of the line beyond q in the direction `way`, through the tree.
void prism_crossings(const Prism& o, const PrismLine& line, double way, std::vector<PrismCrossing>& out) {
    if (!o.tree || (line.empty && way > 0.0)) return;
    const Ray walk{dvec3(line.q.x, 0.0, line.q.y), dvec3(way * line.e.x, 0.0, way * line.e.y)};
    double reach = kInfinity;
    walk_element_tree(*o.tree, walk, reach,
                      [&](std::uint32_t index, double&) { prism_segment_crossings(o, index, line, way, out); });
}

// Whether the outline holds the plane's point q: the parity of the half-line along +x.
bool prism_holds(const Prism& o, const dvec2& q) {
    PrismLine line{q, dvec2(1.0, 0.0), dvec2(0.0, 1.0), 0.0};
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, line, 1.0, crossings);
    return crossings.size() % 2 == 1;
}

// The outline plane's point of a point of the prism's space: (x, z), or for a conic sweep its
// central projection (x / y, z / y).
dvec2 prism_plane_point(const Prism& o, const dvec3& p) { return o.conic ? dvec2(p.x / p.y, p.z / p.y) : dvec2(p.x, p.z); }

// The ray's stretch through the slab (t_in, t_out); false where it misses it.
bool prism_slab(double y0, double y1, const Ray& ray, double& t_in, double& t_out) {
    if (ray.dir.y != 0.0) {
        const double a = (y0 - ray.origin.y) / ray.dir.y, b = (y1 - ray.origin.y) / ray.dir.y;
        t_in = std::min(a, b);
        t_out = std::max(a, b);
        return true;
    }
    t_in = -kInfinity;
    t_out = kInfinity;
    return ray.origin.y > y0 && ray.origin.y < y1;
}

// The outline plane's line of the ray from its point at `start` (in the slab), and the line's s
// at the ray's t_out (infinity where the ray does not leave the slab); false where the line is a
// point (a ray along y, or for a conic sweep along a line through the apex).
//
// A conic sweep's line: Q(tau) = (x0.xz + tau d.xz) / (x0.y + tau d.y) = q + s e, with
// e = d.xz x0.y - x0.xz d.y and s = tau / (x0.y (x0.y + tau d.y)), increasing with tau in the slab.
bool prism_line(const Prism& o, const Ray& ray, double start, double start_y, double t_out, double y_out, PrismLine& line,
                double& s_out) {
    dvec3 x0 = ray.origin + start * ray.dir;
    if (std::isfinite(start_y)) x0.y = start_y;  // on the entry cap exactly
    line.t_q = start;
    line.q = prism_plane_point(o, x0);
    line.e = dvec2(ray.dir.x, ray.dir.z);
    s_out = t_out - start;
    if (!o.conic) {
        line.n = dvec2(-line.e.y, line.e.x);
        const double scale = std::max({std::abs(line.q.x), std::abs(line.q.y), std::abs(o.lo.x), std::abs(o.lo.y), std::abs(o.hi.x),
                                       std::abs(o.hi.y)});
        return std::abs(line.e.x) + std::abs(line.e.y) > 1e-14 * scale;
    }
    line.conic = true;
    line.x0 = x0;
    line.d = ray.dir;
    // Near the apex q is far off (1 / y): the line is taken from the plane through the apex and the
    // ray instead (normal n3 = x0 x d: n3.x X + n3.z Z + n3.y = 0 at y = 1; e = (-n3.z, n3.x) is the
    // e above), walked from its point nearest the outline's box centre, or from q where q is
    // nearer than the box's reach (s then counted from there: s = sigma - sigma_start).
    const dvec3 n3 = glm::cross(x0, ray.dir);
    line.e = dvec2(-n3.z, n3.x);
    line.n = dvec2(-line.e.y, line.e.x);
    const double ee = glm::dot(line.e, line.e);
    if (!(ee > 1e-28 * glm::dot(x0, x0) * glm::dot(ray.dir, ray.dir))) return false;
    const dvec2 centre = 0.5 * (o.lo + o.hi), normal(n3.x, n3.z);
    const dvec2 foot = centre - ((glm::dot(normal, centre) + n3.y) / glm::dot(normal, normal)) * normal;
    const double sigma0 = glm::dot(line.q - foot, line.e) / ee;
    // Where the ray leaves the slab, from that point's own projection (its height exact): near the
    // apex one of q and it is far off and its sigma huge, but then only its side of the box counts.
    double sigma_out = sigma0 + s_out / (x0.y * x0.y);  // at a fixed height, s = tau / y^2
    if (ray.dir.y != 0.0) {
        dvec3 x1 = ray.origin + t_out * ray.dir;
        x1.y = y_out;
        sigma_out = glm::dot(prism_plane_point(o, x1) - foot, line.e) / ee;
    }
    const double reach = (0.5 * glm::length(o.hi - o.lo) * 1.01 + 1e-300) / std::sqrt(ee);
    if (sigma0 > reach) line.empty = true;  // the box lies behind: no crossings beyond q
    const double sigma_start = std::max(sigma0, -reach);
    line.q = foot + sigma_start * line.e;
    s_out = sigma_out - sigma_start;
    return true;
}

// The wall's outward normal at a crossing: for a linear sweep the tangent turned in the plane, for
// a conic sweep the cross product of the surface's tangents (B', 0) and (B, 1); facing against the
// ray where it enters (an odd count of crossings beyond it).
dvec3 prism_wall_normal(const Prism& o, const PrismCrossing& c, const dvec3& d, bool entering) {
    const PrismSegment& seg = o.segments[c.segment];
    const dvec2 tangent = prism_tangent(seg, c.u);
    dvec3 n(tangent.y, 0.0, -tangent.x);
    if (o.conic) {
        const dvec2 b = prism_point(seg, c.u);
        n = dvec3(tangent.y, tangent.x * b.y - tangent.y * b.x, -tangent.x);
    }
    n = glm::normalize(n);
    const bool faces_ray = glm::dot(n, d) < 0.0;
    if (faces_ray != entering) n = -n;
    return n;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Prism& o, const Ray& ray, double t_min, double t_max) {
    double y0, y1, t_in, t_out;
    bool cap0, cap1;
    prism_walk_heights(o, y0, y1, cap0, cap1);
    if (o.segments.empty() || !prism_slab(y0, y1, ray, t_in, t_out)) return std::nullopt;
    const double start = std::max(t_in, t_min), end = std::min(t_out, t_max);
    if (!(start < end)) return std::nullopt;
    // The caps the ray enters and leaves by, and their outward normals' y.
    const bool up = ray.dir.y > 0.0;
    const bool entry_cap = up ? cap0 : cap1, exit_cap = up ? cap1 : cap0;
    const double entry_y = up ? -1.0 : 1.0;
    PrismLine line;
    double s_out;
    const double entry_height = up ? y0 : y1, exit_height = up ? y1 : y0;
    if (!prism_line(o, ray, start, start == t_in ? entry_height : kInfinity, t_out, exit_height, line, s_out)) {
        // A point: no walls, the parity there.
        if (!prism_holds(o, line.q)) return std::nullopt;
        if (entry_cap && t_in > t_min) return SurfaceHit{t_in, dvec3(0.0, entry_y, 0.0)};
        if (exit_cap && t_out < t_max) return SurfaceHit{t_out, dvec3(0.0, -entry_y, 0.0)};
        return std::nullopt;
    }
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, line, 1.0, crossings);
    std::sort(crossings.begin(), crossings.end(), [](const PrismCrossing& a, const PrismCrossing& b) { return a.s < b.s; });
    if (entry_cap && t_in > t_min && crossings.size() % 2 == 1) return SurfaceHit{t_in, dvec3(0.0, entry_y, 0.0)};
    // The first wall: the nearest crossing whose t is beyond t_min (a conic sweep's t, from the
    // line through the apex, may round to the start where the ray starts on the wall).
    for (std::size_t k = 0; k < crossings.size() && crossings[k].s < s_out; ++k) {
        if (!(crossings[k].t > t_min)) continue;
        if (!(crossings[k].t < end)) break;
        const bool entering = (crossings.size() - 1 - k) % 2 == 1;
        return SurfaceHit{crossings[k].t, prism_wall_normal(o, crossings[k], ray.dir, entering)};
    }
    if (exit_cap && t_out < t_max) {
        const auto beyond = std::count_if(crossings.begin(), crossings.end(), [&](const PrismCrossing& c) { return c.s > s_out; });
        if (beyond % 2 == 1) return SurfaceHit{t_out, dvec3(0.0, -entry_y, 0.0)};
    }
    return std::nullopt;
}

std::vector<double> roots_on_line(const Prism& o, const Ray& ray) {
    double y0, y1, t_in, t_out;
    bool cap0, cap1;
    prism_walk_heights(o, y0, y1, cap0, cap1);
    if (o.segments.empty() || !prism_slab(y0, y1, ray, t_in, t_out)) return {};
    const bool up = ray.dir.y > 0.0;
    const bool entry_cap = up ? cap0 : cap1, exit_cap = up ? cap1 : cap0;
    std::vector<double> roots;
    // From the slab's entry (a horizontal line: from t = 0, both ways, with one normal).
    const double from = std::isfinite(t_in) ? t_in : 0.0;
    PrismLine line;
    double s_out;
    if (!prism_line(o, ray, from, std::isfinite(t_in) ? (up ? y0 : y1) : kInfinity, t_out, up ? y1 : y0, line, s_out)) {
        if (std::isfinite(t_in) && prism_holds(o, line.q)) {
            if (entry_cap) roots.push_back(t_in);
            if (exit_cap) roots.push_back(t_out);
        }
        return roots;
    }
    std::vector<PrismCrossing> crossings;
    prism_crossings(o, line, 1.0, crossings);
    const std::size_t ahead = crossings.size();
    if (!std::isfinite(t_in)) prism_crossings(o, line, -1.0, crossings);
    for (const PrismCrossing& c : crossings)
        if (c.s < s_out && (std::isfinite(t_in) || c.t > t_in)) roots.push_back(c.t);
    if (std::isfinite(t_in)) {
        if (entry_cap && ahead % 2 == 1) roots.push_back(t_in);
        const auto beyond = std::count_if(crossings.begin(), crossings.end(), [&](const PrismCrossing& c) { return c.s > s_out; });
        if (exit_cap && beyond % 2 == 1) roots.push_back(t_out);
    }
    std::sort(roots.begin(), roots.end());
    return roots;
}

bool inside(const Prism& o, const dvec3& p) {
    double y0, y1;
    bool cap0, cap1;
    prism_walk_heights(o, y0, y1, cap0, cap1);
    if (o.segments.empty() || !(p.y > y0 && p.y < y1)) return false;
    return prism_holds(o, prism_plane_point(o, p));
}

// POV-Ray's default, planar: (x, z) of the prism's own coordinates.
glm::dvec2 texture_uv(const Prism&, const dvec3& p) { return {p.x, p.z}; }

}  // namespace lancer::cpu
