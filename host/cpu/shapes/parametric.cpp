// Ray / parametric surface for the CPU reference: a certified search over (u, v).
//
// The ray is written as the intersection of two planes through it (normals n1, n2 perpendicular
// to d), so a hit is a root of F(u, v) = (n1 . (S - o), n2 . (S - o)), and its t follows from S.
// Parameter boxes are examined nearest first (by a lower bound of t), starting from the leaves
// of the box tree that the ray enters. For each box:
//   * exclusion: F(X) (natural interval extension) stays 1e-12 of the surface's size away from
//     0, or no t in (t_min, t_best);
//   * Krawczyk: K(X) = c - Y F(c) + (I - Y [J](X)) (X - c), Y = mid([J])^-1. K(X) inside X proves a
//     unique root in X (Newton from c finds it); K(X) disjoint from X proves none; otherwise X
//     shrinks to K(X) and X, or is split. X is inflated by 1% first, so that a root on the edge
//     between two boxes is inside one of them;
//   * boxes that shrink to ~1e-10 of the surface's size without a proof (tangent rays, poles,
//     where the Jacobian is singular) are accepted at the point Newton or their centre gives.
// Work is capped per ray, so a pathological ray ends with the nearest root found so far.
// This shares nothing with the GPU's intersector beyond the surface's evaluation.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "cpu/shapes/line_crossings.hpp"
#include "cpu/shapes/parametric_tree.hpp"
#include "cpu/shapes/ray_planes.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

using surface::Dual;
using surface::Interval;

constexpr double kInflation = 0.01;       // of a box's width, for the Krawczyk test
constexpr double kTinyFraction = 1e-10;   // of the surface's size: a box this small is a root
constexpr double kNearMiss = 1e-12;       // of the surface's size: closer than this is a hit

thread_local int last_boxes = 0;

struct Root {
    double t, u, v;
};

// The ray in the surface's frame, and two planes that contain it.
struct ParametricRay {
    dvec3 o, d, n1, n2;
    double dd;  // |d|^2
};

ParametricRay parametric_ray(const ParametricTree& tree, const Ray& ray) {
    ParametricRay r;
    r.o = dvec3(tree.to_local * glm::dvec4(ray.origin, 1.0));
    r.d = glm::dmat3(tree.to_local) * ray.dir;
    r.dd = glm::dot(r.d, r.d);
    std::tie(r.n1, r.n2) = ray_planes(r.d / std::sqrt(r.dd));
    return r;
}

Interval dot(const dvec3& n, const Interval* x) {
    return Interval(n.x) * x[0] + Interval(n.y) * x[1] + Interval(n.z) * x[2];
}

struct Item {
    double key;  // a lower bound of t over the item
    int node;    // a tree node, or -1 for a parameter box
    Interval u, v;
    bool operator<(const Item& other) const { return key > other.key; }  // min-heap
};

class Search {
public:
    Search(const ParametricTree& tree, const ParametricRay& ray, double t_min, double t_max)
        : tree_(tree), r_(ray), t_min_(t_min), t_best_(t_max), heap_(scratch_heap()) {
        heap_.clear();
        du_ = tree.u1 - tree.u0;
        dv_ = tree.v1 - tree.v0;
    }

    std::optional<Root> run() {
        if (auto t = enter(tree_.nodes[0])) push({*t, 0, {}, {}});
        int boxes = 0;
        while (!heap_.empty() && boxes < kMaxParametricBoxes) {
            std::pop_heap(heap_.begin(), heap_.end());
            Item item = heap_.back();
            heap_.pop_back();
            if (item.key >= t_best_) break;  // everything left is farther than the best root
            if (item.node >= 0) {
                visit(item);
            } else {
                ++boxes;
                examine(item);
            }
        }
        last_boxes = boxes;
        return best_;
    }

private:
    static std::vector<Item>& scratch_heap() {
        thread_local std::vector<Item> heap;
        return heap;
    }

    void push(const Item& item) {
        heap_.push_back(item);
        std::push_heap(heap_.begin(), heap_.end());
    }

    // Where the ray enters the node's box within (t_min, t_best), if it does.
    // The box is widened by the near-miss distance, the thickness the exclusion test allows.
    std::optional<double> enter(const ParametricTreeNode& n) const {
        const double eps = kNearMiss * tree_.scale;
        double t0 = t_min_, t1 = t_best_;
        for (int i = 0; i < 3; ++i) {
            const double lo = n.lo[i] - eps, hi = n.hi[i] + eps;
            if (r_.d[i] == 0.0) {
                if (r_.o[i] < lo || r_.o[i] > hi) return std::nullopt;
                continue;
            }
            double a = (lo - r_.o[i]) / r_.d[i], b = (hi - r_.o[i]) / r_.d[i];
            if (a > b) std::swap(a, b);
            // Widen by a relative hair: the slab arithmetic is rounded, the boxes are not padded.
            a -= 1e-12 * std::abs(a);
            b += 1e-12 * std::abs(b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
            if (!(t0 <= t1)) return std::nullopt;
        }
        return t0;
    }

    void visit(const Item& item) {
        const ParametricTreeNode& n = tree_.nodes[item.node];
        if (n.leaf()) {
            push({item.key, -1, n.u, n.v});
            return;
        }
        for (int c : n.child) {
            if (c < 0) continue;
            if (auto t = enter(tree_.nodes[c])) push({std::max(*t, item.key), c, {}, {}});
        }
    }

    // X widened by kInflation on each side, but not beyond the domain.
    Interval inflate(const Interval& x, double lo, double hi) const {
        double w = kInflation * x.width();
        return {std::max(lo, x.lo - w), std::min(hi, x.hi + w)};
    }

    void examine(const Item& item) {
        const Interval U = inflate(item.u, tree_.u0, tree_.u1), V = inflate(item.v, tree_.v0, tree_.v1);
        Dual<Interval> s[3];
        const bool smooth = surface::evaluate_program_on_box(tree_.program, U, V, s);
        Interval rel[3], su[3], sv[3];
        for (int i = 0; i < 3; ++i) {
            if (s[i].v.is_empty()) return;  // S is undefined on the whole box
            rel[i] = s[i].v - Interval(r_.o[i]);
            su[i] = s[i].du;
            sv[i] = s[i].dv;
        }
        if (far_from_ray(dot(r_.n1, rel)) || far_from_ray(dot(r_.n2, rel))) return;
        Interval t = dot(r_.d, rel) / Interval(r_.dd);
        if (t.hi <= t_min_ || t.lo >= t_best_) return;
        const double key = std::max(item.key, t.lo);

        Interval u = item.u, v = item.v;
        if (smooth) {
            switch (krawczyk(U, V, su, sv, u, v)) {
                case Verdict::None: return;
                case Verdict::Unique:
                    if (auto root = newton(U.mid(), V.mid(), U, V)) {
                        consider(*root);
                        return;
                    }
                    break;  // Newton failed after all (rounding at a near-singular root): split
                case Verdict::Shrunk: {
                    double before = item.u.width() * item.v.width(), after = u.width() * v.width();
                    if (after <= 0.5 * before) {
                        push({key, -1, u, v});
                        return;
                    }
                    break;
                }
                case Verdict::Unknown: break;
            }
        }

        // World-scaled side lengths: split the longer one, stop when both are tiny.
        double lu = u.width() * length(su), lv = v.width() * length(sv);
        bool scaled = std::isfinite(lu) && std::isfinite(lv);
        double tiny = kTinyFraction * tree_.scale;
        if ((scaled && std::max(lu, lv) <= tiny) || (u.width() <= 1e-13 * du_ && v.width() <= 1e-13 * dv_)) {
            accept_tiny(u, v);
            return;
        }
        if (!scaled) {
            lu = u.width() / du_;
            lv = v.width() / dv_;
        }
        if (lu >= lv) {
            double m = 0.5 * (u.lo + u.hi);
            push({key, -1, {u.lo, m}, v});
            push({key, -1, {m, u.hi}, v});
        } else {
            double m = 0.5 * (v.lo + v.hi);
            push({key, -1, u, {v.lo, m}});
            push({key, -1, u, {m, v.hi}});
        }
    }

    // Whether a plane distance stays farther from the ray than kNearMiss of the surface's size.
    // Points that close count as on the ray: a sphere parametrised over [-pi/2, pi/2] in double
    // stops 6e-17 short of its poles, and a ray through a pole must not slip through that hole.
    bool far_from_ray(const Interval& distance) const {
        double eps = kNearMiss * tree_.scale;
        return distance.lo > eps || distance.hi < -eps;
    }

    static double length(const Interval* a) {
        return std::sqrt(surface::sqr(a[0].mag()) + surface::sqr(a[1].mag()) + surface::sqr(a[2].mag()));
    }

    enum class Verdict { None, Unique, Shrunk, Unknown };

    // The Krawczyk test on X = U x V (the inflated box) with the interval partials su, sv over
    // it. On Shrunk, (u, v) (the box before inflation) becomes its intersection with K(X).
    Verdict krawczyk(const Interval& U, const Interval& V, const Interval* su, const Interval* sv, Interval& u,
                     Interval& v) const {
        const double uc = U.mid(), vc = V.mid();
        Interval sc[3];
        surface::evaluate_program(tree_.program, Interval(uc), Interval(vc), sc);
        Interval rc[3];
        for (int i = 0; i < 3; ++i) {
            if (sc[i].is_empty()) return Verdict::Unknown;
            rc[i] = sc[i] - Interval(r_.o[i]);
        }
        const Interval fc = dot(r_.n1, rc), gc = dot(r_.n2, rc);
        const Interval j00 = dot(r_.n1, su), j01 = dot(r_.n1, sv), j10 = dot(r_.n2, su), j11 = dot(r_.n2, sv);
        const double m00 = j00.mid(), m01 = j01.mid(), m10 = j10.mid(), m11 = j11.mid();
        const double det = m00 * m11 - m01 * m10;
        if (!std::isfinite(det) || det == 0.0 || !j00.is_finite() || !j01.is_finite() || !j10.is_finite() ||
            !j11.is_finite())
            return Verdict::Unknown;
        const Interval y00(m11 / det), y01(-m01 / det), y10(-m10 / det), y11(m00 / det);
        const Interval ru = U - Interval(uc), rv = V - Interval(vc);
        const Interval a00 = Interval(1.0) - (y00 * j00 + y01 * j10), a01 = -(y00 * j01 + y01 * j11);
        const Interval a10 = -(y10 * j00 + y11 * j10), a11 = Interval(1.0) - (y10 * j01 + y11 * j11);
        const Interval ku = Interval(uc) - (y00 * fc + y01 * gc) + a00 * ru + a01 * rv;
        const Interval kv = Interval(vc) - (y10 * fc + y11 * gc) + a10 * ru + a11 * rv;
        if (intersect(ku, U).is_empty() || intersect(kv, V).is_empty()) return Verdict::None;
        if (ku.lo > U.lo && ku.hi < U.hi && kv.lo > V.lo && kv.hi < V.hi) return Verdict::Unique;
        u = intersect(ku, u);
        v = intersect(kv, v);
        if (u.is_empty() || v.is_empty()) return Verdict::None;  // the root K allows is in the margin
        return Verdict::Shrunk;
    }

    // Newton's method on F from (u, v), staying inside U x V; the root when it converges.
    std::optional<Root> newton(double u, double v, const Interval& U, const Interval& V) const {
        for (int i = 0; i < 24; ++i) {
            Dual<double> s[3];
            surface::evaluate_program(tree_.program, Dual<double>::variable_u(u), Dual<double>::variable_v(v), s);
            dvec3 rel = dvec3(s[0].v, s[1].v, s[2].v) - r_.o;
            dvec3 su(s[0].du, s[1].du, s[2].du), sv(s[0].dv, s[1].dv, s[2].dv);
            double f = glm::dot(r_.n1, rel), g = glm::dot(r_.n2, rel);
            double j00 = glm::dot(r_.n1, su), j01 = glm::dot(r_.n1, sv);
            double j10 = glm::dot(r_.n2, su), j11 = glm::dot(r_.n2, sv);
            double det = j00 * j11 - j01 * j10;
            if (!std::isfinite(det) || det == 0.0) return std::nullopt;
            double step_u = (j11 * f - j01 * g) / det, step_v = (j00 * g - j10 * f) / det;
            u -= step_u;
            v -= step_v;
            if (!(U.contains(u) && V.contains(v))) return std::nullopt;
            if (std::abs(step_u) <= 1e-12 * du_ && std::abs(step_v) <= 1e-12 * dv_) return root_at(u, v);
        }
        return std::nullopt;
    }

    // t at (u, v), when S(u, v) is on the ray to within rounding.
    std::optional<Root> root_at(double u, double v) const {
        double s[3];
        surface::evaluate_program(tree_.program, u, v, s);
        dvec3 rel = dvec3(s[0], s[1], s[2]) - r_.o;
        double t = glm::dot(r_.d, rel) / r_.dd;
        double miss = glm::length(rel - t * r_.d);
        if (!std::isfinite(t) || !(miss <= 1e-8 * (tree_.scale + glm::length(rel)))) return std::nullopt;
        return Root{t, u, v};
    }

    // A box too small to split further that no test could exclude: a root at the edge of
    // provability (tangency, a pole). Newton may still pin it down; else take the centre.
    void accept_tiny(const Interval& u, const Interval& v) {
        Interval U = inflate(u, tree_.u0, tree_.u1), V = inflate(v, tree_.v0, tree_.v1);
        if (auto root = newton(u.mid(), v.mid(), U, V)) return consider(*root);
        if (auto root = root_at(u.mid(), v.mid())) consider(*root);
    }

    void consider(const Root& root) {
        if (root.t > t_min_ && root.t < t_best_) {
            t_best_ = root.t;
            best_ = root;
        }
    }

    const ParametricTree& tree_;
    const ParametricRay& r_;
    double t_min_, t_best_;
    double du_, dv_;
    std::vector<Item>& heap_;
    std::optional<Root> best_;
};

}  // namespace

int last_parametric_boxes() { return last_boxes; }

std::optional<SurfaceHit> intersect(const surface::ParametricSurface& s, const Ray& ray, double t_min, double t_max) {
    last_boxes = 0;
    const ParametricTree& tree = parametric_tree(s);
    if (!tree.invertible || tree.nodes.empty()) return std::nullopt;
    ParametricRay r = parametric_ray(tree, ray);
    if (!(r.dd > 0.0) || !std::isfinite(r.dd) || !std::isfinite(r.o.x + r.o.y + r.o.z)) return std::nullopt;
    auto root = Search(tree, r, t_min, t_max).run();
    if (!root) return std::nullopt;
    return SurfaceHit{root->t, surface::surface_normal(s, root->u, root->v), {root->u, root->v}};
}

// The gap past each root is beyond the search's 1e-10 of the surface's size.
std::vector<LineCrossing> crossings_on_line(const ParametricObject& o, const Ray& ray, double t0, double t1) {
    const double gap = 1e-8 * glm::length(o.bounds_hi - o.bounds_lo) / glm::length(ray.dir);
    return crossings_by_search([&](double from, double to) { return intersect(*o.surface, ray, from, to); }, o.outward, ray, t0,
                               t1, gap);
}

}  // namespace lancer::cpu
