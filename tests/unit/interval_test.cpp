// Interval arithmetic: every result must contain the value of the same operation at every
// point of its inputs (property tests on random boxes, including ones around extrema, poles and
// zero), plus the cases that need care: trigonometric extrema, division by intervals containing
// 0, domains, empty intervals, rounding.
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "surface/interval.hpp"
#include "surface/scalar_ops.hpp"

namespace lancer::surface {
namespace {

using std::numbers::pi;

struct Unary {
    std::string name;
    std::function<double(double)> f;
    std::function<Interval(const Interval&)> F;
};

struct Binary {
    std::string name;
    std::function<double(double, double)> f;
    std::function<Interval(const Interval&, const Interval&)> F;
};

std::vector<Unary> unary_functions() {
    return {
        {"neg", [](double x) { return -x; }, [](const Interval& x) { return -x; }},
        {"sqr", [](double x) { return sqr(x); }, [](const Interval& x) { return sqr(x); }},
        {"sqrt", [](double x) { return std::sqrt(x); }, [](const Interval& x) { return sqrt(x); }},
        {"cbrt", [](double x) { return std::cbrt(x); }, [](const Interval& x) { return cbrt(x); }},
        {"exp", [](double x) { return std::exp(x); }, [](const Interval& x) { return exp(x); }},
        {"exp2", [](double x) { return std::exp2(x); }, [](const Interval& x) { return exp2(x); }},
        {"log", [](double x) { return std::log(x); }, [](const Interval& x) { return log(x); }},
        {"log2", [](double x) { return std::log2(x); }, [](const Interval& x) { return log2(x); }},
        {"log10", [](double x) { return std::log10(x); }, [](const Interval& x) { return log10(x); }},
        {"sin", [](double x) { return std::sin(x); }, [](const Interval& x) { return sin(x); }},
        {"cos", [](double x) { return std::cos(x); }, [](const Interval& x) { return cos(x); }},
        {"tan", [](double x) { return std::tan(x); }, [](const Interval& x) { return tan(x); }},
        {"asin", [](double x) { return std::asin(x); }, [](const Interval& x) { return asin(x); }},
        {"acos", [](double x) { return std::acos(x); }, [](const Interval& x) { return acos(x); }},
        {"atan", [](double x) { return std::atan(x); }, [](const Interval& x) { return atan(x); }},
        {"sinh", [](double x) { return std::sinh(x); }, [](const Interval& x) { return sinh(x); }},
        {"cosh", [](double x) { return std::cosh(x); }, [](const Interval& x) { return cosh(x); }},
        {"tanh", [](double x) { return std::tanh(x); }, [](const Interval& x) { return tanh(x); }},
        {"asinh", [](double x) { return std::asinh(x); }, [](const Interval& x) { return asinh(x); }},
        {"acosh", [](double x) { return std::acosh(x); }, [](const Interval& x) { return acosh(x); }},
        {"atanh", [](double x) { return std::atanh(x); }, [](const Interval& x) { return atanh(x); }},
        {"abs", [](double x) { return std::abs(x); }, [](const Interval& x) { return abs(x); }},
        {"powi 2", [](double x) { return powi(x, 2); }, [](const Interval& x) { return powi(x, 2); }},
        {"powi 3", [](double x) { return powi(x, 3); }, [](const Interval& x) { return powi(x, 3); }},
        {"powi 6", [](double x) { return powi(x, 6); }, [](const Interval& x) { return powi(x, 6); }},
        {"powi 7", [](double x) { return powi(x, 7); }, [](const Interval& x) { return powi(x, 7); }},
        {"powi -1", [](double x) { return powi(x, -1); }, [](const Interval& x) { return powi(x, -1); }},
        {"powi -2", [](double x) { return powi(x, -2); }, [](const Interval& x) { return powi(x, -2); }},
        {"powi -3", [](double x) { return powi(x, -3); }, [](const Interval& x) { return powi(x, -3); }},
        {"powc 0.5", [](double x) { return powc(x, 0.5); }, [](const Interval& x) { return powc(x, 0.5); }},
        {"powc 2.5", [](double x) { return powc(x, 2.5); }, [](const Interval& x) { return powc(x, 2.5); }},
        {"powc -1.5", [](double x) { return powc(x, -1.5); }, [](const Interval& x) { return powc(x, -1.5); }},
    };
}

std::vector<Binary> binary_functions() {
    return {
        {"+", [](double a, double b) { return a + b; }, [](const Interval& a, const Interval& b) { return a + b; }},
        {"-", [](double a, double b) { return a - b; }, [](const Interval& a, const Interval& b) { return a - b; }},
        {"*", [](double a, double b) { return a * b; }, [](const Interval& a, const Interval& b) { return a * b; }},
        {"/", [](double a, double b) { return a / b; }, [](const Interval& a, const Interval& b) { return a / b; }},
        {"atan2", [](double a, double b) { return std::atan2(a, b); },
         [](const Interval& a, const Interval& b) { return atan2(a, b); }},
        {"pow", [](double a, double b) { return powr(a, b); },
         [](const Interval& a, const Interval& b) { return powr(a, b); }},
        {"min", [](double a, double b) { return min(a, b); },
         [](const Interval& a, const Interval& b) { return min(a, b); }},
        {"max", [](double a, double b) { return max(a, b); },
         [](const Interval& a, const Interval& b) { return max(a, b); }},
        {"hypot", [](double a, double b) { return std::hypot(a, b); },
         [](const Interval& a, const Interval& b) { return hypot(a, b); }},
    };
}

// A random interval: centres at every scale (and near the special points of the functions:
// 0, +-1, multiples of pi/2), widths from ulps to many periods.
Interval random_interval(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 5);
    double centre;
    switch (kind(rng)) {
        case 0: centre = (unit(rng) - 0.5) * 4.0; break;
        case 1: centre = (unit(rng) - 0.5) * 40.0; break;
        case 2: centre = std::round((unit(rng) - 0.5) * 20.0) * pi / 2; break;
        case 3: centre = std::round((unit(rng) - 0.5) * 4.0); break;
        case 4: centre = (unit(rng) - 0.5) * 1e-6; break;
        default: centre = (unit(rng) - 0.5) * 1400.0; break;
    }
    double width = std::pow(10.0, -12.0 + 14.0 * unit(rng));
    double lo = centre - width * unit(rng);
    return {lo, lo + width};
}

// Points of the interval: both ends and random interior points.
std::vector<double> points_of(const Interval& x, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> p{x.lo, x.hi};
    for (int i = 0; i < 24; ++i) p.push_back(std::clamp(x.lo + unit(rng) * x.width(), x.lo, x.hi));
    return p;
}

TEST(Interval, UnaryFunctionsContainEverySampledValue) {
    std::mt19937 rng(11);
    for (const Unary& fn : unary_functions()) {
        int checked = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            Interval x = random_interval(rng);
            Interval y = fn.F(x);
            for (double p : points_of(x, rng)) {
                double value = fn.f(p);
                if (std::isnan(value)) continue;  // outside the domain: no value to contain
                ++checked;
                ASSERT_TRUE(y.contains(value)) << fn.name << " on [" << x.lo << ", " << x.hi << "] at " << p
                                               << " = " << value << " not in [" << y.lo << ", " << y.hi << "]";
            }
        }
        EXPECT_GT(checked, 10000) << fn.name;
    }
}

TEST(Interval, BinaryFunctionsContainEverySampledValue) {
    std::mt19937 rng(12);
    for (const Binary& fn : binary_functions()) {
        for (int trial = 0; trial < 3000; ++trial) {
            Interval a = random_interval(rng), b = random_interval(rng);
            Interval y = fn.F(a, b);
            auto pa = points_of(a, rng), pb = points_of(b, rng);
            for (std::size_t i = 0; i < pa.size(); ++i) {
                for (std::size_t j = 0; j < pb.size(); j += 5) {
                    double value = fn.f(pa[i], pb[j]);
                    if (std::isnan(value)) continue;
                    ASSERT_TRUE(y.contains(value))
                        << fn.name << " on [" << a.lo << ", " << a.hi << "] x [" << b.lo << ", " << b.hi << "] at ("
                        << pa[i] << ", " << pb[j] << ") = " << value << " not in [" << y.lo << ", " << y.hi << "]";
                }
            }
        }
    }
}

TEST(Interval, SinAndCosReachTheirExtremaInside) {
    EXPECT_EQ(sin(Interval(0.0, pi)).hi, 1.0);                 // pi/2 inside
    EXPECT_LT(sin(Interval(0.0, pi)).lo, 1e-15);
    EXPECT_EQ(sin(Interval(4.0, 5.0)).lo, -1.0);               // 3 pi/2 = 4.71 inside
    EXPECT_LT(sin(Interval(1.6, 3.0)).hi, 1.0);                // decreasing part: no extremum
    EXPECT_NEAR(sin(Interval(1.6, 3.0)).hi, std::sin(1.6), 1e-15);
    EXPECT_EQ(cos(Interval(-0.1, 0.1)).hi, 1.0);
    EXPECT_EQ(cos(Interval(3.0, 3.3)).lo, -1.0);
    EXPECT_EQ(cos(Interval(2 * pi * 1000 - 0.01, 2 * pi * 1000 + 0.01)).hi, 1.0);  // far periods
    Interval narrow = sin(Interval(0.5, 0.5000001));
    EXPECT_LT(narrow.width(), 1e-7);  // tight where monotone
    EXPECT_EQ(sin(Interval(0.0, 7.0)).lo, -1.0);               // more than a period
    EXPECT_EQ(sin(Interval(0.0, 7.0)).hi, 1.0);
}

TEST(Interval, DivisionByAnIntervalContainingZeroIsTheWholeLine) {
    EXPECT_EQ(Interval(1.0, 2.0) / Interval(-1.0, 1.0), Interval::entire());
    EXPECT_EQ(Interval(1.0, 2.0) / Interval(0.0, 1.0), Interval::entire());
    EXPECT_EQ(Interval(1.0) / Interval(0.0), Interval::entire());
    Interval q = Interval(1.0) / Interval(2.0, 4.0);
    EXPECT_TRUE(q.contains(0.25) && q.contains(0.5));
    EXPECT_LT(q.width(), 0.25 + 1e-15);
    EXPECT_EQ(powi(Interval(-1.0, 1.0), -2), Interval::entire());
}

TEST(Interval, TanPolesGiveTheWholeLine) {
    EXPECT_EQ(tan(Interval(1.5, 1.6)), Interval::entire());
    EXPECT_TRUE(tan(Interval(-1.0, 1.0)).is_finite());
}

TEST(Interval, DomainsClipAndWhollyInvalidIsEmpty) {
    EXPECT_TRUE(sqrt(Interval(-4.0, -1.0)).is_empty());
    Interval s = sqrt(Interval(-1.0, 4.0));
    EXPECT_EQ(s.lo, 0.0);
    EXPECT_TRUE(s.contains(2.0));
    EXPECT_TRUE(log(Interval(-1.0, 0.0)).is_empty());
    EXPECT_EQ(log(Interval(0.0, 1.0)).lo, -kInf);
    EXPECT_TRUE(asin(Interval(1.5, 2.0)).is_empty());
    EXPECT_TRUE(acos(Interval(-3.0, -1.5)).is_empty());
    EXPECT_TRUE(acosh(Interval(0.0, 0.5)).is_empty());
    EXPECT_TRUE(atanh(Interval(1.0, 2.0)).is_empty());
    EXPECT_TRUE(powc(Interval(-2.0, -1.0), 0.5).is_empty());
    EXPECT_TRUE(powr(Interval(-2.0, -1.0), Interval(2.0)).is_empty());
}

TEST(Interval, EmptyPropagates) {
    Interval e = Interval::empty();
    EXPECT_TRUE((e + Interval(1.0)).is_empty());
    EXPECT_TRUE((Interval(1.0) * e).is_empty());
    EXPECT_TRUE((e / Interval(2.0)).is_empty());
    EXPECT_TRUE(sin(e).is_empty());
    EXPECT_TRUE(atan2(e, Interval(1.0)).is_empty());
    EXPECT_TRUE(hull(e, e).is_empty());
    EXPECT_EQ(hull(e, Interval(1.0, 2.0)), Interval(1.0, 2.0));
}

TEST(Interval, RoundsOutward) {
    Interval sum = Interval(0.1) + Interval(0.2);
    EXPECT_LT(sum.lo, 0.1 + 0.2);
    EXPECT_GT(sum.hi, 0.1 + 0.2);
    Interval product = Interval(1.0 / 3.0) * Interval(3.0);
    EXPECT_LT(product.lo, 1.0);
    EXPECT_GE(product.hi, 1.0);
    EXPECT_EQ(next_up(1.0), std::nextafter(1.0, 2.0));
    EXPECT_EQ(next_down(1.0), std::nextafter(1.0, 0.0));
    EXPECT_EQ(next_down(0.0), -std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(next_down(kInf), std::numeric_limits<double>::max());
    EXPECT_EQ(next_up(-kInf), -std::numeric_limits<double>::max());
    Interval overflow = exp(Interval(1000.0));  // lo is never +inf, hi never -inf
    EXPECT_TRUE(std::isfinite(overflow.lo));
    EXPECT_EQ(overflow.hi, kInf);
}

TEST(Interval, ZeroTimesInfinityIsZero) {
    Interval r = Interval(0.0) * Interval::entire();
    EXPECT_FALSE(std::isnan(r.lo) || std::isnan(r.hi));
    EXPECT_TRUE(r.contains(0.0));
    EXPECT_LT(r.width(), 1e-300);
}

TEST(Interval, MidIsInsideEvenForInfiniteBounds) {
    for (Interval x : {Interval(1.0, 2.0), Interval(-kInf, 3.0), Interval(-3.0, kInf), Interval::entire(),
                       Interval(std::numeric_limits<double>::denorm_min()), Interval(-1e308, 1e308)}) {
        double m = x.mid();
        EXPECT_TRUE(std::isfinite(m));
        EXPECT_TRUE(x.contains(m)) << x.lo << " " << x.hi << " " << m;
    }
}

}  // namespace
}  // namespace lancer::surface
