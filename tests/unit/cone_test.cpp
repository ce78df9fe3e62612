// The reference's cone and cylinder (host/cpu/shapes/cone.cpp), its readers' checks, its box and
// its texture mapping.
#include <cmath>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/shape_bounds.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/animation.hpp"
#include "support/test_support.hpp"

namespace lancer::cpu {
namespace {

constexpr double kBeyond = 1e30;

Cone cone_from(const std::string& keys) {
    Scene s = test::scene_from_text("[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\n" + keys);
    return std::get<Cone>(s.objects.at(0).shape);
}

// Radius 1 about the y axis from y = 0 to y = 2 (the reader sets the texture's axes).
Cone upright_cylinder(bool open = false) {
    return cone_from(std::string("type = \"cylinder\"\nbase_point = [0, 0, 0]\ncap_point = [0, 2, 0]\nradius = 1\n") +
                      (open ? "open = true\n" : ""));
}

// Radius 2 at y = 0 to radius 1 at y = 1 about the y axis: its apex would be at y = 2.
Cone frustum() {
    return cone_from("type = \"cone\"\nbase_point = [0, 0, 0]\nbase_radius = 2\ncap_point = [0, 1, 0]\ncap_radius = 1\n");
}

// Pointed: radius 1 at y = 0, the apex at y = 3.
Cone pointed() {
    return cone_from("type = \"cone\"\nbase_point = [0, 0, 0]\nbase_radius = 1\ncap_point = [0, 3, 0]\ncap_radius = 0\n");
}

TEST(Cone, CylinderSideHitFromOutside) {
    auto h = intersect(upright_cylinder(), {{0, 1, -5}, {0, 0, 1}}, 0.0, kBeyond);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4.0);
    EXPECT_NEAR(glm::length(h->normal - dvec3(0, 0, -1)), 0.0, 1e-15);
    EXPECT_EQ(h->uv.x, 0.0);  // the side
}

TEST(Cone, CapsAreDiscsWithAxisNormals) {
    Cone c = upright_cylinder();
    auto top = intersect(c, {{0.3, 5, 0.2}, {0, -1, 0}}, 0.0, kBeyond);
    auto bottom = intersect(c, {{0.3, -5, 0.2}, {0, 1, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(top && bottom);
    EXPECT_DOUBLE_EQ(top->t, 3.0);
    EXPECT_DOUBLE_EQ(bottom->t, 5.0);
    EXPECT_EQ(top->normal, dvec3(0, 1, 0));
    EXPECT_EQ(bottom->normal, dvec3(0, -1, 0));
    EXPECT_EQ(top->uv.x, 2.0);
    EXPECT_EQ(bottom->uv.x, 1.0);
}

TEST(Cone, OpenHasNoCapsButItsInsideShows) {
    Cone c = upright_cylinder(true);
    // Down the axis: through both open ends.
    EXPECT_FALSE(intersect(c, {{0.3, 5, 0.2}, {0, -1, 0}}, 0.0, kBeyond));
    // Slanting in through the open top: the inside of the far wall.
    dvec3 dir = glm::normalize(dvec3(1, -1, 0));
    auto h = intersect(c, {{0, 2.5, 0}, dir}, 0.0, kBeyond);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, std::sqrt(2.0), 1e-14);  // at (1, 1.5, 0)
    EXPECT_NEAR(glm::length(h->normal - dvec3(1, 0, 0)), 0.0, 1e-15);  // the geometric (outward) normal
}

TEST(Cone, FromInsideHitsTheWallOrTheCap) {
    Cone c = upright_cylinder();
    auto side = intersect(c, {{0, 1, 0}, {1, 0, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(side);
    EXPECT_DOUBLE_EQ(side->t, 1.0);
    auto cap = intersect(c, {{0, 1, 0}, {0, 1, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(cap);
    EXPECT_DOUBLE_EQ(cap->t, 1.0);
    EXPECT_EQ(cap->uv.x, 2.0);
    // Open: from inside, up the axis, nothing.
    EXPECT_FALSE(intersect(upright_cylinder(true), {{0, 1, 0}, {0, 1, 0}}, 0.0, kBeyond));
}

TEST(Cone, MissesBesideBeyondAndOutsideTheRange) {
    Cone c = upright_cylinder();
    EXPECT_FALSE(intersect(c, {{1.01, 1, -5}, {0, 0, 1}}, 0.0, kBeyond));  // beside
    EXPECT_FALSE(intersect(c, {{0, 2.01, -5}, {0, 0, 1}}, 0.0, kBeyond));  // above the cap
    EXPECT_FALSE(intersect(c, {{0, -0.01, -5}, {0, 0, 1}}, 0.0, kBeyond)); // below the base
    EXPECT_FALSE(intersect(c, {{0, 1, -5}, {0, 0, -1}}, 0.0, kBeyond));   // going away
    EXPECT_FALSE(intersect(c, {{0, 1, -5}, {0, 0, 1}}, 0.0, 3.9));     // beyond t_max
    auto far_side = intersect(c, {{0, 1, -5}, {0, 0, 1}}, 4.1, kBeyond);  // past the near wall: the far one
    ASSERT_TRUE(far_side);
    EXPECT_DOUBLE_EQ(far_side->t, 6.0);
}

TEST(Cone, RimBelongsToIt) {
    Cone c = upright_cylinder(true);
    // Along the top rim's plane, tangent to the rim circle at (1, 2, 0)... and through the rim.
    auto h = intersect(c, {{-5, 2, 0}, {1, 0, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4.0);
    EXPECT_TRUE(intersect(c, {{1, 2, -5}, {0, 0, 1}}, 0.0, kBeyond));  // grazing the rim's outermost point
}

TEST(Cone, GrazingRaysNearTheRimHitTheSideOrTheCap) {
    Cone c = upright_cylinder();
    for (double e : {1e-3, 1e-6, 1e-9}) {
        // Just below the top's plane, across: the side at x = -1 (t = 4).
        auto below = intersect(c, {{-5, 2 - e, 0}, {1, 0, 0}}, 0.0, kBeyond);
        ASSERT_TRUE(below) << e;
        EXPECT_NEAR(below->t, 4.0, 1e-12) << e;
        EXPECT_EQ(below->uv.x, 0.0) << e;
        // Just above it, descending slowly: the cap.
        dvec3 dir = glm::normalize(dvec3(1, -e, 0));
        auto cap = intersect(c, {{-0.5, 2 + 0.25 * e, 0}, dir}, 0.0, kBeyond);
        ASSERT_TRUE(cap) << e;
        EXPECT_EQ(cap->uv.x, 2.0) << e;
        EXPECT_NEAR(cap->t, 0.25 * std::sqrt(1 + e * e), 1e-15 / e) << e;  // the plane's height error over e
    }
}

TEST(Cone, FrustumSideNormalAccountsForTheSlope) {
    Cone c = frustum();
    // At y = 0.5 the radius is 1.5: a ray along +z at x = 0 meets the side at z = -1.5.
    auto h = intersect(c, {{0, 0.5, -5}, {0, 0, 1}}, 0.0, kBeyond);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.5, 1e-14);
    // r(y) = 2 - y: the side's outward normal is (0, 1, -1) / sqrt 2 there.
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(dvec3(0, 1, -1))), 0.0, 1e-15);
    // Above the cap's plane, within its base radius: a miss.
    EXPECT_FALSE(intersect(c, {{1.5, 1.2, -5}, {0, 0, 1}}, 0.0, kBeyond));
    // Down onto the top: the cap disc of radius 1, not the base's 2.
    EXPECT_TRUE(intersect(c, {{0.99, 5, 0}, {0, -1, 0}}, 0.0, kBeyond));
    auto slope = intersect(c, {{1.5, 5, 0}, {0, -1, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(slope);
    EXPECT_NEAR(slope->t, 4.5, 1e-14);  // the side at y = 0.5
}

// The side of a pointed cone meets a ray where |(x, z)| = 1 - y / 3; the apex is on it, and
// the other nappe beyond the apex (which the quadratic includes) is not.
TEST(Cone, PointedConeAndItsApex) {
    Cone c = pointed();
    auto apex = intersect(c, {{0, 5, 0}, {0, -1, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(apex);
    EXPECT_NEAR(apex->t, 2.0, 1e-14);
    EXPECT_NEAR(glm::length(apex->normal), 1.0, 1e-15);
    EXPECT_EQ(apex->uv.x, 0.0);  // the side: no disc at a radius of 0
    // Horizontally at y = 4 (the other nappe's radius would be 1/3 there): nothing.
    EXPECT_FALSE(intersect(c, {{0, 4, -5}, {0, 0, 1}}, 0.0, kBeyond));
    // At y = 1.5 the radius is 0.5.
    auto h = intersect(c, {{0, 1.5, -5}, {0, 0, 1}}, 0.0, kBeyond);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-14);
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(dvec3(0, 1.0 / 3.0, -1))), 0.0, 1e-15);
    // From below: the base disc.
    auto base = intersect(c, {{0.2, -1, 0.1}, {0, 1, 0}}, 0.0, kBeyond);
    ASSERT_TRUE(base);
    EXPECT_EQ(base->uv.x, 1.0);
}

// A tilted cylinder against a hand-made parametrisation: points c(theta, s) = base + s axis +
// r (cos theta e1 + sin theta e2), with a ray aimed at each from outside along the outward
// normal's opposite, far from the world origin.
TEST(Cone, TiltedCylinderFarFromTheOriginAgainstItsParametrisation) {
    Cone c = cone_from(
        "type = \"cylinder\"\nbase_point = [3e5, -2e5, 7e5]\ncap_point = [300001, -199998, 699999.5]\nradius = 0.25\n");
    const dvec3 axis = glm::normalize(c.cap - c.base);
    const double h = glm::length(c.cap - c.base);
    const dvec3 e1 = glm::normalize(glm::cross(axis, dvec3(0, 0, 1))), e2 = glm::cross(axis, e1);
    for (int i = 0; i < 24; ++i) {
        double theta = 0.27 * i, s = h * (0.02 + 0.96 * (i % 7) / 6.0);
        dvec3 radial = std::cos(theta) * e1 + std::sin(theta) * e2;
        dvec3 target = c.base + s * axis + 0.25 * radial;
        dvec3 dir = glm::normalize(-radial + 0.3 * axis);
        auto hit = intersect(c, {target - 5.0 * dir, dir}, 0.0, kBeyond);
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->t, 5.0, 1e-9) << i;
        EXPECT_NEAR(glm::length(hit->normal - radial), 0.0, 1e-9) << i;
    }
}

// Rays aimed at random points of a tilted truncated cone's side and ends from random directions
// from outside hit them (a convex solid: nothing else is in the way from outside); rays aimed
// just beyond the rims or the ends miss the solid's surface there; a ray leaving a hit to the
// outside never meets it again.
TEST(Cone, AimedRandomRaysHitTheirTargetAndLeavingRaysEscape) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Cone c = cone_from(
        "type = \"cone\"\nbase_point = [0.3, -0.2, 0.7]\nbase_radius = 1.3\ncap_point = [-0.5, 1.6, 1.1]\ncap_radius = 0.4\n");
    const dvec3 axis = glm::normalize(c.cap - c.base);
    const double h = glm::length(c.cap - c.base), k = (c.cap_radius - c.base_radius) / h;
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        double angle = M_PI * u(rng), s = 0.5 + 0.5 * u(rng);
        dvec3 radial = std::cos(angle) * c.u_axis + std::sin(angle) * c.v_axis;
        dvec3 target, normal;
        int part = i % 3;
        if (part == 0) {  // the side
            target = c.base + s * h * axis + (c.base_radius + k * s * h) * radial;
            normal = glm::normalize(radial - k * axis);
        } else {  // an end's disc
            bool top = part == 2;
            target = (top ? c.cap : c.base) + s * 0.999 * (top ? c.cap_radius : c.base_radius) * radial;
            normal = top ? axis : -axis;
        }
        dvec3 dir = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
        if (glm::dot(dir, normal) > -1e-3) dir = glm::reflect(dir, normal);
        if (glm::dot(dir, normal) > -1e-3) continue;
        double distance = 0.01 + 10.0 * std::abs(u(rng));
        auto hit = intersect(c, {target - distance * dir, dir}, 0.0, kBeyond);
        ASSERT_TRUE(hit) << i;
        ++hits;
        EXPECT_NEAR(hit->t, distance, 1e-12 * (1.0 + distance) / std::abs(glm::dot(dir, normal))) << i;
        EXPECT_EQ(int(hit->uv.x), part) << i;
        EXPECT_NEAR(glm::length(hit->normal - normal), 0.0, 1e-9) << i;
        dvec3 out = glm::normalize(normal + 0.9 * dvec3(u(rng), u(rng), u(rng)));
        if (glm::dot(out, normal) <= 0.05) continue;
        Ray leaving{target + ray_offset(target, dvec3(0.0)) * normal, out};
        EXPECT_FALSE(intersect(c, leaving, 0.0, kBeyond)) << i;
    }
    EXPECT_GT(hits, 2900);
    // Just beyond the cap's end along the axis, and just outside the side at mid-height: misses
    // of the surface there (the ray along the surface's normal meets nothing on the other side).
    for (int i = 0; i < 200; ++i) {
        double angle = M_PI * u(rng);
        dvec3 radial = std::cos(angle) * c.u_axis + std::sin(angle) * c.v_axis;
        dvec3 outside = c.base + 0.5 * h * axis + (c.base_radius + k * 0.5 * h) * 1.001 * radial;
        EXPECT_FALSE(intersect(c, {outside, glm::normalize(radial - k * axis)}, 0.0, kBeyond)) << i;
        dvec3 above = c.cap + 0.001 * axis + 0.5 * c.cap_radius * radial;
        EXPECT_FALSE(intersect(c, {above, axis}, 0.0, kBeyond)) << i;
    }
}

TEST(Cone, TextureRoundTheAxisAndAlongIt) {
    Cone c = upright_cylinder();  // u axis +x, v axis +z: the plane's for normal +y
    auto side = [&](double angle, double y, int part) {
        return texture_uv(c, dvec3(std::cos(angle), y, std::sin(angle)), part);
    };
    EXPECT_NEAR(side(0.0, 0.0, 0).x, 0.0, 1e-15);
    EXPECT_NEAR(side(0.0, 0.0, 0).y, 0.0, 1e-15);
    EXPECT_NEAR(side(0.5 * M_PI, 2.0, 0).x, 0.25, 1e-15);
    EXPECT_NEAR(side(0.5 * M_PI, 2.0, 0).y, 1.0, 1e-15);
    EXPECT_NEAR(side(-0.5 * M_PI, 0.5, 0).x, 0.75, 1e-15);
    EXPECT_NEAR(side(-0.5 * M_PI, 0.5, 0).y, 0.25, 1e-15);
    glm::dvec2 lid = texture_uv(c, {0.0, 2.0, 0.5}, 2);
    EXPECT_NEAR(lid.x, 0.25, 1e-15);
    EXPECT_NEAR(lid.y, 0.5, 1e-15);
    EXPECT_EQ(texture_uv(c, {0.0, 0.0, 0.0}, 1), glm::dvec2(0.0, 0.0));  // the base's centre
    EXPECT_GE(side(-1e-17, 1.0, 0).x, 0.0);
    EXPECT_LT(side(-1e-17, 1.0, 0).x, 1.0);
}

TEST(Cone, BoxHoldsBothEndCirclesAndMovesWithThem) {
    Cone c = cone_from("type = \"cone\"\nbase_point = [1, 2, 3]\nbase_radius = 2\ncap_point = [4, 6, 3]\ncap_radius = 0.5\n");
    auto box = shape_bounds(c);
    ASSERT_TRUE(box);
    const dvec3 a = glm::normalize(c.cap - c.base);  // (0.6, 0.8, 0)
    EXPECT_NEAR(box->lo.x, 1.0 - 2.0 * std::sqrt(1.0 - a.x * a.x), 1e-12);
    EXPECT_NEAR(box->hi.x, 4.0 + 0.5 * std::sqrt(1.0 - a.x * a.x), 1e-12);
    EXPECT_NEAR(box->lo.y, 2.0 - 2.0 * 0.6, 1e-12);
    EXPECT_NEAR(box->hi.y, 6.0 + 0.5 * 0.6, 1e-12);
    EXPECT_NEAR(box->lo.z, 1.0, 1e-12);
    EXPECT_NEAR(box->hi.z, 5.0, 1e-12);
    // Every point of the rims is inside.
    for (int i = 0; i < 64; ++i) {
        double angle = 2.0 * M_PI * i / 64.0;
        dvec3 radial = std::cos(angle) * c.u_axis + std::sin(angle) * c.v_axis;
        for (dvec3 p : {c.base + c.base_radius * radial, c.cap + c.cap_radius * radial})
            for (int j = 0; j < 3; ++j) {
                EXPECT_GE(p[j], box->lo[j]);
                EXPECT_LE(p[j], box->hi[j]);
            }
    }
    Shape moved = c;
    translate(moved, {1, 2, 3});
    EXPECT_EQ(std::get<Cone>(moved).base, c.base + dvec3(1, 2, 3));
    EXPECT_EQ(std::get<Cone>(moved).cap, c.cap + dvec3(1, 2, 3));
}

TEST(ConeReader, ReadsPovRaysParameters) {
    Cone cyl = cone_from("type = \"cylinder\"\nbase_point = [1, 2, 3]\ncap_point = [1, 2, 7]\nradius = 1.5\nopen = true\n");
    EXPECT_EQ(cyl.base, dvec3(1, 2, 3));
    EXPECT_EQ(cyl.cap, dvec3(1, 2, 7));
    EXPECT_EQ(cyl.base_radius, 1.5);
    EXPECT_EQ(cyl.cap_radius, 1.5);
    EXPECT_TRUE(cyl.open);
    const dvec3 axis(0, 0, 1);
    EXPECT_NEAR(glm::dot(cyl.u_axis, axis), 0.0, 1e-15);
    EXPECT_NEAR(glm::dot(cyl.v_axis, axis), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::cross(cyl.u_axis, cyl.v_axis) + axis), 0.0, 1e-15);  // u x v = -axis, as the disc's
    Cone cone = cone_from("type = \"cone\"\nbase_point = [0, 0, 0]\nbase_radius = 0\ncap_point = [0, 1, 0]\ncap_radius = 2\n");
    EXPECT_EQ(cone.base_radius, 0.0);
    EXPECT_EQ(cone.cap_radius, 2.0);
    EXPECT_FALSE(cone.open);
}

// Each bad value fails at its key's line and column (line 6 is the first key after the head); a
// missing key fails at the [[object]] line.
void expect_cone_refused(const std::string& type, const std::string& keys, int line, int column, const std::string& message) {
    test::expect_scene_error("[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"" + type + "\"\n" + keys, line, column, message);
}

TEST(ConeReader, RefusesDegenerateCylinders) {
    expect_cone_refused("cylinder", "base_point = [0, 0, 0]\ncap_point = [0, 1, 0]\nradius = 0\n", 8, 10, "cylinder radius must be positive");
    expect_cone_refused("cylinder", "base_point = [0, 0, 0]\ncap_point = [0, 1, 0]\nradius = -1\n", 8, 10, "cylinder radius must be positive");
    expect_cone_refused("cylinder", "base_point = [1, 2, 3]\ncap_point = [1, 2, 3]\nradius = 1\n", 7, 13, "must differ from base_point");
    expect_cone_refused("cylinder", "base_point = [1e6, 0, 0]\ncap_point = [1000000.0000000001, 0, 0]\nradius = 1\n", 7, 13,
                   "must differ from base_point");  // 1e-10 long at 1e6: no direction
    expect_cone_refused("cylinder", "base_point = [0, 0, 0]\ncap_point = [0, 1, 0]\nradius = 1\nopen = 1\n", 9, 8, "open");
    expect_cone_refused("cylinder", "base_point = [0, 0, 0]\ncap_point = [0, 1, 0]\n", 4, 1, "radius");  // at its [[object]]
    expect_cone_refused("cylinder", "base_point = [0, nan, 0]\ncap_point = [0, 1, 0]\nradius = 1\n", 6, 18, "finite");
}

TEST(ConeReader, RefusesDegenerateCones) {
    const std::string axis = "base_point = [0, 0, 0]\ncap_point = [0, 1, 0]\n";
    expect_cone_refused("cone", axis + "base_radius = -1\ncap_radius = 1\n", 8, 15, "cone base_radius must not be negative");
    expect_cone_refused("cone", axis + "base_radius = 1\ncap_radius = -0.5\n", 9, 14, "cone cap_radius must not be negative");
    expect_cone_refused("cone", axis + "base_radius = 0\ncap_radius = 0\n", 9, 14, "must not both be 0");
    expect_cone_refused("cone", "base_point = [0, 0, 0]\ncap_point = [0, 0, 0]\nbase_radius = 1\ncap_radius = 0\n", 7, 13,
                   "must differ from base_point");
    expect_cone_refused("cone", axis + "radius = 1\n", 4, 1, "base_radius");  // a cylinder's key: base_radius missing
}

}  // namespace
}  // namespace lancer::cpu
