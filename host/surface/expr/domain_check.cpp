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

using Box = std::vector<Interval>;

bool usable(std::span<const Interval> domain) {
    for (const Interval& x : domain)
        if (x.is_empty() || !x.is_finite()) return false;
    return true;
}

// A grid including the edges (9 x 9 over a rectangle, 5 x 5 x 5 over a box), plus 32 interior
// points of a Halton sequence.
std::vector<std::vector<double>> sample_points(const Box& box) {
    const int dims = static_cast<int>(box.size());
    const int steps = dims <= 2 ? 8 : 4;
    std::vector<std::vector<double>> points;
    std::vector<int> index(dims, 0);
    for (;;) {
        std::vector<double> p(dims);
        for (int k = 0; k < dims; ++k) p[k] = box[k].lo + box[k].width() * index[k] / steps;
        points.push_back(std::move(p));
        int k = 0;
        while (k < dims && ++index[k] > steps) index[k++] = 0;
        if (k == dims) break;
    }
    auto halton = [](int i, int base) {
        double f = 1.0, r = 0.0;
        for (; i > 0; i /= base) r += (f /= base) * (i % base);
        return r;
    };
    constexpr int kBases[] = {2, 3, 5, 7};
    for (int i = 1; i <= 32; ++i) {
        std::vector<double> p(dims);
        for (int k = 0; k < dims; ++k) p[k] = box[k].lo + box[k].width() * halton(i, kBases[k % 4]);
        points.push_back(std::move(p));
    }
    return points;
}

class DomainChecker {
public:
    DomainChecker(const Expr& expr, Box domain) : expr_(expr), domain_(std::move(domain)) {
        for (const auto& point : sample_points(domain_)) {
            std::vector<double> values(expr.nodes.size());
            evaluate_nodes(expr.nodes.data(), static_cast<int>(values.size()), point.data(), values.data());
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
        const int dims = static_cast<int>(domain_.size());
        std::vector<Box> boxes{domain_};
        std::vector<Dual<Interval>> ivalues(r.operand + 1), variables(dims);
        std::vector<double> dvalues(r.operand + 1), centre(dims);
        std::vector<double> change(dims);
        for (int budget = kBoxBudget; !boxes.empty(); --budget) {
            if (budget == 0) return false;
            Box box = boxes.back();
            boxes.pop_back();
            // One pass per variable, each carrying the derivative along that variable only.
            Interval value;
            for (int k = 0; k < dims; ++k) {
                for (int j = 0; j < dims; ++j) variables[j] = {box[j], Interval(j == k ? 1.0 : 0.0), Interval(0.0)};
                evaluate_nodes(expr_.nodes.data(), r.operand + 1, variables.data(), ivalues.data());
                value = ivalues[r.operand].v;
                change[k] = ivalues[r.operand].du.mag() * box[k].width();
            }
            if (value.is_empty() || r.proved_invalid(value)) continue;
            for (int k = 0; k < dims; ++k) centre[k] = box[k].mid();
            evaluate_nodes(expr_.nodes.data(), r.operand + 1, centre.data(), dvalues.data());
            double xc = dvalues[r.operand];
            if (!std::isnan(xc) && !r.invalid(xc)) return false;
            // Rounding keeps intervals from proving a box that touches the edge of a domain
            // (atanh(1 + u) at u = 0 is atanh(1)): where the operand is constant to 1e-12 on the
            // box, the box counts as its centre.
            if (value.width() <= kFlat * (1.0 + std::abs(xc))) continue;
            // Split across the direction the operand changes along (u - 0.5 never needs a v split).
            bool nan = false;
            for (double c : change) nan |= c != c;
            int split = 0;
            if (!nan)
                for (int k = 1; k < dims; ++k)
                    if (change[k] > change[split]) split = k;
            Box low = box, high = box;
            low[split].hi = centre[split];
            high[split].lo = centre[split];
            boxes.push_back(std::move(low));
            boxes.push_back(std::move(high));
        }
        return true;
    }

    const Expr& expr_;
    Box domain_;
    std::vector<std::vector<double>> samples_;
};

}  // namespace

std::optional<ExprError> where_non_finite_starts(const Expr& expr, std::span<const Interval> domain) {
    if (!usable(domain)) return std::nullopt;
    return DomainChecker(expr, Box(domain.begin(), domain.end())).non_finite_origin();
}

void check_expression_domain(const Expr& expr, std::span<const Interval> domain) {
    if (!usable(domain)) throw UserError("the domain must be finite and not empty");
    DomainChecker(expr, Box(domain.begin(), domain.end())).check();
}

}  // namespace lancer::surface
