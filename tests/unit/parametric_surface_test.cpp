// Surface evaluation in world space and the robust normal: exact where the parametrisation is
// regular, the limit normal at poles and singular curves, never NaN anywhere.
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "unit/surface_fixtures.hpp"

namespace lancer::surface {
namespace {

using std::numbers::pi;

TEST(ParametricSurface, EvaluatesPointAndPartialsInWorldSpace) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));  // R = 1, r = 0.35
    SurfacePoint p = evaluate_surface(s, pi / 2, 0.0);
    EXPECT_NEAR(glm::length(p.P - dvec3(0.0, 1.35, 0.0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(p.Pu - dvec3(-1.35, 0.0, 0.0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(p.Pv - dvec3(0.0, 0.0, 0.35)), 0.0, 1e-15);
    s.to_world = glm::translate(glm::dmat4(1.0), dvec3(1, 2, 3)) * glm::scale(glm::dmat4(1.0), dvec3(2, 2, 2));
    SurfacePoint q = evaluate_surface(s, pi / 2, 0.0);
    EXPECT_NEAR(glm::length(q.P - dvec3(1.0, 4.7, 3.0)), 0.0, 1e-14);
    EXPECT_NEAR(glm::length(q.Pu - dvec3(-2.7, 0.0, 0.0)), 0.0, 1e-14);
}

TEST(ParametricSurface, NormalIsTheNormalisedCrossProduct) {
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));  // R = 1.5
    for (double u : {0.0, 0.7, 2.0, 5.5}) {
        for (double v : {-1.2, -0.3, 0.0, 0.9}) {
            dvec3 expected(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
            EXPECT_NEAR(glm::length(surface_normal(s, u, v) - expected), 0.0, 1e-14) << u << ", " << v;
        }
    }
}

TEST(ParametricSurface, NormalUnderNonUniformScaleIsTheWorldNormal) {
    // An ellipsoid: the world normal is M^-T times the sphere's, not M times it.
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));
    s.to_world = glm::scale(glm::dmat4(1.0), dvec3(1.0, 2.0, 0.5));
    double u = 0.6, v = 0.4;
    dvec3 local(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
    dvec3 expected = glm::normalize(local / dvec3(1.0, 2.0, 0.5));
    EXPECT_NEAR(glm::length(surface_normal(s, u, v) - expected), 0.0, 1e-14);
}

TEST(ParametricSurface, NormalAtPolesIsTheLimit) {
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));
    for (double u : {0.0, 1.0, 3.0, 2 * pi}) {
        EXPECT_NEAR(glm::length(surface_normal(s, u, pi / 2) - dvec3(0, 0, 1)), 0.0, 1e-6);
        EXPECT_NEAR(glm::length(surface_normal(s, u, -pi / 2) - dvec3(0, 0, -1)), 0.0, 1e-6);
    }
    // A cone x = v cos u, y = v sin u, z = v over v in [0, 1]: the apex has no tangent plane;
    // the normal there is the limit along the inward direction, still a unit vector.
    ParametricSurface cone;
    cone.x = parse_expression("v*cos(u)", {});
    cone.y = parse_expression("v*sin(u)", {});
    cone.z = parse_expression("v", {});
    cone.u1 = 2 * pi;
    dvec3 n = surface_normal(cone, 0.0, 0.0);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(n.z), std::sqrt(0.5), 1e-5);
}

TEST(ParametricSurface, NormalIsNeverNaN) {
    // Every classic surface on a grid that includes its domain's edges, plus a surface whose
    // partials vanish everywhere (a constant point) and one that is undefined.
    for (const auto& spec : test::classic_surfaces()) {
        ParametricSurface s = test::make_surface(spec);
        for (int i = 0; i <= 40; ++i) {
            for (int j = 0; j <= 40; ++j) {
                double u = s.u0 + (s.u1 - s.u0) * i / 40, v = s.v0 + (s.v1 - s.v0) * j / 40;
                dvec3 n = surface_normal(s, u, v);
                ASSERT_NEAR(glm::length(n), 1.0, 1e-12) << spec.name << " at " << u << ", " << v;
            }
        }
    }
    ParametricSurface point;
    point.x = parse_expression("1", {});
    point.y = parse_expression("2", {});
    point.z = parse_expression("3", {});
    EXPECT_NEAR(glm::length(surface_normal(point, 0.5, 0.5)), 1.0, 1e-12);
    ParametricSurface undefined;
    undefined.x = parse_expression("sqrt(-1 - u)", {});
    undefined.y = parse_expression("v", {});
    undefined.z = parse_expression("u", {});
    EXPECT_NEAR(glm::length(surface_normal(undefined, 0.5, 0.5)), 1.0, 1e-12);
}

TEST(ParametricSurface, CopiesStartWithAnEmptyDerivedSlot) {
    ParametricSurface a = test::make_surface(test::surface_spec("torus"));
    const int& built = a.derived.get<int>([] { return 7; });
    EXPECT_EQ(built, 7);
    EXPECT_EQ(a.derived.get<int>([] { return 8; }), 7);  // built once
    ParametricSurface b = a;
    EXPECT_EQ(b.derived.get<int>([] { return 9; }), 9);
    EXPECT_THROW(a.derived.get<double>([] { return 1.0; }), std::logic_error);
}

}  // namespace
}  // namespace lancer::surface
