// The CPU reference intersector for parametric surfaces: against the analytic sphere, aimed rays
// (a ray aimed at S(u0, v0) must hit it at t = 1 unless something is nearer), tangent and
// grazing rays, poles, seams, self-intersections, partly undefined surfaces, and its speed.
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "unit/surface_fixtures.hpp"

namespace lancer::cpu {
namespace {

using surface::ParametricSurface;
using std::numbers::pi;

bool is_unit(const dvec3& n) { return std::isfinite(n.x + n.y + n.z) && std::abs(glm::length(n) - 1.0) < 1e-12; }

// The analytic sphere's nearest t > t_min along o + t d (|d| = 1), or nothing.
std::optional<double> sphere_t(const dvec3& c, double r, const dvec3& o, const dvec3& d, double t_min) {
    dvec3 f = o - c;
    double b = glm::dot(f, d);
    dvec3 perp = f - b * d;
    double disc = r * r - glm::dot(perp, perp);
    if (disc < 0.0) return std::nullopt;
    double root = std::sqrt(disc);
    double t0 = -b - root, t1 = -b + root;
    if (t0 > t_min) return t0;
    if (t1 > t_min) return t1;
    return std::nullopt;
}

TEST(ParametricIntersect, SphereAgreesWithTheAnalyticSphere) {
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));
    const double R = 1.5;
    const dvec3 centre(0.5, -0.25, 2.0);
    s.to_world = glm::translate(glm::dmat4(1.0), centre);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int hits = 0, compared = 0;
    double worst_t = 0.0, worst_normal = 0.0;
    for (int i = 0; i < 2000; ++i) {
        dvec3 o = centre + dvec3(unit(rng), unit(rng), unit(rng)) * 5.0;
        if (i % 10 == 0) o = centre + dvec3(unit(rng), unit(rng), unit(rng)) * 0.5;  // from inside
        dvec3 aim = centre + dvec3(unit(rng), unit(rng), unit(rng)) * (1.3 * R);
        dvec3 d = glm::normalize(aim - o);
        // Skip rays within rounding of the silhouette, where hit or miss is a coin toss.
        dvec3 f = o - centre;
        double miss_distance = glm::length(f - glm::dot(f, d) * d);
        if (std::abs(miss_distance - R) < 1e-7) continue;
        ++compared;
        auto expected = sphere_t(centre, R, o, d, 1e-9);
        auto hit = intersect(s, {o, d}, 1e-9, 1e30);
        ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i << " miss distance " << miss_distance;
        if (!hit) continue;
        ++hits;
        worst_t = std::max(worst_t, std::abs(hit->t - *expected));
        ASSERT_NEAR(hit->t, *expected, 1e-9) << "ray " << i;
        dvec3 n = glm::normalize(o + hit->t * d - centre);
        ASSERT_TRUE(is_unit(hit->normal));
        worst_normal = std::max(worst_normal, glm::length(hit->normal - n));
        ASSERT_NEAR(glm::length(hit->normal - n), 0.0, 1e-6) << "ray " << i;
        ASSERT_GE(hit->uv.x, s.u0);
        ASSERT_LE(hit->uv.x, s.u1);
        ASSERT_GE(hit->uv.y, s.v0);
        ASSERT_LE(hit->uv.y, s.v1);
    }
    std::cout << "[ sphere   ] " << compared << " rays, " << hits << " hits, max |dt| " << worst_t
              << ", max |dn| " << worst_normal << "\n";
    EXPECT_GT(hits, 600);
}

TEST(ParametricIntersect, SpherePolesAndSeam) {
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));  // R = 1.5
    auto top = intersect(s, {{0, 0, 5}, {0, 0, -1}}, 0.0, 1e30);  // through the pole v = pi/2
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 3.5, 1e-9);
    EXPECT_NEAR(glm::length(top->normal - dvec3(0, 0, 1)), 0.0, 1e-6);
    auto bottom = intersect(s, {{0, 0, -5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(bottom);
    EXPECT_NEAR(bottom->t, 3.5, 1e-9);
    EXPECT_NEAR(glm::length(bottom->normal - dvec3(0, 0, -1)), 0.0, 1e-6);
    auto near_pole = intersect(s, {{1e-7, 2e-7, 5}, {0, 0, -1}}, 0.0, 1e30);
    ASSERT_TRUE(near_pole);
    EXPECT_NEAR(near_pole->t, 5.0 - std::sqrt(2.25 - 5e-14), 1e-9);
    auto seam = intersect(s, {{5, 0, 0.3}, {-1, 0, 0}}, 0.0, 1e30);  // u = 0 = 2 pi
    ASSERT_TRUE(seam);
    EXPECT_NEAR(seam->t, 5.0 - std::sqrt(2.25 - 0.09), 1e-9);
}

TEST(ParametricIntersect, RespectsTheInterval) {
    ParametricSurface s = test::make_surface(test::surface_spec("sphere"));
    EXPECT_FALSE(intersect(s, {{0, 0, -5}, {0, 0, 1}}, 0.0, 3.4));
    auto far = intersect(s, {{0, 0, -5}, {0, 0, 1}}, 4.0, 1e30);
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 6.5, 1e-9);
    EXPECT_FALSE(intersect(s, {{0, 0, -5}, {0, 0, -1}}, 0.0, 1e30));  // pointing away
}

struct AimedStats {
    int at_target = 0, nearer = 0;
};

// Rays from random origins aimed at random S(u0, v0), d = S - o unnormalised: a hit at t = 1,
// or a genuine hit (on the surface, inside the domain) nearer than that.
// With an implicit equation of the surface, also checks that no crossing of the surface comes
// before the reported hit (an independent test that the hit is the nearest).
AimedStats aimed_rays(const ParametricSurface& s, int count, unsigned seed, double spread,
                      double (*implicit)(const dvec3&) = nullptr) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    AimedStats stats;
    for (int i = 0; i < count; ++i) {
        double u0 = s.u0 + (s.u1 - s.u0) * unit(rng), v0 = s.v0 + (s.v1 - s.v0) * unit(rng);
        dvec3 target = surface::evaluate_surface(s, u0, v0).P;
        dvec3 o = target + spread * glm::normalize(dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        dvec3 d = target - o;
        auto hit = intersect(s, {o, d}, 1e-9, 1.0 + 1e-6);
        EXPECT_TRUE(hit) << "ray " << i << " aimed at (" << u0 << ", " << v0 << ")";
        if (!hit) continue;
        EXPECT_TRUE(is_unit(hit->normal));
        if (implicit) {
            const int samples = 2000;
            double first = implicit(o);
            for (int k = 1; k <= samples; ++k) {
                double t = hit->t * (1.0 - 1e-6) * k / samples;
                if (std::signbit(implicit(o + t * d)) != std::signbit(first)) {
                    ADD_FAILURE() << "ray " << i << " crosses the surface at t ~ " << t << " before its hit at "
                                  << hit->t;
                    break;
                }
            }
        }
        if (std::abs(hit->t - 1.0) <= 1e-9) {
            ++stats.at_target;
            continue;
        }
        EXPECT_LT(hit->t, 1.0) << "ray " << i << " aimed at (" << u0 << ", " << v0 << "), got t = " << hit->t;
        ++stats.nearer;
        dvec3 p = surface::evaluate_surface(s, hit->uv.x, hit->uv.y).P;
        EXPECT_LT(glm::length(p - (o + hit->t * d)), 1e-9 * (1.0 + glm::length(p)));
        EXPECT_TRUE(hit->uv.x >= s.u0 && hit->uv.x <= s.u1 && hit->uv.y >= s.v0 && hit->uv.y <= s.v1);
    }
    return stats;
}

// The torus's implicit equation (R = 1, r = 0.35): negative inside the tube.
double torus_implicit(const dvec3& p) {
    const double R = 1.0, r = 0.35;
    double q = glm::dot(p, p) + R * R - r * r;
    return q * q - 4 * R * R * (p.x * p.x + p.y * p.y);
}

TEST(ParametricIntersect, AimedRaysHitTheTorusAtTheirTarget) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    AimedStats stats = aimed_rays(s, 2000, 41, 3.0, torus_implicit);
    std::cout << "[ torus    ] aimed: " << stats.at_target << " at t = 1, " << stats.nearer << " nearer\n";
    EXPECT_GT(stats.at_target, 700);
    EXPECT_GT(stats.nearer, 100);  // the test sees occlusion at all
}

TEST(ParametricIntersect, AimedRaysHitATransformedTorus) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    s.to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(10.0, -3.0, 7.0)) *
                 glm::rotate(glm::dmat4(1.0), 1.1, glm::normalize(glm::dvec3(0.3, 1.0, 0.2))) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(2.0, 2.0, 0.75));
    AimedStats stats = aimed_rays(s, 500, 42, 6.0);
    EXPECT_GT(stats.at_target, 200);
}

TEST(ParametricIntersect, AimedRaysOnSelfIntersectingAndSingularSurfaces) {
    for (const char* name : {"klein8", "mobius", "enneper", "dini", "sphere"}) {
        SCOPED_TRACE(name);
        ParametricSurface s = test::make_surface(test::surface_spec(name));
        AimedStats stats = aimed_rays(s, 300, 43, 4.0);
        std::cout << "[ " << name << " ] aimed: " << stats.at_target << " at t = 1, " << stats.nearer << " nearer\n";
        EXPECT_GT(stats.at_target, 75);
    }
}

TEST(ParametricIntersect, TangentRaysEndWithoutNaN) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    std::mt19937 rng(51);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        double u = 2 * pi * unit(rng), v = 2 * pi * unit(rng);
        surface::SurfacePoint p = surface::evaluate_surface(s, u, v);
        double a = 2 * pi * unit(rng);
        dvec3 d = glm::normalize(std::cos(a) * glm::normalize(p.Pu) + std::sin(a) * glm::normalize(p.Pv));
        d = glm::normalize(d - glm::dot(d, surface::surface_normal(s, u, v)) * surface::surface_normal(s, u, v));
        auto hit = intersect(s, {p.P - 2.0 * d, d}, 1e-9, 1e30);
        if (!hit) continue;
        ++hits;
        ASSERT_TRUE(std::isfinite(hit->t));
        ASSERT_TRUE(is_unit(hit->normal));
        ASSERT_LE(hit->t, 2.0 + 1e-3) << "the tangent point itself is on the ray";
    }
    EXPECT_GT(hits, 150);
    // Tangent to the outer equator: touches at (0, 1.35, 0) and nowhere else.
    auto touch = intersect(s, {{-3.0, 1.35, 0.0}, {1.0, 0.0, 0.0}}, 0.0, 1e30);
    if (touch) {
        EXPECT_NEAR(touch->t, 3.0, 1e-3);
    }
    // Tangent to the top circle z = r along its tangent: touches at (1, 0, 0.35).
    auto top = intersect(s, {{1.0, -3.0, 0.35}, {0.0, 1.0, 0.0}}, 0.0, 1e30);
    if (top) {
        EXPECT_NEAR(top->t, 3.0, 1e-3);
    }
}

TEST(ParametricIntersect, SecondaryRaysLeaveTheSurface) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    auto first = intersect(s, {{-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0.0, 1e30);
    ASSERT_TRUE(first);
    EXPECT_NEAR(first->t, 3.0 - 1.35, 1e-10);
    EXPECT_NEAR(glm::length(first->normal - dvec3(-1, 0, 0)), 0.0, 1e-9);
    dvec3 p{-1.35, 0.0, 0.0};
    auto second = intersect(s, {p, {1.0, 0.0, 0.0}}, 1e-4, 1e30);  // through the tube, then the hole
    ASSERT_TRUE(second);
    EXPECT_NEAR(second->t, 0.7, 1e-10);
}

TEST(ParametricIntersect, PartlyUndefinedSurface) {
    // The upper unit hemisphere over the square: undefined outside the disc, infinitely steep at
    // its rim, so boxes there are not smooth and Krawczyk is not used on them.
    ParametricSurface s;
    s.x = surface::parse_expression("u", {});
    s.y = surface::parse_expression("v", {});
    s.z = surface::parse_expression("sqrt(1 - u^2 - v^2)", {});
    s.u0 = s.v0 = -1.0;
    s.u1 = s.v1 = 1.0;
    std::mt19937 rng(61);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        double x = unit(rng), y = unit(rng);
        auto hit = intersect(s, {{x, y, 3.0}, {0.0, 0.0, -1.0}}, 0.0, 1e30);
        double r2 = x * x + y * y;
        if (r2 > 1.0 + 1e-9) {
            EXPECT_FALSE(hit) << x << ", " << y;
        } else if (r2 < 0.95) {
            ASSERT_TRUE(hit) << x << ", " << y;
            EXPECT_NEAR(hit->t, 3.0 - std::sqrt(1.0 - r2), 1e-9);
            EXPECT_NEAR(glm::length(hit->normal - dvec3(x, y, std::sqrt(1.0 - r2))), 0.0, 1e-6);
        }
    }
}

TEST(ParametricIntersect, DegenerateInputsGiveNoHit) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    EXPECT_FALSE(intersect(s, {{-3, 0, 0}, {0, 0, 0}}, 0.0, 1e30));  // no direction
    ParametricSurface flat = test::make_surface(test::surface_spec("torus"));
    flat.to_world = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, 0.0));
    EXPECT_FALSE(intersect(flat, {{0.5, 0.5, -3}, {0, 0, 1}}, 0.0, 1e30));
}

TEST(ParametricIntersect, AChangedSurfaceIsCaught) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    ASSERT_TRUE(intersect(s, {{-3, 0, 0}, {1, 0, 0}}, 0.0, 1e30));
    ParametricSurface copy = s;  // a copy starts afresh
    copy.u1 = pi;
    EXPECT_TRUE(intersect(copy, {{-3, 0, 0}, {1, 0, 0}}, 0.0, 1e30));
    s.u1 = pi;
    EXPECT_THROW(intersect(s, {{-3, 0, 0}, {1, 0, 0}}, 0.0, 1e30), std::logic_error);
}

}  // namespace
}  // namespace lancer::cpu
