// Ray/blob (POV-Ray's blob) for the CPU reference, in double precision, written apart from
// shaders/shapes/blob.glsl.
//
// A component's field is s (1 - q)^2 where q = d^2 / r^2 < 1, d the distance to its segment
// [a, b] (a point for a sphere), and 0 beyond; f = threshold - (their sum). Along the ray
// o + sigma d, |d| = 1, a component's support (a capsule: convex) is one interval, which the
// segment's end planes cut into pieces where d^2 is a quadratic in sigma (the distance to a, to
// the axis, or to b). Between consecutive ends of these pieces over every component (a stretch)
// the active components are fixed and f is a quartic g(tau), tau in [-1, 1] over the stretch:
// its roots are isolated by Bernstein subdivision (cpu/shapes/bernstein_roots.hpp: certified, as
// the torus's), each found by bisection on the field summed directly. A touching point, or a run
// where g is 0 to rounding (a ray along a capsule's side), is one root. A stretch where even the
// positive components' largest fields fall short of the threshold is skipped unopened.
// A ray tests only the components in the leaves of the blob's own tree (Blob::tree, over their
// boxes) that its stretch passes through, each by a bounding ball first.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/bernstein_roots.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// A component seen from the ray o + sigma d: its offsets, its support's interval and where the
// ray crosses its end planes (NaN where it does not, within the support).
struct BlobPiece {
    const BlobComponent* k;
    dvec3 wa, wb;   // o - a, o - b
    dvec3 u{0.0};   // the unit axis from a to b (0 for a sphere)
    double length;  // |b - a|
    double r2;
    double enter, leave;
    double cross_a, cross_b;
};

// The ray with a unit direction: t = sigma / length.
struct BlobLine {
    dvec3 o, d;
    double length;
};

// The ray's interval within r of the point at offset w = o - c.
bool ball_span(const dvec3& w, const dvec3& d, double r2, double& s0, double& s1) {
    const double along = glm::dot(w, d);
    const dvec3 perp = w - along * d;  // r^2 - |perp|^2: no cancellation of along^2 - (|w|^2 - r^2)
    const double disc = r2 - glm::dot(perp, perp);
    if (!(disc >= 0.0)) return false;
    const double root = std::sqrt(disc);
    s0 = -along - root;
    s1 = -along + root;
    return true;
}

// q at a point whose offsets from a and b are ea and eb, and `away`, its offset from the
// segment's nearest point.
double blob_q(const BlobPiece& p, const dvec3& ea, const dvec3& eb, dvec3& away) {
    const double along = glm::dot(ea, p.u);
    if (p.length == 0.0 || along <= 0.0) away = ea;
    else if (along >= p.length) away = eb;
    else away = ea - along * p.u;
    return glm::dot(away, away) / p.r2;
}

// The component seen from o: its offsets and axis (no support yet).
BlobPiece blob_offsets(const BlobComponent& k, const dvec3& o) {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    BlobPiece p{&k, o - k.a, o - k.b, dvec3(0.0), glm::length(k.b - k.a), k.radius * k.radius, 0.0, -1.0, kNone, kNone};
    if (p.length > 0.0) p.u = (k.b - k.a) / p.length;
    return p;
}

BlobPiece blob_piece(const BlobComponent& k, const dvec3& o, const dvec3& d) {
    BlobPiece p = blob_offsets(k, o);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, s0, s1;
    auto join = [&] {
        lo = std::min(lo, s0);
        hi = std::max(hi, s1);
    };
    if (ball_span(p.wa, d, p.r2, s0, s1)) join();
    if (p.length > 0.0) {
        if (ball_span(p.wb, d, p.r2, s0, s1)) join();
        // The finite cylinder: within r of the axis, between the end planes.
        const double wu = glm::dot(p.wa, p.u), du = glm::dot(d, p.u);
        const dvec3 wp = p.wa - wu * p.u, dp = d - du * p.u;
        const double aa = glm::dot(dp, dp);
        bool body = true;
        s0 = -std::numeric_limits<double>::infinity();
        s1 = -s0;
        if (aa > 0.0) {
            const double middle = -glm::dot(wp, dp) / aa;
            const dvec3 nearest = wp + middle * dp;
            const double disc = (p.r2 - glm::dot(nearest, nearest)) / aa;
            body = disc >= 0.0;
            if (body) {
                s0 = middle - std::sqrt(disc);
                s1 = middle + std::sqrt(disc);
            }
        } else {
            body = glm::dot(wp, wp) < p.r2;
        }
        if (du != 0.0) {
            p.cross_a = -wu / du;
            p.cross_b = (p.length - wu) / du;
            s0 = std::max(s0, std::min(p.cross_a, p.cross_b));
            s1 = std::min(s1, std::max(p.cross_a, p.cross_b));
        } else {
            body = body && wu >= 0.0 && wu <= p.length;
        }
        if (body && s0 <= s1) join();
    }
    p.enter = lo;
    p.leave = hi;
    return p;
}

// Calls visit(component) for each component in a leaf of the tree whose box the line o + sigma d
// passes through within (s0, s1). The boxes hold their components exactly: each slab's exit is
// widened by its rounding, so that a line through a corner is not turned away.
template <class Visit>
void along_tree(const ElementTree& tree, const BlobLine& line, double s0, double s1, Visit&& visit) {
    constexpr double kWiden = 1e-12;
    std::vector<std::uint32_t> stack{0u};
    while (!stack.empty()) {
        const ElementTree::Node& n = tree.nodes[stack.back()];
        stack.pop_back();
        double enter = s0, leave = s1;
        for (int k = 0; k < 3 && enter <= leave; ++k) {
            if (line.d[k] == 0.0) {
                if (line.o[k] < n.lo[k] || line.o[k] > n.hi[k]) leave = -std::numeric_limits<double>::infinity();
                continue;
            }
            double a = (n.lo[k] - line.o[k]) / line.d[k], b = (n.hi[k] - line.o[k]) / line.d[k];
            if (a > b) std::swap(a, b);
            const double slack = kWiden * (std::abs(a) + std::abs(b)) + kWiden;
            enter = std::max(enter, a - slack);
            leave = std::min(leave, b + slack);
        }
        if (!(enter <= leave)) continue;
        if (n.count == 0) {
            stack.push_back(n.first);
            stack.push_back(n.first + 1);
            continue;
        }
        for (std::uint32_t e = n.first; e < n.first + n.count; ++e) visit(tree.order[e]);
    }
}

// The field's sum at o + sigma d over the pieces (the components whose support holds the point,
// and perhaps others, which add 0), and, if asked, -grad of it (outward).
double blob_field(const std::vector<const BlobPiece*>& pieces, const BlobLine& line, double sigma, dvec3* outward = nullptr) {
    double sum = 0.0;
    for (const BlobPiece* p : pieces) {
        dvec3 away;
        const double q = blob_q(*p, p->wa + sigma * line.d, p->wb + sigma * line.d, away);
        if (!(q < 1.0)) continue;
        sum += p->k->strength * (1.0 - q) * (1.0 - q);
        if (outward) *outward += (4.0 * p->k->strength * (1.0 - q) / p->r2) * away;
    }
    return sum;
}

struct BlobRoot {
    double t;
    dvec3 outward;  // -grad of the field there
};

// The roots along the ray with t in (t_min, t_max), nearest first (only the nearest, or all).
std::vector<BlobRoot> blob_roots(const Blob& o, const Ray& ray, double t_min, double t_max, bool nearest_only) {
    const double length = glm::length(ray.dir);
    if (!(length > 0.0)) return {};
    const BlobLine line{ray.origin, ray.dir / length, length};
    const double sigma_min = t_min * line.length, sigma_max = t_max * line.length;

    // The components the ray's stretch (sigma_min, sigma_max) meets, and the ends of their pieces.
    std::vector<BlobPiece> pieces;
    std::vector<double> ends;
    along_tree(*o.tree, line, sigma_min, sigma_max, [&](std::uint32_t index) {
        const BlobComponent& k = o.components[index];
        // A bounding ball about the segment's middle first.
        const dvec3 w = line.o - 0.5 * (k.a + k.b);
        const double reach = 0.5 * glm::length(k.b - k.a) + k.radius;
        const dvec3 perp = w - glm::dot(w, line.d) * line.d;
        if (glm::dot(perp, perp) > reach * reach * (1.0 + 1e-9)) return;
        const BlobPiece p = blob_piece(k, line.o, line.d);
        if (!(p.enter < p.leave) || p.leave <= sigma_min || p.enter >= sigma_max) return;
        pieces.push_back(p);
        ends.push_back(p.enter);
        ends.push_back(p.leave);
        for (double cross : {p.cross_a, p.cross_b})
            if (cross > p.enter && cross < p.leave) ends.push_back(cross);
    });
    if (pieces.empty()) return {};
    if (std::isfinite(sigma_min)) ends.push_back(sigma_min);
    if (std::isfinite(sigma_max)) ends.push_back(sigma_max);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());

    double total = o.threshold;  // the field's scale, for the quick test's slack
    for (const BlobPiece& p : pieces) total += std::abs(p.k->strength);

    std::vector<BlobRoot> roots;
    double run_end = 0.0, run_half = 0.0;  // where the last root's piece ends, and its stretch's half width
    std::vector<const BlobPiece*> active;
    for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
        const double lo = std::max(ends[e], sigma_min), hi = std::min(ends[e + 1], sigma_max);
        if (!(lo < hi)) continue;
        const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
        active.clear();
        for (const BlobPiece& p : pieces)
            if (p.enter < mid && mid < p.leave) active.push_back(&p);

        // g = threshold - sum s (A + B tau + C tau^2)^2, 1 - q = A + B tau + C tau^2 along the
        // active piece of each component: power coefficients, and the sums of their terms'
        // magnitudes. The upper bound of the field (its positive components at their least q)
        // skips a stretch where it cannot reach the threshold.
        bernstein::Quartic g{}, m{};
        g[0] = m[0] = o.threshold;
        double upper = 0.0;
        for (const BlobPiece* p : active) {
            const dvec3 ea = p->wa + mid * line.d;
            const double along = glm::dot(ea, p->u);
            dvec3 e, de = line.d;
            if (p->length == 0.0 || along <= 0.0) {
                e = ea;
            } else if (along >= p->length) {
                e = p->wb + mid * line.d;
            } else {  // the body: the parts across the axis
                e = ea - along * p->u;
                de = line.d - glm::dot(line.d, p->u) * p->u;
            }
            const double q0 = glm::dot(e, e) / p->r2, q1 = 2.0 * half * glm::dot(e, de) / p->r2,
                         q2 = half * half * glm::dot(de, de) / p->r2;
            const double A = 1.0 - q0, B = -q1, C = -q2, mA = 1.0 + q0;
            const double s = p->k->strength, as = std::abs(s);
            g[0] -= s * A * A;
            g[1] -= 2.0 * s * A * B;
            g[2] -= s * (B * B + 2.0 * A * C);
            g[3] -= 2.0 * s * B * C;
            g[4] -= s * C * C;
            m[0] += as * mA * mA;
            m[1] += 2.0 * as * mA * std::abs(B);
            m[2] += as * (B * B + 2.0 * mA * std::abs(C));
            m[3] += 2.0 * as * std::abs(B * C);
            m[4] += as * C * C;
            if (s > 0.0) {
                const double q_least = std::abs(q1) < 2.0 * q2 ? q0 - q1 * q1 / (4.0 * q2) : q0 - std::abs(q1) + q2;
                const double most = 1.0 - std::clamp(q_least, 0.0, 1.0);
                upper += s * most * most;
            }
        }
        if (upper < o.threshold - 1e-10 * total) continue;  // the slack covers q_least's rounding, generously

        const bernstein::Form bern = bernstein::from_power(g, m);
        // A few dozen roundings of the magnitudes per coefficient (the offsets, q, its square, two
        // changes of basis), and one more for each component summed.
        const double error = (256.0 + 8.0 * double(active.size())) * bernstein::kEpsilon * bern.magnitude;
        auto sigma = [&](double tau) { return mid + half * tau; };
        auto value = [&](double tau) { return o.threshold - blob_field(active, line, sigma(tau)); };
        auto accept = [&](double tau, double from, double to) {
            const double t = sigma(tau) / line.length;
            if (!(t > t_min && t < t_max)) return false;
            // Pieces told apart by no more than rounding are one root: a touching point's run of
            // pieces, and a root on the end between two stretches, found from both sides.
            const double slack = bernstein::kTouchingWidth * (run_half + half);
            if (!roots.empty() && sigma(from) <= run_end + slack) {
                run_end = std::max(run_end, sigma(to));
                run_half = half;
                return nearest_only;
            }
            dvec3 outward(0.0);
            blob_field(active, line, sigma(tau), &outward);
            roots.push_back({t, outward});
            run_end = sigma(to);
            run_half = half;
            return nearest_only;
        };
        if (bernstein::isolate(bern.c, -1.0, 1.0, error, value, accept, true)) break;
    }
    return roots;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Blob& o, const Ray& ray, double t_min, double t_max) {
    const std::vector<BlobRoot> roots = blob_roots(o, ray, t_min, t_max, true);
    if (roots.empty()) return std::nullopt;
    // Where the field's gradient vanishes there is no tangent plane: facing the ray, then.
    const double length = glm::length(roots.front().outward);
    const dvec3 normal = length > 0.0 ? roots.front().outward / length : -glm::normalize(ray.dir);
    return SurfaceHit{roots.front().t, normal};
}

std::vector<double> roots_on_line(const Blob& o, const Ray& ray) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    std::vector<double> roots;
    for (const BlobRoot& root : blob_roots(o, ray, -kInfinity, kInfinity, false)) roots.push_back(root.t);
    return roots;
}

// The field's sum above the threshold (the components in the tree's leaves that hold p).
bool inside(const Blob& o, const dvec3& p) {
    double sum = 0.0;
    along_tree(*o.tree, BlobLine{p, dvec3(1.0, 0.0, 0.0), 1.0}, 0.0, 0.0, [&](std::uint32_t index) {
        const BlobComponent& k = o.components[index];
        const BlobPiece piece = blob_offsets(k, p);
        dvec3 away;
        const double q = blob_q(piece, piece.wa, piece.wb, away);
        if (q < 1.0) sum += k.strength * (1.0 - q) * (1.0 - q);
    });
    return sum > o.threshold;
}

glm::dvec2 texture_uv(const Blob& o, const dvec3& p) {
    return {(p.x - o.lo.x) / (o.hi.x - o.lo.x), (p.y - o.lo.y) / (o.hi.y - o.lo.y)};
}

}  // namespace lancer::cpu
