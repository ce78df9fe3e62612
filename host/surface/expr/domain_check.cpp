// "Invalid everywhere" is decided two ways, and either one rejects:
//  1. Proof by intervals: a search over sub-boxes of the domain that discards every box on which
//     interval evaluation shows the operand invalid (or undefined), and stops at the first box
//     whose centre is valid. Rejects when every box is discarded (a box on which the operand is
//     constant to 1e-12 counts as its centre); gives up (accepts) after a budget of boxes, so it
//     never takes long.
//  2. Constant operands: intervals cannot see that u - u is 0 (they give [-w, w]), so an operand
//     that takes one and the same invalid value at every sample point is taken to be that
//     constant, which catches 1/(u-u) and log(0*u).
#include "surface/expr/domain_check.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "surface/expr/evaluate_nodes.hpp"
#include "surface/expr/functions.hpp"

namespace lancer::surface {
namespace {

constexpr int kBoxBudget = 256;
constexpr double kFlat = 1e-12;  // relative width of an operand's interval that counts as a point

struct Restriction {
    int operand;                                // the node whose value must be valid
    std::function<bool(double)> invalid;        // at a point
    std::function<bool(const Interval&)> proved_invalid;  // on a whole box (empty: undefined there)
    std::string message;
};

std::optional<Restriction> restriction_of(const Node& n, std::string_view name) {
    auto nonpositive = [](double x) { return x <= 0.0; };
    auto negative = [](double x) { return x < 0.0; };
    std::string everywhere = " everywhere on the domain";
    switch (n.op) {
        case Op::Div:
            return Restriction{n.b, [](double x) { return x == 0.0; },
                               [](const Interval& x) { return x.lo == 0.0 && x.hi == 0.0; },
                               "division by zero: the denominator is 0" + everywhere};
        case Op::PowInt:
            if (n.value >= 0.0) return std::nullopt;
            return Restriction{n.a, [](double x) { return x == 0.0; },
                               [](const Interval& x) { return x.lo == 0.0 && x.hi == 0.0; },
                               "division by zero: 0 to a negative power" + everywhere};
        case Op::PowConst:
            if (n.value < 0.0)
                return Restriction{n.a, nonpositive, [](const Interval& x) { return x.hi <= 0.0; },
                                   "x^c with a negative, non-integer c needs x > 0, but x <= 0" + everywhere};
            return Restriction{n.a, negative, [](const Interval& x) { return x.hi < 0.0; },
                               "x^c with a non-integer c needs x >= 0, but x < 0" + everywhere};
        case Op::Pow:
            return Restriction{n.a, negative, [](const Interval& x) { return x.hi < 0.0; },
                               "x^y with a varying y needs x > 0, but x < 0" + everywhere};
        case Op::Sqrt:
            return Restriction{n.a, negative, [](const Interval& x) { return x.hi < 0.0; },
                               std::string(name) + " of a negative number" + everywhere};
        case Op::Log:
        case Op::Log2:
        case Op::Log10:
            return Restriction{n.a, nonpositive, [](const Interval& x) { return x.hi <= 0.0; },
                               std::string(name) + " of a number <= 0" + everywhere};
        case Op::Asin:
        case Op::Acos:
            return Restriction{n.a, [](double x) { return std::abs(x) > 1.0; },
                               [](const Interval& x) { return x.lo > 1.0 || x.hi < -1.0; },
                               std::string(name) + " of a number outside [-1, 1]" + everywhere};
        case Op::Acosh:
            return Restriction{n.a, [](double x) { return x < 1.0; }, [](const Interval& x) { return x.hi < 1.0; },
                               "acosh of a number < 1" + everywhere};
        case Op::Atanh:
            return Restriction{n.a, [](double x) { return std::abs(x) >= 1.0; },
                               [](const Interval& x) { return x.lo >= 1.0 || x.hi <= -1.0; },
                               "atanh of a number outside (-1, 1)" + everywhere};
        default:
            return std::nullopt;
    }
}

struct Box {
    Interval u, v;
};

// A 9 x 9 grid including the edges, plus interior points of a Halton sequence.
std::vector<std::pair<double, double>> sample_points(const Interval& u, const Interval& v) {
    std::vector<std::pair<double, double>> points;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) points.emplace_back(u.lo + u.width() * i / 8.0, v.lo + v.width() * j / 8.0);
    auto halton = [](int index, int base) {
        double f = 1.0, r = 0.0;
        for (int i = index; i > 0; i /= base) r += (f /= base) * (i % base);
        return r;
    };
    for (int k = 1; k <= 32; ++k) points.emplace_back(u.lo + u.width() * halton(k, 2), v.lo + v.width() * halton(k, 3));
    return points;
}

class DomainChecker {
public:
    DomainChecker(const Expr& expr, Box domain) : expr_(expr), domain_(domain) {
        for (auto [u, v] : sample_points(domain.u, domain.v)) {
            std::vector<double> values(expr.nodes.size());
            evaluate_nodes(expr.nodes.data(), static_cast<int>(values.size()), u, v, values.data());
            samples_.push_back(std::move(values));
        }
    }

    std::optional<ExprError> non_finite_origin() const {
        auto never_finite = [&](int node) {
            for (const auto& values : samples_)
                if (std::isfinite(values[node])) return false;
            return true;
        };
        if (!never_finite(expr_.root())) return std::nullopt;
        for (int i = 0; i <= expr_.root(); ++i) {
            const Node& n = expr_.nodes[i];
            if (!never_finite(i) || (n.a >= 0 && never_finite(n.a)) || (n.b >= 0 && never_finite(n.b))) continue;
            bool overflow = std::isinf(samples_.front()[i]);
            return ExprError(overflow ? "this overflows to infinity everywhere on the domain (the largest number is about 1.8e308)"
                                      : "this is not a number anywhere on the domain (such as 0 * infinity)",
                             n.column);
        }
        return std::nullopt;
    }

    void check() const {
        for (const Node& n : expr_.nodes) {
            auto r = restriction_of(n, function_name(n.op));
            if (r && invalid_everywhere(*r)) throw ExprError(r->message, n.column);
        }
    }

private:
    bool invalid_everywhere(const Restriction& r) const {
        bool any_defined = false, all_same = true;
        double first = 0.0;
        for (const auto& values : samples_) {
            double x = values[r.operand];
            if (std::isnan(x)) continue;  // undefined upstream: says nothing about this operation
            if (!r.invalid(x)) return false;
            if (any_defined && x != first) all_same = false;
            if (!any_defined) first = x;
            any_defined = true;
        }
        if (any_defined && all_same) return true;
        return proved_invalid_everywhere(r);
    }

    bool proved_invalid_everywhere(const Restriction& r) const {
        std::vector<Box> boxes{domain_};
        std::vector<Dual<Interval>> ivalues(r.operand + 1);
        std::vector<double> dvalues(r.operand + 1);
        for (int budget = kBoxBudget; !boxes.empty(); --budget) {
            if (budget == 0) return false;
            Box box = boxes.back();
            boxes.pop_back();
            evaluate_nodes(expr_.nodes.data(), r.operand + 1, Dual<Interval>::variable_u(box.u),
                           Dual<Interval>::variable_v(box.v), ivalues.data());
            const Dual<Interval>& x = ivalues[r.operand];
            if (x.v.is_empty() || r.proved_invalid(x.v)) continue;
            double uc = box.u.mid(), vc = box.v.mid();
            evaluate_nodes(expr_.nodes.data(), r.operand + 1, uc, vc, dvalues.data());
            double xc = dvalues[r.operand];
            if (!std::isnan(xc) && !r.invalid(xc)) return false;
            // Rounding keeps intervals from proving a box that touches the edge of a domain
            // (atanh(1 + u) at u = 0 is atanh(1)): where the operand is constant to 1e-12 on the
            // box, the box counts as its centre.
            if (x.v.width() <= kFlat * (1.0 + std::abs(xc))) continue;
            // Split across the direction the operand changes along (u - 0.5 never needs a v split).
            double change_u = x.du.mag() * box.u.width(), change_v = x.dv.mag() * box.v.width();
            if (!(change_u == change_u && change_v == change_v)) change_u = change_v = 1.0;
            if (change_u >= change_v) {
                boxes.push_back({{box.u.lo, uc}, box.v});
                boxes.push_back({{uc, box.u.hi}, box.v});
            } else {
                boxes.push_back({box.u, {box.v.lo, vc}});
                boxes.push_back({box.u, {vc, box.v.hi}});
            }
        }
        return true;
    }

    const Expr& expr_;
    Box domain_;
    std::vector<std::vector<double>> samples_;
};

}  // namespace

std::optional<ExprError> where_non_finite_starts(const Expr& expr, Interval u, Interval v) {
    if (u.is_empty() || v.is_empty() || !u.is_finite() || !v.is_finite()) return std::nullopt;
    return DomainChecker(expr, {u, v}).non_finite_origin();
}

void check_expression_domain(const Expr& expr, Interval u, Interval v) {
    if (u.is_empty() || v.is_empty() || !u.is_finite() || !v.is_finite())
        throw UserError("the (u, v) domain must be finite and not empty");
    DomainChecker(expr, {u, v}).check();
}

}  // namespace lancer::surface
