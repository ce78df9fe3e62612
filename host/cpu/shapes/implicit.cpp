// Ray / implicit surface f(x, y, z) = 0 for the CPU reference, in double precision.
//
// The ray is carried into the surface's coordinates (the transform is affine, so t is kept) and
// clipped to its box: the roots of g(t) = f(o + t d) on that segment are the hits.
//   * f a polynomial of degree n: g is a polynomial of degree <= n. Its coefficients come from
//     the expansion with t re-centred and scaled to [-1, 1] on the segment; its roots are the
//     eigenvalues of the balanced companion matrix (polynomial_roots). Each real one (and each
//     complex one within 1e-3 of the real axis, which a near-double root may become) is polished
//     by Newton's method on f itself and then certified on [t - e, t + e] by interval arithmetic.
//   * any other f: interval Newton on the segment, front to back: a piece where the enclosure
//     of g (natural extension, narrowed by the mean-value form) excludes 0 has no root; where g'
//     excludes 0, N(T) = m - g(m) / g'(T) excludes roots outside N(T) and, when N(T) lies inside
//     T, proves exactly one root in T, which further Newton steps enclose to width e.
// Certificates (e = kRootBound of the box's diagonal, along the ray):
//   * a simple root is reported only when proved: by a sign change of g between t - e and t + e
//     (f continuous there), or by interval Newton's inclusion; it is then within e of a true root;
//   * where nothing can be proved but the enclosure of g over a piece of width e contains 0 (the
//     ray touches the surface: a double root; or passes through a singular point, or within
//     rounding of either), the point is reported as a hit. Both backends count a touching ray as
//     a hit (docs/scene-format.md).
// This shares nothing with the GPU's intersector beyond the expression's evaluation.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "cpu/shapes/polynomial_roots.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

using surface::Dual;
using surface::ImplicitSurface;
using surface::Interval;

constexpr double kRootBound = 1e-10;   // of the box's diagonal (along the ray): a root's certified accuracy
constexpr double kNearReal = 1e-3;     // eigenvalues this close to the real axis are candidates (t scaled to [-1, 1])
constexpr double kCluster = 1e-6;      // real eigenvalues this close may be a double root split by rounding
constexpr int kMaxIntervalSteps = 20000;  // per ray, all searches together; a pathological ray ends with what it found so far
constexpr double kRootGuard = 4.0;        // root bounds on each side of a found root left to its certificate
constexpr double kTouchingGuard = 1e-6;   // of the segment on each side of a touching point: the same point
constexpr double kGapPiece = 16.0;        // root bounds: a piece this short goes to interval Newton on f
constexpr int kGapLevels = 12;            // halvings of a gap before its pieces go to interval Newton on f
constexpr double kCoefficientRounding = 1e-12;  // of the magnitudes' sum: the restricted coefficients' rounding, with margin

// The ray in the surface's coordinates, from a base point on it: x(s) = o + s d, s = t - base.
struct ImplicitRay {
    dvec3 o, d;
    double base;
};

// g and g' at s (double).
Dual<double> along(const ImplicitSurface& f, const ImplicitRay& r, double s) {
    const Dual<double> x[] = {{r.o.x + s * r.d.x, r.d.x, 0.0}, {r.o.y + s * r.d.y, r.d.y, 0.0},
                              {r.o.z + s * r.d.z, r.d.z, 0.0}};
    Dual<double> g;
    surface::evaluate_program<Dual<double>>(f.program, x, &g);
    return g;
}

Interval coordinate(double o, double d, const Interval& s) { return Interval(o) + Interval(d) * s; }

// An enclosure of g over S.
Interval along(const ImplicitSurface& f, const ImplicitRay& r, const Interval& s) {
    const Interval x[] = {coordinate(r.o.x, r.d.x, s), coordinate(r.o.y, r.d.y, s), coordinate(r.o.z, r.d.z, s)};
    Interval g;
    surface::evaluate_program<Interval>(f.program, x, &g);
    return g;
}

// Enclosures of g and g' over S; true when f is proved defined and smooth all along S.
bool along_smooth(const ImplicitSurface& f, const ImplicitRay& r, const Interval& s, Dual<Interval>& g) {
    const Dual<Interval> x[] = {{coordinate(r.o.x, r.d.x, s), Interval(r.d.x), Interval(0.0)},
                                {coordinate(r.o.y, r.d.y, s), Interval(r.d.y), Interval(0.0)},
                                {coordinate(r.o.z, r.d.z, s), Interval(r.d.z), Interval(0.0)}};
    return surface::evaluate_program_on_box(f.program, x, &g);
}

class RootFinder {
public:
    // Roots with s in [s0, s1] (the box) and t = base + s in (t_min, t_max).
    RootFinder(const ImplicitSurface& f, const ImplicitRay& r, double s0, double s1, double t_min, double t_max, double e,
               bool all)
        : f_(f), r_(r), s0_(s0), s1_(s1), t_min_(t_min), t_max_(t_max), e_(e), all_(all) {}

    std::vector<ImplicitRoot> run() {
        if (f_.polynomial) {
            by_eigenvalues();
            verify_the_gaps();
        } else {
            by_interval_newton(s0_, s1_);
        }
        // The eigenvalues' candidates are in order, but polishing may carry one past the next
        // (near a root of high multiplicity): nearest first, each root once, and for a first
        // hit the nearest of all.
        std::sort(roots_.begin(), roots_.end(), [](const ImplicitRoot& a, const ImplicitRoot& b) { return a.t < b.t; });
        std::vector<ImplicitRoot> roots;
        for (const ImplicitRoot& root : roots_)
            if (roots.empty() || root.t - roots.back().t > e_) roots.push_back(root);
        if (!all_ && roots.size() > 1) roots.erase(roots.begin() + 1, roots.end());
        return roots;
    }

private:
    void report(double s, RootKind kind) {
        s = std::clamp(s, s0_, s1_);
        const double t = r_.base + s;
        if (!(t > t_min_ && t < t_max_)) return;
        if (!roots_.empty() && std::abs(t - roots_.back().t) <= e_) return;  // found twice
        roots_.push_back({t, kind});
    }
    bool done() const { return !all_ && !roots_.empty(); }

    // The certificate of a candidate root s, if it has one.
    std::optional<RootKind> certify(double s) const {
        const Interval piece{s - e_, s + e_};
        Dual<Interval> g;
        const bool smooth = along_smooth(f_, r_, piece, g);
        const Interval before = along(f_, r_, Interval(piece.lo)), after = along(f_, r_, Interval(piece.hi));
        if (smooth && ((before.hi < 0.0 && after.lo > 0.0) || (before.lo > 0.0 && after.hi < 0.0)))
            return RootKind::Simple;
        if (g.v.contains_zero()) return RootKind::Touching;
        return std::nullopt;
    }

    // Newton's method on g from s; s itself when it does not settle close by (a near-double root
    // pulls Newton away slowly; the unpolished eigenvalue is then as good as it gets).
    double polish(double s, double reach) const {
        double x = s;
        for (int i = 0; i < 24; ++i) {
            Dual<double> g = along(f_, r_, x);
            if (!std::isfinite(g.v) || !std::isfinite(g.du) || g.du == 0.0 || g.v == 0.0) break;
            double next = x - g.v / g.du;
            if (!(std::abs(next - s) <= reach)) return s;
            if (std::abs(next - x) <= 1e-15 * (std::abs(x) + reach)) return next;
            x = next;
        }
        return x;
    }

    void by_eigenvalues() {
        const double centre = 0.5 * (s0_ + s1_), half = 0.5 * (s1_ - s0_);
        if (!(half > 0.0)) {
            if (auto kind = certify(centre)) report(centre, *kind);
            return;
        }
        // g(centre + half * tau) for tau in [-1, 1].
        std::vector<double> c = surface::restrict_to_line(*f_.polynomial, r_.o + centre * r_.d, half * r_.d);
        coeffs_ = c;
        centre_ = centre;
        half_ = half;
        std::vector<double> taus;
        for (const ComplexRoot& z : polynomial_roots(c))
            if (std::abs(z.im) <= kNearReal && std::abs(z.re) <= 1.0 + kNearReal) taus.push_back(z.re);
        std::sort(taus.begin(), taus.end());
        // A double root (a touching ray, a singular point) is only as good as sqrt(rounding) in
        // each of its two eigenvalues, but their mean is good to rounding: it is a candidate too
        // (a complex pair's real part already is that mean).
        std::vector<double> candidates;
        for (std::size_t i = 0; i < taus.size(); ++i) {
            if (i > 0 && taus[i] - taus[i - 1] <= kCluster) candidates.push_back(centre + half * 0.5 * (taus[i - 1] + taus[i]));
            candidates.push_back(centre + half * taus[i]);
        }
        std::sort(candidates.begin(), candidates.end());
        auto inside = [&](double s) { return s >= s0_ - e_ && s <= s1_ + e_; };
        for (double s : candidates) {
            // The polished root when it is proved simple, else the eigenvalue itself when it is a
            // touching point (Newton creeps toward a double root and stalls in rounding noise).
            const double polished = polish(s, 1e-3 * half);
            std::optional<RootKind> kind = inside(polished) ? certify(polished) : std::nullopt;
            if (kind == RootKind::Simple) {
                report(polished, *kind);
            } else if (auto raw = inside(s) ? certify(s) : std::nullopt) {
                report(s, *raw);
            } else if (kind) {
                report(polished, *kind);
            }
        }
    }

    // The eigenvalues of a companion matrix are not certified: clustered or many roots (a
    // polynomial of high degree) can leave a real root's eigenvalue off the real axis, and that
    // root would be missed. Unless Descartes' rule shows none is missing, every stretch of the
    // segment the eigenvalues left without a root (before the nearest, for a first hit) is
    // searched again, missing nothing: a piece is dropped only where the polynomial's Taylor
    // bound about its middle keeps it away from 0 by more than its coefficients' rounding allows;
    // a piece of a few root bounds that is not goes to interval Newton on f itself. Each root
    // found keeps kRootGuard root bounds clear on each side, where its own neighbourhood cannot
    // be excluded.
    void verify_the_gaps() {
        std::sort(roots_.begin(), roots_.end(), [](const ImplicitRoot& a, const ImplicitRoot& b) { return a.t < b.t; });
        if (descartes_agrees()) return;
        const std::vector<ImplicitRoot> found = roots_;
        double from = s0_;
        for (const ImplicitRoot& root : found) {
            const double s = root.t - r_.base;
            // Around a touching point g stays within rounding of 0 over about the square root of
            // the rounding: that whole stretch is the one point.
            const double guard = root.kind == RootKind::Simple ? kRootGuard * e_ : kTouchingGuard * (s1_ - s0_);
            if (s - guard > from) search_gap(from, s - guard);
            if (done() && roots_.size() > found.size()) return;  // a nearer first hit
            if (!all_) return;
            from = std::max(from, s + guard);
        }
        if (from < s1_ && (all_ || found.empty())) search_gap(from, s1_);
    }

    // The cheap certificate that usually makes the search unneeded: Descartes' rule on the
    // Bernstein coefficients of g over the segment, whose sign variations bound its roots there
    // (with multiplicity). As many as the roots the eigenvalues gave, and none is missing. A
    // coefficient within its rounding of 0 (the conversion amplifies the coefficients' rounding
    // by binomials and powers of 2, so high degrees rarely pass) leaves the question to the search.
    bool descartes_agrees() const {
        const std::size_t n = coeffs_.size();
        if (n == 0) return false;
        std::size_t multiplicity = 0;  // a touching point is a double root
        for (const ImplicitRoot& root : roots_) {
            const double tau = (root.t - r_.base - centre_) / half_;
            if (!(tau > -1.0 && tau < 1.0)) return false;
            multiplicity += root.kind == RootKind::Simple ? 1 : 2;
        }
        // tau = 2x - 1: the coefficients in x, then the Bernstein coefficients over x in [0, 1];
        // the same sums of magnitudes bound their rounding.
        const std::size_t degree = n - 1;
        thread_local std::vector<double> a, a_mag;
        a.assign(n, 0.0);
        a_mag.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            double binomial = 1.0;  // C(i, k)
            for (std::size_t k = 0; k <= i; ++k) {
                const double term = coeffs_[i] * binomial * std::ldexp(((i - k) & 1) ? -1.0 : 1.0, int(k));
                a[k] += term;
                a_mag[k] += std::abs(term);
                binomial = binomial * double(i - k) / double(k + 1);
            }
        }
        std::size_t variations = 0;
        int sign = 0;
        for (std::size_t j = 0; j < n; ++j) {
            double b = 0.0, b_mag = 0.0, c_jk = 1.0, c_nk = 1.0;  // C(j, k), C(degree, k)
            for (std::size_t k = 0; k <= j; ++k) {
                b += c_jk / c_nk * a[k];
                b_mag += c_jk / c_nk * a_mag[k];
                c_jk = c_jk * double(j - k) / double(k + 1);
                c_nk = c_nk * double(degree - k) / double(k + 1);
            }
            if (std::abs(b) <= kCoefficientRounding * b_mag) return false;
            const int s = b > 0.0 ? 1 : -1;
            variations += sign != 0 && s != sign;
            sign = s;
        }
        return variations == multiplicity;
    }

    // Front to back: pieces the Taylor bound cannot exclude are split, down to kGapLevels halvings
    // or a few root bounds, and then searched by interval Newton on f (which, unlike the bound,
    // does not suffer the cancellation among the coefficients of a polynomial of high degree).
    void search_gap(double from, double to) {
        struct Piece {
            double a, b;
            int level;
        };
        thread_local std::vector<Piece> stack;
        stack.assign(1, {from, to, 0});
        const std::size_t before = roots_.size();
        while (!stack.empty() && steps_left_ > 0 && !(done() && roots_.size() > before)) {
            --steps_left_;
            const Piece p = stack.back();
            stack.pop_back();
            if (excluded_by_taylor(p.a, p.b)) continue;
            if (p.level >= kGapLevels || p.b - p.a <= kGapPiece * e_) {
                by_interval_newton(p.a, p.b);
                continue;
            }
            const double m = 0.5 * (p.a + p.b);
            stack.push_back({m, p.b, p.level + 1});
            stack.push_back({p.a, m, p.level + 1});
        }
    }

    // Whether g has no root on [a, b], by the restricted polynomial's Taylor expansion about the
    // middle: |g(m)| > sum |g^(k)(m)| / k! r^k, beyond an allowance for the coefficients'
    // rounding (kCoefficientRounding of the same sums of magnitudes).
    bool excluded_by_taylor(double a, double b) const {
        const std::size_t n = coeffs_.size();
        if (n == 0) return false;
        const double m = (0.5 * (a + b) - centre_) / half_, r = 0.5 * (b - a) / half_;
        thread_local std::vector<double> d, mag;
        d.assign(coeffs_.begin(), coeffs_.end());
        mag.resize(n);
        for (std::size_t i = 0; i < n; ++i) mag[i] = std::abs(coeffs_[i]);
        // Repeated synthetic division by (tau - m): d[k] becomes g's k-th Taylor coefficient at m.
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t i = n - 1; i > k; --i) {
                d[i - 1] += m * d[i];
                mag[i - 1] += std::abs(m) * mag[i];
            }
        double spread = 0.0, scale = mag[0], rk = 1.0;
        for (std::size_t k = 1; k < n; ++k) {
            rk *= r;
            spread += std::abs(d[k]) * rk;
            scale += mag[k] * rk;
        }
        return std::abs(d[0]) > spread + kCoefficientRounding * scale;
    }

    // Front to back over [from, to]: the piece on top of the stack is always the nearest one left.
    void by_interval_newton(double from, double to) {
        thread_local std::vector<Interval> stack;
        stack.assign(1, Interval{from, to});
        const std::size_t before = roots_.size();
        for (; !stack.empty() && steps_left_ > 0 && !(done() && roots_.size() > before); --steps_left_) {
            Interval piece = stack.back();
            stack.pop_back();
            Dual<Interval> g;
            const bool smooth = along_smooth(f_, r_, piece, g);
            if (g.v.is_empty()) continue;  // f undefined all along the piece
            const double m = piece.mid();
            const Interval gm = along(f_, r_, Interval(m));
            Interval value = g.v;
            const bool newton = smooth && g.du.is_finite() && !gm.is_empty() && gm.is_finite();
            if (newton) value = intersect(value, gm + g.du * (piece - Interval(m)));  // the mean-value form
            if (value.is_empty() || !value.contains_zero()) continue;
            if (piece.width() <= e_) {
                // Pieces in a row where the ray touches the surface (f within rounding of 0 all
                // along) are one touching point: the nearest.
                if (!(touching_until_ >= piece.lo)) report(m, RootKind::Touching);
                touching_until_ = piece.hi;
                continue;
            }
            if (newton && !g.du.contains_zero()) {
                Interval n = Interval(m) - gm / g.du;
                if (n.lo > piece.lo && n.hi < piece.hi) {
                    report(enclose_unique_root(n), RootKind::Simple);
                    continue;
                }
                Interval next = intersect(n, piece);
                if (next.is_empty()) continue;
                if (next.width() <= 0.5 * piece.width()) {
                    stack.push_back(next);
                    continue;
                }
            }
            stack.push_back({m, piece.hi});
            stack.push_back({piece.lo, m});
        }
    }

    // Interval Newton from a piece proved to hold exactly one root, down to width e (or to where
    // rounding stops it shrinking); the root is within the returned point's piece.
    double enclose_unique_root(Interval piece) const {
        for (int i = 0; i < 64 && piece.width() > e_; ++i) {
            Dual<Interval> g;
            along_smooth(f_, r_, piece, g);
            const double m = piece.mid();
            Interval next = intersect(Interval(m) - along(f_, r_, Interval(m)) / g.du, piece);
            if (next.is_empty() || !(next.width() < piece.width())) break;
            piece = next;
        }
        return piece.mid();
    }

    const ImplicitSurface& f_;
    const ImplicitRay& r_;
    double s0_, s1_, t_min_, t_max_, e_;
    bool all_;
    std::vector<ImplicitRoot> roots_;
    std::vector<double> coeffs_;  // g(centre_ + half_ tau), by_eigenvalues' restriction
    int steps_left_ = kMaxIntervalSteps;
    double centre_ = 0.0, half_ = 1.0;
    double touching_until_ = -std::numeric_limits<double>::infinity();  // the end of the last touching piece
};

// The roots of f along the ray with t in (t_min, t_max) and inside the box, nearest first.
std::vector<ImplicitRoot> roots_along(const ImplicitSurface& f, const Ray& ray, double t_min, double t_max, bool all) {
    const dvec3 o = dvec3(f.to_local * glm::dvec4(ray.origin, 1.0));
    const dvec3 d = glm::dmat3(f.to_local) * ray.dir;
    // Only where the surface can be (the loader proved the rest of the box empty): the root bound
    // is relative to it, not to a box chosen far too large.
    const dvec3 box_lo = f.search_box ? (*f.search_box)[0] : f.box_lo, box_hi = f.search_box ? (*f.search_box)[1] : f.box_hi;
    double t0 = t_min, t1 = t_max;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (o[i] < box_lo[i] || o[i] > box_hi[i]) return {};
            continue;
        }
        double a = (box_lo[i] - o[i]) / d[i], b = (box_hi[i] - o[i]) / d[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (!(t0 <= t1) || !std::isfinite(t0) || !std::isfinite(t1)) return {};
    const double e = kRootBound * glm::length(box_hi - box_lo) / glm::length(d);
    const ImplicitRay r{o + t0 * d, d, t0};
    return RootFinder(f, r, 0.0, t1 - t0, t_min, t_max, e, all).run();
}

}  // namespace

std::vector<ImplicitRoot> implicit_roots(const ImplicitSurface& s, const Ray& ray, double t_min, double t_max) {
    return roots_along(s, ray, t_min, t_max, true);
}

std::vector<double> roots_on_line(const ImplicitObject& o, const Ray& ray) {
    std::vector<double> roots;
    for (const ImplicitRoot& root : roots_along(*o.surface, ray, -surface::kInf, surface::kInf, true)) roots.push_back(root.t);
    return roots;
}

bool inside(const ImplicitObject& o, const dvec3& p) {
    const dvec3 local = dvec3(o.surface->to_local * glm::dvec4(p, 1.0));
    return surface::evaluate_implicit(*o.surface, local).f < 0.0;
}

std::optional<SurfaceHit> intersect(const ImplicitObject& o, const Ray& ray, double t_min, double t_max) {
    const ImplicitSurface& s = *o.surface;
    std::vector<ImplicitRoot> roots = roots_along(s, ray, t_min, t_max, false);
    if (roots.empty()) return std::nullopt;
    const double t = roots.front().t;
    const dvec3 p = ray.origin + t * ray.dir;
    return SurfaceHit{t, surface::implicit_normal(s, p),
                      surface::implicit_texture_uv(s, dvec3(s.to_local * glm::dvec4(p, 1.0)))};
}

}  // namespace lancer::cpu
