// The patch maths of host/surface/bezier_patch: evaluation, derivatives, splitting, bounds,
// transforms and the robust normal, on random (rational) patches and on the teapot.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "unit/bezier_test_support.hpp"

namespace lancer::surface {
namespace {

using test::random_patch;
using test::uniform;

// S(u, v) straight from the definition, sum w P B B / sum w B B: independent of the library's nets.
dvec3 reference_point(const BezierPatch& p, double u, double v) {
    auto b = [](int i, double t) {
        const double c[4] = {1, 3, 3, 1};
        return c[i] * std::pow(t, i) * std::pow(1.0 - t, 3 - i);
    };
    dvec3 num(0.0);
    double den = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double w = p.weights[4 * i + j] * b(i, u) * b(j, v);
            num += w * p.points[4 * i + j];
            den += w;
        }
    return num / den;
}

double max_abs(const dvec3& a) { return std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)}); }

TEST(BezierPatch, EvaluatesTheBernsteinSum) {
    std::mt19937 rng(1);
    for (bool rational : {false, true})
        for (int n = 0; n < 50; ++n) {
            BezierPatch p = random_patch(rng, rational);
            double u = uniform(rng), v = uniform(rng);
            EXPECT_LE(max_abs(evaluate(p, u, v) - reference_point(p, u, v)), 1e-14);
            EXPECT_LE(max_abs(evaluate_jet(p, u, v).s - reference_point(p, u, v)), 1e-14);
        }
}

TEST(BezierPatch, CornersAreTheCornerControlPoints) {
    std::mt19937 rng(2);
    BezierPatch p = random_patch(rng, true);
    EXPECT_LE(max_abs(evaluate(p, 0, 0) - control_point(p, 0, 0)), 1e-15);
    EXPECT_LE(max_abs(evaluate(p, 1, 0) - control_point(p, 3, 0)), 1e-15);  // i runs along u
    EXPECT_LE(max_abs(evaluate(p, 0, 1) - control_point(p, 0, 3)), 1e-15);
    EXPECT_LE(max_abs(evaluate(p, 1, 1) - control_point(p, 3, 3)), 1e-15);
}

TEST(BezierPatch, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(3);
    const double h = 1e-5;
    for (bool rational : {false, true})
        for (int n = 0; n < 50; ++n) {
            BezierPatch p = random_patch(rng, rational);
            double u = uniform(rng, 0.05, 0.95), v = uniform(rng, 0.05, 0.95);
            SurfaceJet j = evaluate_jet(p, u, v);
            auto s = [&](double a, double b) { return reference_point(p, a, b); };
            dvec3 su = (s(u + h, v) - s(u - h, v)) / (2 * h);
            dvec3 sv = (s(u, v + h) - s(u, v - h)) / (2 * h);
            // Second derivatives as differences of the library's own first derivatives.
            dvec3 suu = (evaluate_jet(p, u + h, v).su - evaluate_jet(p, u - h, v).su) / (2 * h);
            dvec3 suv = (evaluate_jet(p, u, v + h).su - evaluate_jet(p, u, v - h).su) / (2 * h);
            dvec3 svv = (evaluate_jet(p, u, v + h).sv - evaluate_jet(p, u, v - h).sv) / (2 * h);
            double scale = 1.0 + max_abs(j.su) + max_abs(j.sv) + max_abs(j.suu) + max_abs(j.svv);
            EXPECT_LE(max_abs(j.su - su), 1e-7 * scale) << "rational " << rational;
            EXPECT_LE(max_abs(j.sv - sv), 1e-7 * scale);
            EXPECT_LE(max_abs(j.suu - suu), 1e-6 * scale);
            EXPECT_LE(max_abs(j.suv - suv), 1e-6 * scale);
            EXPECT_LE(max_abs(j.svv - svv), 1e-6 * scale);
        }
}

TEST(BezierPatch, SubPatchIsTheSameSurface) {
    std::mt19937 rng(4);
    for (bool rational : {false, true})
        for (int n = 0; n < 30; ++n) {
            BezierPatch p = random_patch(rng, rational);
            double u0 = uniform(rng), u1 = uniform(rng), v0 = uniform(rng), v1 = uniform(rng);
            BezierPatch q = sub_patch(p, u0, u1, v0, v1);
            EXPECT_EQ(is_rational(q), rational);
            for (int k = 0; k < 20; ++k) {
                double s = uniform(rng), t = uniform(rng);
                dvec3 a = evaluate(q, s, t);
                dvec3 b = evaluate(p, u0 + s * (u1 - u0), v0 + t * (v1 - v0));
                EXPECT_LE(max_abs(a - b), 1e-13);
            }
        }
}

TEST(BezierPatch, SplitHalvesShareTheirEdgeExactly) {
    std::mt19937 rng(5);
    for (bool rational : {false, true}) {
        BezierPatch p = random_patch(rng, rational);
        auto [lo, hi] = split_u(p, 0.37);
        auto [left, right] = split_v(p, 0.61);
        for (int j = 0; j < 4; ++j) {
            EXPECT_EQ(control_point(lo, 3, j), control_point(hi, 0, j));
            EXPECT_EQ(lo.weights[12 + j], hi.weights[j]);
            EXPECT_EQ(control_point(left, j, 3), control_point(right, j, 0));
        }
        for (double s : {0.0, 0.3, 0.8, 1.0}) {
            EXPECT_LE(max_abs(evaluate(lo, s, 0.4) - evaluate(p, 0.37 * s, 0.4)), 1e-14);
            EXPECT_LE(max_abs(evaluate(hi, s, 0.4) - evaluate(p, 0.37 + 0.63 * s, 0.4)), 1e-14);
            EXPECT_LE(max_abs(evaluate(right, 0.2, s) - evaluate(p, 0.2, 0.61 + 0.39 * s)), 1e-14);
        }
    }
}

TEST(BezierPatch, WholeDomainSubPatchIsTheSamePatch) {
    std::mt19937 rng(6);
    for (bool rational : {false, true}) {
        BezierPatch p = random_patch(rng, rational);
        BezierPatch q = sub_patch(p, 0, 1, 0, 1);
        for (int k = 0; k < 16; ++k) {
            EXPECT_LE(max_abs(q.points[k] - p.points[k]), rational ? 1e-15 : 0.0);
            EXPECT_NEAR(q.weights[k], p.weights[k], 1e-15);
        }
    }
}

TEST(BezierPatch, SplittingKeepsCollapsedEdgesCollapsed) {
    const BezierPatch& lid = test::teapot()[20];  // row 0 is the lid apex, four equal points
    BezierPatch q = sub_patch(lid, 0.0, 0.3, 0.25, 0.8);
    for (int j = 1; j < 4; ++j) EXPECT_EQ(control_point(q, 0, j), control_point(q, 0, 0));
    EXPECT_EQ(control_point(q, 0, 0), dvec3(0, 0, 3.15));
}

TEST(BezierPatch, BoundsHoldEverySampledPoint) {
    std::mt19937 rng(7);
    std::vector<BezierPatch> patches = test::teapot();
    for (int n = 0; n < 20; ++n) patches.push_back(random_patch(rng, n % 2 == 1));
    for (const BezierPatch& p : patches) {
        PatchBounds b = bounds(p);
        for (int i = 0; i <= 24; ++i)
            for (int j = 0; j <= 24; ++j) {
                dvec3 s = evaluate(p, i / 24.0, j / 24.0);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_GE(s[c], b.min[c] - 1e-14);
                    EXPECT_LE(s[c], b.max[c] + 1e-14);
                }
            }
        // ...and the box is that of the control points, not a looser one.
        for (int c = 0; c < 3; ++c) {
            double lo = 1e30, hi = -1e30;
            for (const dvec3& q : p.points) lo = std::min(lo, q[c]), hi = std::max(hi, q[c]);
            EXPECT_EQ(b.min[c], lo);
            EXPECT_EQ(b.max[c], hi);
        }
    }
}

TEST(BezierPatch, AffineTransformMovesTheSurface) {
    std::mt19937 rng(8);
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), dvec3(1.5, -2.0, 0.25));
    m = glm::rotate(m, 0.7, glm::normalize(dvec3(1, 2, 3)));
    m = glm::scale(m, dvec3(2.0, 0.5, 1.25));
    for (bool rational : {false, true}) {
        BezierPatch p = random_patch(rng, rational);
        BezierPatch q = transformed(p, m);
        EXPECT_EQ(q.weights, p.weights);
        for (int k = 0; k < 20; ++k) {
            double u = uniform(rng), v = uniform(rng);
            dvec3 expected = dvec3(m * glm::dvec4(evaluate(p, u, v), 1.0));
            EXPECT_LE(max_abs(evaluate(q, u, v) - expected), 1e-13);
        }
    }
}

TEST(BezierPatch, RotationRotatesTheNormal) {
    glm::dmat4 r = glm::rotate(glm::dmat4(1.0), 1.1, glm::normalize(dvec3(-1, 0.5, 2)));
    const BezierPatch& body = test::teapot()[4];
    BezierPatch q = transformed(body, r);
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.5, 0.9}) {
            dvec3 expected = glm::dmat3(r) * unit_normal(body, u, v);
            EXPECT_LE(max_abs(unit_normal(q, u, v) - expected), 1e-12);
        }
}

TEST(BezierPatch, ProjectiveMatrixIsRefused) {
    glm::dmat4 m(1.0);
    m[2][3] = 0.5;  // a perspective row
    EXPECT_THROW(transformed(test::teapot()[0], m), std::invalid_argument);
}

bool is_unit(const dvec3& n) {
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) && std::abs(glm::length(n) - 1.0) < 1e-12;
}

TEST(BezierPatch, TeapotNormalsAreUnitEverywhereIncludingTheApexes) {
    const double edge_values[] = {0.0, 1e-300, 1e-12, 1e-7, 0.5, 1.0 - 1e-12, 1.0};
    for (const BezierPatch& p : test::teapot()) {
        for (int i = 0; i <= 32; ++i)
            for (int j = 0; j <= 32; ++j) EXPECT_TRUE(is_unit(unit_normal(p, i / 32.0, j / 32.0)));
        for (double u : edge_values)
            for (double v : edge_values) EXPECT_TRUE(is_unit(unit_normal(p, u, v))) << u << " " << v;
    }
    EXPECT_TRUE(is_unit(unit_normal(test::teapot()[0], std::nan(""), 0.5)));
}

// Su x Sv from central differences of S, where it is well away from zero.
TEST(BezierPatch, NormalsMatchFiniteDifferenceNormals) {
    const double h = 1e-6;
    int compared = 0;
    for (const BezierPatch& p : test::teapot())
        for (int i = 1; i < 16; ++i)
            for (int j = 1; j < 16; ++j) {
                double u = i / 16.0, v = j / 16.0;
                dvec3 su = (evaluate(p, u + h, v) - evaluate(p, u - h, v)) / (2 * h);
                dvec3 sv = (evaluate(p, u, v + h) - evaluate(p, u, v - h)) / (2 * h);
                dvec3 n = glm::cross(su, sv);
                if (glm::length(n) < 1e-3) continue;
                EXPECT_GT(glm::dot(glm::normalize(n), unit_normal(p, u, v)), 1.0 - 1e-9);
                ++compared;
            }
    EXPECT_GT(compared, 32 * 15 * 15 * 9 / 10);
}

// At a collapsed edge Su x Sv = 0; the normal there must be the limit from inside the patch.
TEST(BezierPatch, ApexNormalIsTheLimitOfNearbyNormals) {
    const auto& t = test::teapot();
    for (int k : {20, 21, 22, 23, 28, 29, 30, 31})  // lid (apex z = 3.15) and bottom (centre z = 0)
        for (double v : {0.0, 0.2, 0.5, 0.9, 1.0}) {
            dvec3 at = unit_normal(t[k], 0.0, v);
            dvec3 near = unit_normal(t[k], 1e-5, v);
            EXPECT_GT(glm::dot(at, near), 1.0 - 1e-8) << "patch " << k + 1 << " v " << v;
            EXPECT_NEAR(std::abs(at.z), 1.0, 1e-12);  // both apexes are horizontal
        }
}

TEST(BezierPatch, DegeneratePatchesStillGiveAUnitNormal) {
    BezierPatch point;  // all 16 control points at the origin
    EXPECT_TRUE(is_unit(unit_normal(point, 0.5, 0.5)));
    BezierPatch line;  // a segment: every row the same
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) line.points[4 * i + j] = dvec3(j, 0, 0);
    EXPECT_TRUE(is_unit(unit_normal(line, 0.3, 0.6)));
}

TEST(BezierPatch, RationalFlagFollowsTheWeights) {
    BezierPatch p = test::teapot()[0];
    EXPECT_FALSE(is_rational(p));
    p.weights[5] = 2.0;
    EXPECT_TRUE(is_rational(p));
}

}  // namespace
}  // namespace lancer::surface
