#include "cpu/shapes/parametric_tree.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/finite.hpp"

namespace lancer::cpu {
namespace {

using surface::Dual;
using surface::Interval;
using surface::dvec3;

constexpr int kMinDepth = 4;   // at least 16 leaves, so that culling starts somewhere
constexpr int kMaxDepth = 14;  // at most 16384 leaves
constexpr double kLeafFraction = 1.0 / 16.0;

// The diagonal of the local box of S sampled on a grid.
double sampled_size(const surface::Program& program, const surface::ParametricSurface& s) {
    constexpr int n = 16;
    dvec3 lo(surface::kInf), hi(-surface::kInf);
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            double p[3];
            surface::evaluate_program(program, s.u0 + (s.u1 - s.u0) * i / n, s.v0 + (s.v1 - s.v0) * j / n, p);
            dvec3 q(p[0], p[1], p[2]);
            if (!all_finite(q)) continue;
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
    }
    double d = glm::length(hi - lo);
    return std::isfinite(d) && d > 0.0 ? d : 1.0;
}

class TreeBuilder {
public:
    TreeBuilder(ParametricTree& tree, double leaf_size, double du, double dv)
        : tree_(tree), leaf_size_(leaf_size), du_(du), dv_(dv) {}

    // The index of the node for this rectangle, or nothing where S is undefined throughout.
    std::optional<int> build(const Interval& u, const Interval& v, int depth) {
        Dual<Interval> s[3];
        surface::evaluate_program_on_box(tree_.program, u, v, s);
        if (s[0].v.is_empty() || s[1].v.is_empty() || s[2].v.is_empty()) return std::nullopt;
        ParametricTreeNode node;
        node.u = u;
        node.v = v;
        node.lo = {s[0].v.lo, s[1].v.lo, s[2].v.lo};
        node.hi = {s[0].v.hi, s[1].v.hi, s[2].v.hi};
        int index = static_cast<int>(tree_.nodes.size());
        tree_.nodes.push_back(node);
        double size = glm::length(node.hi - node.lo);
        if (depth >= kMaxDepth || (depth >= kMinDepth && size <= leaf_size_)) return index;

        // Split the side that is longer on the surface; parameter widths where that is unknown.
        auto length = [](const Dual<Interval>* p, Interval Dual<Interval>::*d) {
            return std::sqrt(surface::sqr((p[0].*d).mag()) + surface::sqr((p[1].*d).mag()) +
                             surface::sqr((p[2].*d).mag()));
        };
        double lu = u.width() * length(s, &Dual<Interval>::du);
        double lv = v.width() * length(s, &Dual<Interval>::dv);
        if (!std::isfinite(lu) || !std::isfinite(lv)) {
            lu = u.width() / du_;
            lv = v.width() / dv_;
        }
        std::optional<int> a, b;
        if (lu >= lv) {
            double m = 0.5 * (u.lo + u.hi);
            a = build({u.lo, m}, v, depth + 1);
            b = build({m, u.hi}, v, depth + 1);
        } else {
            double m = 0.5 * (v.lo + v.hi);
            a = build(u, {v.lo, m}, depth + 1);
            b = build(u, {m, v.hi}, depth + 1);
        }
        // Both children's boxes contain their halves, so does their union; keep the tighter
        // of that and the node's own box in each coordinate.
        ParametricTreeNode& self = tree_.nodes[index];
        dvec3 lo(surface::kInf), hi(-surface::kInf);
        int children = 0;
        for (const auto& c : {a, b}) {
            if (!c) continue;
            self.child[children++] = *c;
            lo = glm::min(lo, tree_.nodes[*c].lo);
            hi = glm::max(hi, tree_.nodes[*c].hi);
        }
        if (children == 0) return index;  // both halves undefined: keep the node as a leaf
        self.lo = glm::max(self.lo, lo);
        self.hi = glm::min(self.hi, hi);
        return index;
    }

private:
    ParametricTree& tree_;
    double leaf_size_, du_, dv_;
};

}  // namespace

ParametricTree build_parametric_tree(const surface::ParametricSurface& s) {
    ParametricTree tree;
    const surface::Expr* xyz[] = {&s.x, &s.y, &s.z};
    tree.program = surface::compile_program(xyz);
    tree.u0 = s.u0;
    tree.u1 = s.u1;
    tree.v0 = s.v0;
    tree.v1 = s.v1;
    tree.to_world = s.to_world;
    double det = glm::determinant(glm::dmat3(s.to_world));
    tree.invertible = std::isfinite(det) && det != 0.0;
    if (!tree.invertible) return tree;
    tree.to_local = glm::inverse(s.to_world);
    if (!(s.u0 <= s.u1) || !(s.v0 <= s.v1) || !std::isfinite(s.u1 - s.u0) || !std::isfinite(s.v1 - s.v0)) return tree;
    tree.scale = sampled_size(tree.program, s);
    TreeBuilder builder(tree, kLeafFraction * tree.scale, std::max(s.u1 - s.u0, 1e-300), std::max(s.v1 - s.v0, 1e-300));
    builder.build({s.u0, s.u1}, {s.v0, s.v1}, 0);
    return tree;
}

const ParametricTree& parametric_tree(const surface::ParametricSurface& s) {
    const ParametricTree& tree = s.derived.get<ParametricTree>([&] { return build_parametric_tree(s); });
    if (tree.u0 != s.u0 || tree.u1 != s.u1 || tree.v0 != s.v0 || tree.v1 != s.v1 || tree.to_world != s.to_world)
        throw std::logic_error("a ParametricSurface was changed after its first intersection; copy it instead");
    return tree;
}

}  // namespace lancer::cpu
