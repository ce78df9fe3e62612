// Expansion walks the expression's nodes in order (post-order: operands first), keeping for each
// node its expansion or "not a polynomial". Products accumulate into a dense cube of exponents,
// so even (x + y + z + 1)^24 (2925 terms) expands in milliseconds.
#include "surface/polynomial.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "surface/expr/evaluate_nodes.hpp"

namespace lancer::surface {

int Polynomial3::degree() const {
    int d = -1;
    for (const Term& t : terms) d = std::max(d, t.degree());
    return d;
}

double Polynomial3::evaluate(const glm::dvec3& p) const {
    double sum = 0.0;
    for (const Term& t : terms) sum += t.coefficient * std::pow(p.x, t.x) * std::pow(p.y, t.y) * std::pow(p.z, t.z);
    return sum;
}

namespace {

Polynomial3 constant(double c) {
    Polynomial3 p;
    if (c != 0.0) p.terms.push_back({0, 0, 0, c});
    return p;
}

// The value of a polynomial of degree <= 0.
double constant_value(const Polynomial3& p) { return p.terms.empty() ? 0.0 : p.terms.front().coefficient; }

bool less(const Term& a, const Term& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

Polynomial3 combine(const Polynomial3& a, const Polynomial3& b, double sign) {
    Polynomial3 r;
    std::size_t i = 0, j = 0;
    while (i < a.terms.size() || j < b.terms.size()) {
        if (j == b.terms.size() || (i < a.terms.size() && less(a.terms[i], b.terms[j]))) {
            r.terms.push_back(a.terms[i++]);
        } else if (i == a.terms.size() || less(b.terms[j], a.terms[i])) {
            Term t = b.terms[j++];
            t.coefficient *= sign;
            r.terms.push_back(t);
        } else {
            Term t = a.terms[i++];
            t.coefficient += sign * b.terms[j++].coefficient;
            if (t.coefficient != 0.0) r.terms.push_back(t);
        }
    }
    return r;
}

Polynomial3 scaled(Polynomial3 p, double c) {
    for (Term& t : p.terms) t.coefficient *= c;
    std::erase_if(p.terms, [](const Term& t) { return t.coefficient == 0.0; });
    return p;
}

class Multiplier {
public:
    explicit Multiplier(int max_degree)
        : side_(max_degree + 1), cube_(std::size_t(side_) * side_ * side_, 0.0), seen_(cube_.size(), 0) {}

    // The caller has checked that the product's degree is within max_degree.
    Polynomial3 operator()(const Polynomial3& a, const Polynomial3& b) {
        touched_.clear();
        for (const Term& s : a.terms) {
            for (const Term& t : b.terms) {
                std::size_t k = index(s.x + t.x, s.y + t.y, s.z + t.z);
                if (!seen_[k]) {
                    seen_[k] = 1;
                    touched_.push_back(k);
                }
                cube_[k] += s.coefficient * t.coefficient;
            }
        }
        std::sort(touched_.begin(), touched_.end());  // the cube's order is (x, y, z)
        Polynomial3 r;
        for (std::size_t k : touched_) {
            double c = cube_[k];
            cube_[k] = 0.0;
            seen_[k] = 0;
            if (c == 0.0) continue;
            int z = static_cast<int>(k % side_), y = static_cast<int>(k / side_ % side_), x = static_cast<int>(k / side_ / side_);
            r.terms.push_back({x, y, z, c});
        }
        return r;
    }

private:
    std::size_t index(int x, int y, int z) const { return (std::size_t(x) * side_ + y) * side_ + z; }

    int side_;
    std::vector<double> cube_;
    std::vector<unsigned char> seen_;
    std::vector<std::size_t> touched_;
};

}  // namespace

std::optional<Polynomial3> expand_polynomial(const Expr& expr, int max_degree) {
    std::vector<std::optional<Polynomial3>> poly(expr.nodes.size());
    Multiplier multiply(max_degree);
    auto too_high = [&](int degree, const Node& n) {
        if (degree > max_degree)
            throw ExprError(fmt::format("this has degree {} as a polynomial; implicit surfaces that are polynomials may "
                                        "have degree {} at most",
                                        degree, max_degree),
                            n.column);
    };
    for (std::size_t i = 0; i < expr.nodes.size(); ++i) {
        const Node& n = expr.nodes[i];
        const std::optional<Polynomial3>* a = n.a >= 0 ? &poly[n.a] : nullptr;
        const std::optional<Polynomial3>* b = n.b >= 0 ? &poly[n.b] : nullptr;
        if (n.op == Op::Constant) {
            poly[i] = constant(n.value);
            continue;
        }
        if (n.op == Op::Variable) {
            int v = static_cast<int>(n.value);
            poly[i] = Polynomial3{{{v == 0, v == 1, v == 2, 1.0}}};
            continue;
        }
        if ((a && !*a) || (b && !*b && n.op != Op::PowInt && n.op != Op::PowConst)) return std::nullopt;
        const bool a_constant = !a || (*a)->degree() <= 0;
        const bool b_constant = !b || !*b || (*b)->degree() <= 0;
        if (a_constant && b_constant && n.op != Op::PowInt && n.op != Op::PowConst) {
            // Any function of constants is a constant, computed as evaluate() computes it.
            double operands[2] = {a ? constant_value(**a) : 0.0, b ? constant_value(**b) : 0.0};
            Node local = n;
            local.a = a ? 0 : -1;
            local.b = b ? 1 : -1;
            double value = apply_node<double>(local, operands, nullptr);
            if (!std::isfinite(value)) return std::nullopt;  // the domain check reports it
            poly[i] = constant(value);
            continue;
        }
        switch (n.op) {
            case Op::Add: poly[i] = combine(**a, **b, 1.0); break;
            case Op::Sub: poly[i] = combine(**a, **b, -1.0); break;
            case Op::Neg: poly[i] = scaled(**a, -1.0); break;
            case Op::Mul:
                too_high((*a)->degree() + (*b)->degree(), n);
                poly[i] = multiply(**a, **b);
                break;
            case Op::Div:
                if (!b_constant || constant_value(**b) == 0.0) return std::nullopt;
                poly[i] = scaled(**a, 1.0 / constant_value(**b));
                break;
            case Op::Sqr:
                too_high(2 * (*a)->degree(), n);
                poly[i] = multiply(**a, **a);
                break;
            case Op::PowInt: {
                const int e = static_cast<int>(n.value);
                if (a_constant) {
                    double operand = constant_value(**a);
                    Node local = n;
                    local.a = 0;
                    local.b = -1;
                    double value = apply_node<double>(local, &operand, nullptr);
                    if (!std::isfinite(value)) return std::nullopt;
                    poly[i] = constant(value);
                    break;
                }
                if (e < 0) return std::nullopt;
                too_high((*a)->degree() * e, n);
                Polynomial3 result = constant(1.0), base = **a;
                for (int k = e; k > 0; k >>= 1) {  // square and multiply
                    if (k & 1) result = multiply(result, base);
                    if (k > 1) base = multiply(base, base);
                }
                poly[i] = std::move(result);
                break;
            }
            case Op::PowConst:
                if (!a_constant) return std::nullopt;
                {
                    double operand = constant_value(**a);
                    Node local = n;
                    local.a = 0;
                    local.b = -1;
                    double value = apply_node<double>(local, &operand, nullptr);
                    if (!std::isfinite(value)) return std::nullopt;
                    poly[i] = constant(value);
                }
                break;
            default: return std::nullopt;  // a function of a variable
        }
    }
    if (expr.nodes.empty()) return Polynomial3{};
    return poly.back();
}

std::vector<double> restrict_to_line(const Polynomial3& p, const glm::dvec3& o, const glm::dvec3& d) {
    const int n = std::max(p.degree(), 0);
    // powers[axis][k] = (o[axis] + s d[axis])^k as coefficients in s.
    std::vector<std::vector<double>> powers[3];
    for (int axis = 0; axis < 3; ++axis) {
        powers[axis].assign(n + 1, {});
        powers[axis][0] = {1.0};
        for (int k = 1; k <= n; ++k) {
            const auto& prev = powers[axis][k - 1];
            std::vector<double> next(k + 1, 0.0);
            for (int j = 0; j < k; ++j) {
                next[j] += prev[j] * o[axis];
                next[j + 1] += prev[j] * d[axis];
            }
            powers[axis][k] = std::move(next);
        }
    }
    std::vector<double> c(n + 1, 0.0), xy;
    for (const Term& t : p.terms) {
        const auto& px = powers[0][t.x];
        const auto& py = powers[1][t.y];
        const auto& pz = powers[2][t.z];
        xy.assign(t.x + t.y + 1, 0.0);
        for (std::size_t i = 0; i < px.size(); ++i)
            for (std::size_t j = 0; j < py.size(); ++j) xy[i + j] += px[i] * py[j];
        for (std::size_t i = 0; i < xy.size(); ++i)
            for (std::size_t j = 0; j < pz.size(); ++j) c[i + j] += t.coefficient * xy[i] * pz[j];
    }
    return c;
}

}  // namespace lancer::surface
