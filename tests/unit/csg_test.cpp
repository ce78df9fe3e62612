// CSG in the CPU reference against brute force: whether points are inside the combination,
// from each solid's own inside (point tests written here, apart from the intersections), marched
// along random rays; and the loader's refusals.
#include <cmath>
#include <random>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

bool leaf_contains(const Object& leaf, dvec3 p) {
    if (leaf.placement && leaf.placement->shape_in_object_space) p = leaf.placement->object_point(p);
    if (const auto* s = std::get_if<Sphere>(&leaf.shape)) return glm::length(p - s->center) < s->radius;
    if (const auto* b = std::get_if<Box>(&leaf.shape)) return glm::all(glm::lessThan(b->min, p)) && glm::all(glm::lessThan(p, b->max));
    if (const auto* h = std::get_if<Plane>(&leaf.shape)) return glm::dot(p - h->point, h->normal) < 0.0;
    if (const auto* c = std::get_if<Cone>(&leaf.shape)) {
        const dvec3 axis = c->cap - c->base;
        const double z = glm::dot(p - c->base, axis) / glm::dot(axis, axis);
        const double radius = c->base_radius + z * (c->cap_radius - c->base_radius);
        return z > 0.0 && z < 1.0 && glm::length(p - c->base - z * axis) < radius;
    }
    if (const auto* o = std::get_if<Torus>(&leaf.shape)) {  // (|q|^2 + R^2 - r^2)^2 < 4 R^2 rho^2
        const dvec3 q = p - o->center;
        const double y = glm::dot(q, o->axis), rho2 = glm::dot(q, q) - y * y;
        const double R = o->major_radius, r = o->minor_radius, s = glm::dot(q, q) + R * R - r * r;
        return s * s < 4.0 * R * R * rho2;
    }
    if (const auto* s = std::get_if<Superellipsoid>(&leaf.shape)) {  // POV-Ray's g < 1, as written
        const double a = 2.0 / s->e, b = 2.0 / s->n;
        return std::pow(std::pow(std::abs(p.x), a) + std::pow(std::abs(p.y), a), b / a) + std::pow(std::abs(p.z), b) < 1.0;
    }
    if (const auto* i = std::get_if<ImplicitObject>(&leaf.shape))
        return surface::evaluate_implicit(*i->surface, dvec3(i->surface->to_local * glm::dvec4(p, 1.0))).f < 0.0;
    if (const auto* o = std::get_if<Prism>(&leaf.shape)) {  // even-odd over straight outlines: crossings along +x
        if (!(p.y > o->y0 && p.y < o->y1)) return false;
        bool in = false;
        for (const PrismSegment& s : o->segments) {
            EXPECT_EQ(s.degree, 1) << "the point test knows straight outlines";
            const glm::dvec2 a = s.p[0], b = s.p[1];
            if ((a.y > p.z) != (b.y > p.z) && p.x < (b.x - a.x) * (p.z - a.y) / (b.y - a.y) + a.x) in = !in;
        }
        return in;
    }
    if (const auto* l = std::get_if<Lathe>(&leaf.shape)) {  // a linear lathe: its polygon in (r, y), even-odd
        if (l->degree != 1) ADD_FAILURE() << "the point test knows linear lathes only";
        const double rho = std::hypot(p.x, p.z);
        bool in = false;
        for (const LatheSegment& g : l->segments)
            if ((g.y[0] > p.y) != (g.y[1] > p.y) && g.r[0] + (p.y - g.y[0]) * (g.r[1] - g.r[0]) / (g.y[1] - g.y[0]) > rho) in = !in;
        return in;
    }
    ADD_FAILURE() << "no point test for this solid";
    return false;
}

bool csg_contains(const Csg& c, const dvec3& p) {
    std::vector<bool> stack;
    for (std::uint32_t op : c.program) {
        if ((op & 15u) == CSG_LEAF) {
            stack.push_back(leaf_contains(c.leaves[op >> 4], p));
        } else if (op == CSG_NOT) {
            stack.back() = !stack.back();
        } else {
            const bool b = stack.back();
            stack.pop_back();
            const bool a = stack.back();
            stack.back() = op == CSG_AND ? (a && b) : op == CSG_OR ? (a || b) : (a && !b);
        }
    }
    return stack.at(0);
}

const char* const kStage = R"(
    [camera]
    eye = [0, 0, -6]
    look_at = [0, 0, 0]
    [material.a]
    color = [1, 0, 0]
    [material.b]
    color = [0, 0, 1]
)";

// Each ray's first boundary of the combination beyond t = 0.01, by the reference, must be where
// points step from one side to the other (just before and after it), and no change of sides
// may lie before it (marched in steps of 5e-4); where the reference finds none, none is seen.
void expect_membership_agrees(const std::string& object) {
    const Scene scene = test::scene_from_text(std::string(kStage) + object);
    const Csg& csg = std::get<Csg>(scene.objects.at(0).shape);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const dvec3 target(1.3 * unit(rng), 1.3 * unit(rng), 1.3 * unit(rng));
        dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)));
        const cpu::Ray ray{target - 3.0 * dir, dir};
        const auto hit = cpu::intersect(csg, ray, 0.01, 6.0);
        const double t_end = hit ? hit->t : 6.0;
        const bool start = csg_contains(csg, ray.origin + 0.01 * ray.dir);
        for (double t = 0.01; t + 5e-4 < t_end - 1e-9; t += 5e-4) {
            ASSERT_EQ(csg_contains(csg, ray.origin + (t + 5e-4) * ray.dir), start)
                << "ray " << i << ": the inside changes near t = " << t << " before the reference's hit at " << t_end;
        }
        if (!hit) continue;
        ++hits;
        const double eps = 1e-7 * (1.0 + hit->t);
        EXPECT_NE(csg_contains(csg, ray.origin + (hit->t - eps) * ray.dir), csg_contains(csg, ray.origin + (hit->t + eps) * ray.dir))
            << "ray " << i << ": no change of sides at the reference's hit t = " << hit->t;
        EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-9);
    }
    EXPECT_GT(hits, 100);  // the rays do meet it
}

TEST(Csg, ADieIsABoxRoundedByASphereLessItsPips) {
    expect_membership_agrees(R"(
        [[object]]
        type = "difference"
        transform = { rotate = [10, 25, 5] }
        objects = [
          { type = "intersection", objects = [ { type = "box", min = [-1, -1, -1], max = [1, 1, 1] },
                                               { type = "sphere", center = [0, 0, 0], radius = 1.38 } ] },
          { type = "sphere", center = [0, 0, -1.06], radius = 0.25, material = "b" },
          { type = "sphere", center = [1.06, 0.5, 0.5], radius = 0.25, material = "b" },
          { type = "sphere", center = [1.06, -0.5, -0.5], radius = 0.25, material = "b" },
        ]
    )");
}

TEST(Csg, HalfSpacesStretchedSolidsMergesAndInverses) {
    expect_membership_agrees(R"(
        [[object]]
        type = "intersection"
        objects = [
          { type = "merge", objects = [ { type = "sphere", center = [0, 0, 0], radius = 1, transform = { scale = [1.4, 0.7, 1] } },
                                        { type = "cylinder", base_point = [0, -1.2, 0], cap_point = [0, 1.2, 0], radius = 0.5 } ] },
          { type = "plane", normal = [1, 1, 0], point = [0.3, 0, 0] },
          { type = "box", min = [-0.3, -0.3, -2], max = [0.3, 0.3, 2], inverse = true },
          { type = "cone", base_point = [0, 0, -1.5], base_radius = 1.6, cap_point = [0, 0, 1.5], cap_radius = 0.4 },
        ]
    )");
}

// Superellipsoids are convex solids of their own (one interval inside along a line): a cube-like
// one (exponents of 40 and 2000) less a rounded one, merged with a pinched one (e = 2: straight
// edges, kinks of |x| along the axes).
TEST(Csg, SuperellipsoidsAreSolids) {
    expect_membership_agrees(R"(
        [[object]]
        type = "merge"
        transform = { rotate = [15, 30, 5] }
        objects = [
          { type = "difference", objects = [
              { type = "superellipsoid", e = 0.05, n = 0.001 },
              { type = "superellipsoid", e = 1, n = 0.5, transform = { scale = 0.8, translate = [0.5, 0.6, -0.7] } } ] },
          { type = "superellipsoid", e = 2, n = 1.5, transform = { scale = [0.6, 1.3, 0.6], translate = [0.3, 0, 0.4] } },
        ]
    )");
}

// Tori and implicit surfaces are not convex: several intervals inside along one ray.
TEST(Csg, ToriAndImplicitSurfacesAreWalkedRootByRoot) {
    expect_membership_agrees(R"(
        [[object]]
        type = "difference"
        transform = { rotate = [20, 10, 0] }
        objects = [
          { type = "torus", major_radius = 0.9, minor_radius = 0.35, transform = { scale = [1, 1.5, 1] } },
          { type = "box", min = [0, -2, -2], max = [2, 2, 0] },
          { type = "implicit", function = "x^4 - 5*x^2 + y^4 - 5*y^2 + z^4 - 5*z^2 + 11.8", box = { min = [-2.9, -2.9, -2.9], max = [2.9, 2.9, 2.9] }, transform = { scale = 0.5 } },
        ]
    )");
    expect_membership_agrees(R"(
        [[object]]
        type = "intersection"
        objects = [
          { type = "superellipsoid", e = 0.3, n = 0.6, transform = { scale = 1.2 } },
          { type = "torus", major_radius = 0.8, minor_radius = 0.5, axis = [1, 1, 0], inverse = true },
        ]
    )");
}

TEST(Csg, PrismsWithHolesAreWalkedRootByRoot) {
    expect_membership_agrees(R"(
        [[object]]
        type = "difference"
        transform = { rotate = [20, 10, 0] }
        objects = [
          { type = "box", min = [-1.2, -1, -1.2], max = [1.2, 1, 1.2] },
          { type = "prism", height1 = -1.5, height2 = 0.6, points = [[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, -1],
            [-0.6, -0.6], [0.6, -0.6], [0, 0.7], [-0.6, -0.6]], transform = { rotate = [70, 0, 20] } },
        ]
    )");
    expect_membership_agrees(R"(
        [[object]]
        type = "intersection"
        objects = [
          { type = "sphere", center = [0, 0, 0], radius = 1.3 },
          { type = "prism", height1 = -1, height2 = 1, points = [[0, 1.5], [0.35, 0.45], [1.4, 0.45], [0.55, -0.2], [0.9, -1.2],
            [0, -0.55], [-0.9, -1.2], [-0.55, -0.2], [-1.4, 0.45], [-0.35, 0.45], [0, 1.5]], transform = { rotate = [-60, 15, 0] } },
        ]
    )");
}

// A lathe's inside is even-odd: a cup (a polygon with a wall and a foot) has several intervals
// along a ray, its hollow outside it.
TEST(Csg, ALatheIsWalkedRootByRoot) {
    expect_membership_agrees(R"(
        [[object]]
        type = "difference"
        transform = { rotate = [25, 0, 10] }
        objects = [
          { type = "lathe", points = [[0, -1], [0.9, -1], [1.1, 1], [0.9, 1], [0.7, -0.6], [0, -0.6], [0, -1]] },
          { type = "box", min = [0, -2, -2], max = [2, 2, 0] },
          { type = "sphere", center = [-0.9, 0.6, 0], radius = 0.45 },
        ]
    )");
}

TEST(Csg, AHitIsTheLeafsWithItsMaterial) {
    const Scene scene = test::scene_from_text(std::string(kStage) + R"(
        [[object]]
        type = "difference"
        material = "a"
        objects = [ { type = "sphere", center = [0, 0, 0], radius = 1 },
                    { type = "box", min = [-2, -2, -2], max = [2, 2, -0.5], material = "b" } ]
    )");
    const Csg& csg = std::get<Csg>(scene.objects.at(0).shape);
    // Along z from in front: the box's cut at z = -0.5 (the blue leaf), facing the ray.
    const auto hit = cpu::intersect(csg, cpu::Ray{dvec3(0, 0, -5), dvec3(0, 0, 1)}, 0.0, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.5, 1e-12);
    EXPECT_EQ(hit->part, 1);
    EXPECT_EQ(scene.materials[csg.leaves[1].material].name, "b");
    EXPECT_EQ(scene.materials[csg.leaves[0].material].name, "a");  // inherited
    // Off the cut, the sphere's far side from inside the cut: none nearer than the sphere's back.
    const auto back = cpu::intersect(csg, cpu::Ray{dvec3(0, 0, 0), dvec3(0, 0, 1)}, 0.0, 100.0);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->t, 1.0, 1e-12);
    EXPECT_EQ(back->part, 0);
}

// Fails at `line` of `objects` (kStage's 8 lines come first).
void expect_refused(const std::string& objects, int line, const std::string& words) {
    test::expect_scene_error(std::string(kStage) + objects, line + 8, -1, words);
}

TEST(Csg, WhatCannotBeASolidIsRefusedWithWhy) {
    const std::string sphere = R"({ type = "sphere", center = [0, 0, 0], radius = 1 })";
    expect_refused("[[object]]\ntype = \"difference\"\nobjects = [" + sphere +
                       ", { type = \"disc\", center = [0, 0, 0], normal = [0, 1, 0], radius = 1 }]\n",
                   3, "a disc has no inside");
    expect_refused("[[object]]\ntype = \"intersection\"\nobjects = [" + sphere +
                       ", { type = \"cylinder\", base_point = [0, 0, 0], cap_point = [0, 1, 0], radius = 1, open = true }]\n",
                   3, "an open cylinder has no inside");
    expect_refused("[[object]]\ntype = \"merge\"\nobjects = [" + sphere + ", { type = \"plane\", normal = [0, 1, 0] }]\n",
                   2, "unbounded");
    expect_refused("[[object]]\ntype = \"intersection\"\ninverse = true\nobjects = [" + sphere + "]\n", 2, "unbounded");
    expect_refused("[[object]]\ntype = \"intersection\"\nobjects = [" + sphere +
                       R"(, { type = "sphere", center = [5, 0, 0], radius = 1 }])" + "\n",
                   2, "empty");
    expect_refused("[[object]]\ntype = \"difference\"\nobjects = []\n", 3, "needs `objects`");
    expect_refused("[[object]]\ntype = \"difference\"\nobjects = [" + sphere.substr(0, sphere.size() - 2) + ", name = \"x\" }]\n",
                   3, "cannot have its own name");
    // f < 0 reaches the box's faces: the box would be part of the solid's boundary.
    expect_refused("[[object]]\ntype = \"intersection\"\nobjects = [" + sphere +
                       R"(, { type = "implicit", function = "x^2 + y^2 + z^2 - 1.44", box = { min = [-1, -1, -1], max = [1, 1, 1] } }])" + "\n",
                   3, "is not proved closed in its box");
    expect_refused("[[object]]\ntype = \"merge\"\nobjects = [" + sphere +
                       R"(, { type = "parametric", x = "u", y = "v", z = "0", u = [0, 1], v = [0, 1] }])" + "\n",
                   3, "is not declared closed");
    std::string many = "[[object]]\ntype = \"merge\"\nobjects = [";
    for (int i = 0; i < 33; ++i) many += (i ? ", " : "") + sphere;
    expect_refused(many + "]\n", 3, "at most 32 solids");
}

const char* const kParametricSphere =
    R"toml({ type = "parametric", closed = true, x = "0.3 + 0.8*cos(v)*cos(u)", y = "0.2 + 0.8*sin(v)", z = "-0.4 + 0.8*cos(v)*sin(u)", u = [0, "2*pi"], v = ["-pi/2", "pi/2"] })toml";
// The same sphere with u and v swapped: its normals point in.
const char* const kParametricSphereInward =
    R"toml({ type = "parametric", closed = true, x = "0.3 + 0.8*cos(u)*cos(v)", y = "0.2 + 0.8*sin(u)", z = "-0.4 + 0.8*cos(u)*sin(v)", v = [0, "2*pi"], u = ["-pi/2", "pi/2"] })toml";
const char* const kSphere = R"toml({ type = "sphere", center = [0.3, 0.2, -0.4], radius = 0.8 })toml";
const char* const kParametricTorus =
    R"toml({ type = "parametric", closed = true, x = "(1 + 0.35*cos(v))*cos(u)", y = "0.35*sin(v)", z = "(1 + 0.35*cos(v))*sin(u)", u = [0, "2*pi"], v = [0, "2*pi"] })toml";
const char* const kTorus = R"toml({ type = "torus", major_radius = 1, minor_radius = 0.35 })toml";

// The combination `op` of `first` and `second` hits every ray where the same combination with
// `twin` for `second` does (a solid whose inside the membership test above checks): the same t,
// from the same leaf, for 300 random rays, half of them from points inside its box.
void expect_same_as_twin(const std::string& op, const std::string& first, const std::string& second, const std::string& twin) {
    auto csg = [&](const std::string& leaf) {
        return test::scene_from_text(std::string(kStage) + "[[object]]\ntype = \"" + op +
                                     "\"\ntransform = { rotate = [20, 30, 0], translate = [0.1, 0, 0] }\nobjects = [" + first +
                                     ", " + leaf + "]\n");
    };
    const Scene surface = csg(second), solid = csg(twin);
    const Csg& a = std::get<Csg>(surface.objects.at(0).shape);
    const Csg& b = std::get<Csg>(solid.objects.at(0).shape);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const dvec3 target(0.9 * unit(rng), 0.9 * unit(rng), 0.9 * unit(rng));
        const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)));
        const cpu::Ray ray{i % 2 ? target : target - 3.0 * dir, dir};  // every other one from within
        const auto hit = cpu::intersect(a, ray, 0.01, 10.0), expected = cpu::intersect(b, ray, 0.01, 10.0);
        ASSERT_EQ(bool(hit), bool(expected)) << "ray " << i;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(hit->t, expected->t, 1e-8) << "ray " << i;
        EXPECT_EQ(hit->part, expected->part) << "ray " << i;
        EXPECT_NEAR(std::abs(glm::dot(hit->normal, expected->normal)), 1.0, 1e-6) << "ray " << i;  // a surface's own side
    }
    EXPECT_GT(hits, 100);
}

TEST(Csg, AParametricSurfaceDeclaredClosedIsTheSolidItEncloses) {
    const std::string box = R"({ type = "box", min = [-0.7, -0.7, -0.7], max = [0.7, 0.7, 0.7] })";
    expect_same_as_twin("difference", box, kParametricSphere, kSphere);
    expect_same_as_twin("intersection", box, kParametricSphereInward, kSphere);
    expect_same_as_twin("merge", R"({ type = "sphere", center = [1, 0, 0], radius = 0.5 })", kParametricTorus, kTorus);
}

TEST(Csg, ABezierSurfaceDeclaredClosedIsTheSolidItEncloses) {
    const std::string box = R"({ type = "box", min = [-0.1, -0.2, -0.9], max = [0.9, 0.8, 0.1] })";
    expect_same_as_twin("difference", kSphere, test::bezier_cube(dvec3(0.4, 0.3, -0.4), 0.5), box);
    expect_same_as_twin("intersection", kSphere, test::bezier_cube(dvec3(0.4, 0.3, -0.4), 0.5, true), box);
}

// A mesh operand's triangles, their fronts out or in, as the box they close.
TEST(Csg, AClosedMeshIsTheSolidItEncloses) {
    const std::string dir = test::fresh_dir("csg-mesh");
    test::write_file(dir + "/out.obj", test::cube_obj(dvec3(0.4, 0.3, -0.4), 0.5));
    test::write_file(dir + "/in.obj", test::cube_obj(dvec3(0.4, 0.3, -0.4), 0.5, true));
    const std::string box = R"toml({ type = "box", min = [-0.1, -0.2, -0.9], max = [0.9, 0.8, 0.1] })toml";
    expect_same_as_twin("difference", kSphere, "{ type = \"mesh\", file = \"" + dir + "/out.obj\" }", box);
    expect_same_as_twin("intersection", kSphere, "{ type = \"mesh\", file = \"" + dir + "/in.obj\" }", box);
}

TEST(Csg, ASurfaceThatEnclosesNoSolidIsRefusedWithWhy) {
    const std::string sphere = R"({ type = "sphere", center = [0, 0, 0], radius = 1 })";
    auto difference = [&](const std::string& leaf) { return "[[object]]\ntype = \"difference\"\nobjects = [" + sphere + ",\n" + leaf + "]\n"; };
    // A sphere's cap cut off at 60 degrees: its rim meets nothing.
    expect_refused(difference(R"toml({ type = "parametric", closed = true, x = "cos(v)*cos(u)", y = "sin(v)", z = "cos(v)*sin(u)", u = [0, "2*pi"], v = ["-pi/2", "pi/3"] })toml"),
                   4, "is not closed: the edge of its samples");
    expect_refused(difference(test::bezier_cube(dvec3(0.0), 0.5, false, 2)), 4, "with opposite orientations");
    // Two sides of one square: closed, and no volume.
    std::string square, back;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            square += fmt::format("{}[{}, {}, 0]", i + j ? ", " : "[", i, j);
            back += fmt::format("{}[{}, {}, 0]", i + j ? ", " : "[", j, i);
        }
    square += "]", back += "]";
    expect_refused(difference("{ type = \"bezier\", closed = true, patches = [" + square + ", " + back + "] }"), 4,
                   "encloses no volume");
    const std::string dir = test::fresh_dir("csg-open-mesh");
    test::write_file(dir + "/open.obj", test::cube_obj(dvec3(0.0), 0.5, false, -1, 2));
    test::write_file(dir + "/turned.obj", test::cube_obj(dvec3(0.0), 0.5, false, 4));
    expect_refused(difference("{ type = \"mesh\", file = \"" + dir + "/open.obj\" }"), 4, "belongs to one triangle only");
    expect_refused(difference("{ type = \"mesh\", file = \"" + dir + "/turned.obj\" }"), 4, "run it the same way");
}

}  // namespace
}  // namespace lancer
