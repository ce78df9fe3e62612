// The reference's prism (host/cpu/shapes/prism.cpp) and its builder and reader (scene/prism.hpp,
// scene/parse_prism.cpp): a square prism against the box (aimed random rays, from outside and
// inside), a ring of many small squares against their boxes (the tree's walk), a square with a
// square hole (the even-odd rule), a curved outline against a march of a polygon's crossing-number
// test, rays through vertices and along walls, rays along y onto the caps, open against closed,
// roots_on_line and inside against each other and a march, POV-Ray's splines against POV-Ray's
// own power forms, and make_prism's refusals.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "scene/load_scene.hpp"
#include "scene/prism.hpp"

namespace lancer::cpu {
namespace prism_test {  // its own names in the unity build
namespace {

using glm::dvec2;

PrismSegment prism_test_line(dvec2 a, dvec2 b) {
    PrismSegment s;
    s.degree = 1;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

// A closed polygon's segments (the corners in order; the last joins the first).
void prism_test_polygon(std::vector<PrismSegment>& out, const std::vector<dvec2>& corners) {
    for (std::size_t i = 0; i < corners.size(); ++i) out.push_back(prism_test_line(corners[i], corners[(i + 1) % corners.size()]));
}

Prism prism_test_box_prism(dvec2 lo, dvec2 hi, double y0, double y1, bool open = false) {
    std::vector<PrismSegment> s;
    prism_test_polygon(s, {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}});
    return make_prism(std::move(s), y0, y1, open);
}

// The classic crossing-number test of a point against closed polygons (even-odd), apart from the
// reference's: a half-line along +x, an edge counted where its ends straddle the point's z
// (one end at or above, the other below).
bool prism_test_polygon_holds(const std::vector<std::vector<dvec2>>& polygons, dvec2 p) {
    bool in = false;
    for (const auto& poly : polygons)
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
            const dvec2 a = poly[i], b = poly[j];
            if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
        }
    return in;
}

dvec3 prism_test_random_point(std::mt19937& rng, dvec3 lo, dvec3 hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y), lo.z + u(rng) * (hi.z - lo.z)};
}

dvec3 prism_test_random_direction(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return glm::normalize(dvec3(g(rng), g(rng), g(rng)));
}

// How near p is to the box's edges (the least of its second- and third-nearest face distances):
// a ray through an edge may be called a hit or a miss, and its normal either face's.
double prism_test_edge_distance(const Box& b, const dvec3& p) {
    double d[3];
    for (int k = 0; k < 3; ++k) d[k] = std::min(std::abs(p[k] - b.min[k]), std::abs(p[k] - b.max[k]));
    std::sort(d, d + 3);
    return d[1];
}

TEST(Prism, SquareIsTheBoxForAimedRandomRays) {
    const Box box{{-1.0, -0.5, -0.8}, {1.2, 0.7, 1.0}};
    const Prism prism = prism_test_box_prism({box.min.x, box.min.z}, {box.max.x, box.max.z}, box.min.y, box.max.y);
    std::mt19937 rng(46);
    int hits = 0, compared = 0;
    for (int i = 0; i < 6000; ++i) {
        Ray ray;
        if (i % 3 == 2) {  // from inside
            ray.origin = prism_test_random_point(rng, box.min + 0.01, box.max - 0.01);
            ray.dir = prism_test_random_direction(rng);
        } else {  // from outside, aimed at a point of (or near) the box
            ray.origin = 6.0 * prism_test_random_direction(rng);
            ray.dir = glm::normalize(prism_test_random_point(rng, box.min - 0.3, box.max + 0.3) - ray.origin);
        }
        if (i % 7 == 0) ray.dir *= 2.5;  // any direction length: t is the ray's own
        const auto want = intersect(box, ray, 1e-9, 1e30);
        const auto got = intersect(prism, ray, 1e-9, 1e30);
        if (want.has_value() != got.has_value()) {
            const auto& one = want ? *want : *got;
            EXPECT_LT(prism_test_edge_distance(box, ray.origin + one.t * ray.dir), 1e-9) << "ray " << i;
            continue;
        }
        if (!want) continue;
        ++hits;
        EXPECT_NEAR(got->t, want->t, 1e-11 * (1.0 + want->t)) << "ray " << i;
        if (prism_test_edge_distance(box, ray.origin + want->t * ray.dir) < 1e-7) continue;
        ++compared;
        EXPECT_NEAR(glm::distance(got->normal, want->normal), 0.0, 1e-12) << "ray " << i;
    }
    EXPECT_GT(hits, 3000);
    EXPECT_GT(compared, 3000);
}

TEST(Prism, ManySmallSquaresAreTheirBoxes) {
    // 30 x 25 small squares, 3,000 segments: the tree's walk must find the nearest and count all.
    std::vector<PrismSegment> segments;
    std::vector<Box> boxes;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 25; ++j) {
            const dvec2 lo(-3.0 + 0.2 * i, -2.5 + 0.2 * j), hi = lo + dvec2(0.12, 0.09);
            prism_test_polygon(segments, {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}});
            boxes.push_back(Box{{lo.x, -0.1, lo.y}, {hi.x, 0.25, hi.y}});
        }
    ASSERT_EQ(segments.size(), 3000u);
    const Prism prism = make_prism(std::move(segments), 0.25, -0.1);
    std::mt19937 rng(7);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Ray ray{5.0 * prism_test_random_direction(rng), {}};
        ray.dir = glm::normalize(prism_test_random_point(rng, {-3.1, -0.2, -2.6}, {3.1, 0.3, 2.6}) - ray.origin);
        std::optional<SurfaceHit> want;
        const Box* which = nullptr;
        for (const Box& b : boxes)
            if (auto h = intersect(b, ray, 1e-9, want ? want->t : 1e30)) {
                want = h;
                which = &b;
            }
        const auto got = intersect(prism, ray, 1e-9, 1e30);
        if (want.has_value() != got.has_value()) {
            EXPECT_LT(prism_test_edge_distance(*which, ray.origin + want->t * ray.dir), 1e-9) << "ray " << i;
            continue;
        }
        if (!want) continue;
        ++hits;
        EXPECT_NEAR(got->t, want->t, 1e-10) << "ray " << i;
        if (prism_test_edge_distance(*which, ray.origin + want->t * ray.dir) > 1e-7) {
            EXPECT_NEAR(glm::distance(got->normal, want->normal), 0.0, 1e-12) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 500);
}

// A square of side 2 with a square hole of side 1: the even-odd rule.
Prism prism_test_holed(bool reversed_hole) {
    std::vector<PrismSegment> s;
    prism_test_polygon(s, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
    if (reversed_hole)
        prism_test_polygon(s, {{-0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}});
    else
        prism_test_polygon(s, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    return make_prism(std::move(s), 0.0, 1.0);
}

TEST(Prism, AHoleIsOutsideByTheEvenOddRule) {
    for (bool reversed : {false, true}) {
        const Prism o = prism_test_holed(reversed);
        EXPECT_TRUE(inside(o, {0.75, 0.5, 0.0}));
        EXPECT_FALSE(inside(o, {0.0, 0.5, 0.0}));  // the hole
        EXPECT_FALSE(inside(o, {0.25, 0.5, 0.1}));
        EXPECT_FALSE(inside(o, {1.5, 0.5, 0.0}));
        EXPECT_FALSE(inside(o, {0.75, 1.5, 0.0}));  // above
        // Down the hole: nothing; down the rim: the top cap.
        EXPECT_FALSE(intersect(o, {{0.1, 3.0, 0.2}, {0, -1, 0}}, 0.0, 1e30));
        const auto cap = intersect(o, {{0.7, 3.0, 0.2}, {0, -1, 0}}, 0.0, 1e30);
        ASSERT_TRUE(cap);
        EXPECT_DOUBLE_EQ(cap->t, 2.0);
        EXPECT_EQ(cap->normal, dvec3(0, 1, 0));
        // Across the middle: in, out into the hole (its wall facing the hole), in, out.
        const Ray across{{-3.0, 0.5, 0.1}, {1, 0, 0}};
        const std::vector<double> roots = roots_on_line(o, across);
        ASSERT_EQ(roots.size(), 4u);
        const double want[4] = {2.0, 2.5, 3.5, 4.0};
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(roots[k], want[k], 1e-12);
        const auto hole_wall = intersect(o, across, 2.1, 1e30);
        ASSERT_TRUE(hole_wall);
        EXPECT_NEAR(hole_wall->t, 2.5, 1e-12);
        EXPECT_NEAR(glm::distance(hole_wall->normal, dvec3(1, 0, 0)), 0.0, 1e-12);  // out of the solid, into the hole
        const auto far_wall = intersect(o, across, 2.6, 1e30);
        ASSERT_TRUE(far_wall);
        EXPECT_NEAR(far_wall->t, 3.5, 1e-12);
        EXPECT_NEAR(glm::distance(far_wall->normal, dvec3(-1, 0, 0)), 0.0, 1e-12);
        // A slanted ray from above into the hole's wall: through the cap? No: into the hole.
        const auto slant = intersect(o, {{0.0, 2.0, 0.0}, glm::normalize(dvec3(0.4, -1.0, 0.0))}, 0.0, 1e30);
        ASSERT_TRUE(slant);
        EXPECT_NEAR(glm::distance(slant->normal, dvec3(-1, 0, 0)), 0.0, 1e-12);  // the hole's wall, seen from the hole
    }
}

// A closed curve: four quadratic arcs near a circle of radius 1 (each through two of the points
// (±1, 0), (0, ±1), with its control point at the corner's (±1, ±1) scaled by w), and a hole of
// four cubic arcs (radius 0.4, the usual 0.5523 handles). Sampled into polygons for the
// crossing-number test.
struct PrismTestCurves {
    Prism prism;
    std::vector<std::vector<dvec2>> polygons;
};

PrismTestCurves prism_test_curves() {
    PrismTestCurves c;
    std::vector<PrismSegment> s;
    const dvec2 ends[5] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}};
    std::vector<dvec2> outer;
    for (int k = 0; k < 4; ++k) {
        PrismSegment q;
        q.degree = 2;
        q.p[0] = ends[k];
        q.p[2] = ends[k + 1];
        q.p[1] = 0.9 * (ends[k] + ends[k + 1]);
        s.push_back(q);
        for (int i = 0; i < 1000; ++i) {
            const double u = i / 1000.0, v = 1.0 - u;
            outer.push_back(v * v * q.p[0] + 2.0 * u * v * q.p[1] + u * u * q.p[2]);
        }
    }
    std::vector<dvec2> inner;
    const double r = 0.4, h = 0.5523 * r;
    const dvec2 c0(0.1, -0.05);
    const dvec2 pts[5] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}, {r, 0}};
    const dvec2 tangents[5] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}, {0, 1}};
    for (int k = 0; k < 4; ++k) {
        PrismSegment b;
        b.degree = 3;
        b.p = {c0 + pts[k], c0 + pts[k] + h * tangents[k], c0 + pts[k + 1] - h * tangents[k + 1], c0 + pts[k + 1]};
        s.push_back(b);
        for (int i = 0; i < 1000; ++i) {
            const double u = i / 1000.0, v = 1.0 - u;
            inner.push_back(v * v * v * b.p[0] + 3.0 * u * v * v * b.p[1] + 3.0 * u * u * v * b.p[2] + u * u * u * b.p[3]);
        }
    }
    c.polygons = {outer, inner};
    c.prism = make_prism(std::move(s), -0.3, 0.6);
    return c;
}

bool prism_test_march_inside(const PrismTestCurves& c, const dvec3& p) {
    return p.y > c.prism.y0 && p.y < c.prism.y1 && prism_test_polygon_holds(c.polygons, {p.x, p.z});
}

TEST(Prism, CurvedOutlineAgreesWithAMarchOfItsInside) {
    const PrismTestCurves c = prism_test_curves();
    std::mt19937 rng(3);
    constexpr int kSteps = 2000;
    int hits = 0, told_apart = 0;
    for (int i = 0; i < 400; ++i) {
        const Ray ray{4.0 * prism_test_random_direction(rng), {}};
        const dvec3 aim = prism_test_random_point(rng, {-1.1, -0.4, -1.1}, {1.1, 0.7, 1.1});
        const Ray r{ray.origin, glm::normalize(aim - ray.origin)};
        const auto got = intersect(c.prism, r, 0.0, 1e30);
        // The march: the first step whose point is inside.
        const double step = 8.0 / kSteps;
        std::optional<double> first;
        for (int k = 1; k <= kSteps && !first; ++k)
            if (prism_test_march_inside(c, r.origin + (k * step) * r.dir)) first = k * step;
        if (first.has_value() != got.has_value()) {
            ++told_apart;  // only a ray that grazes the surface within a step may be
            continue;
        }
        if (!got) continue;
        ++hits;
        EXPECT_LE(got->t, *first + 1e-9) << "ray " << i;
        EXPECT_GE(got->t, *first - step - 1e-5) << "ray " << i;  // the polygon is within 1e-6 of the curves
        EXPECT_LT(glm::dot(got->normal, r.dir), 0.0) << "ray " << i;  // it enters, facing the ray
    }
    EXPECT_GT(hits, 150);
    EXPECT_LE(told_apart, 2);
}

TEST(Prism, RootsOnLineAlternateAndAgreeWithInsideAndAMarch) {
    const PrismTestCurves c = prism_test_curves();
    std::mt19937 rng(11);
    for (int i = 0; i < 300; ++i) {
        const dvec3 a = prism_test_random_point(rng, {-1.3, -0.6, -1.3}, {1.3, 0.9, 1.3});
        const dvec3 b = prism_test_random_point(rng, {-1.3, -0.6, -1.3}, {1.3, 0.9, 1.3});
        const Ray ray{a, b - a};
        const std::vector<double> roots = roots_on_line(c.prism, ray);
        ASSERT_TRUE(std::is_sorted(roots.begin(), roots.end()));
        EXPECT_EQ(roots.size() % 2, 0u) << "ray " << i;
        // Between consecutive roots, inside alternates (outside before the first).
        std::vector<double> ts{-1e3};
        ts.insert(ts.end(), roots.begin(), roots.end());
        ts.push_back(1e3);
        for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
            const double lo = std::max(ts[k], -5.0), hi = std::min(ts[k + 1], 5.0);
            if (!(hi - lo > 1e-6)) continue;
            const dvec3 mid = ray.origin + (0.5 * (lo + hi)) * ray.dir;
            EXPECT_EQ(inside(c.prism, mid), k % 2 == 1) << "ray " << i << " stretch " << k;
            EXPECT_EQ(prism_test_march_inside(c, mid), k % 2 == 1) << "ray " << i << " stretch " << k;
        }
    }
}

TEST(Prism, RaysThroughVerticesAndAlongWalls) {
    const Prism o = prism_test_box_prism({-1, -1}, {1, 1}, 0.0, 1.0);
    // Through two corners, along the diagonal: in at (-1, -1), out at (1, 1).
    const double root2 = std::sqrt(2.0);
    const Ray diagonal{{-3.0, 0.5, -3.0}, glm::normalize(dvec3(1, 0, 1))};
    const auto in = intersect(o, diagonal, 0.0, 1e30);
    ASSERT_TRUE(in);
    EXPECT_NEAR(in->t, 2.0 * root2, 1e-12);
    EXPECT_LT(glm::dot(in->normal, diagonal.dir), 0.0);
    EXPECT_EQ(roots_on_line(o, diagonal).size(), 2u);
    // Touching a corner from outside (the line through (2, 0) and (1, 1)): not a crossing; a hit,
    // if any, is the corner itself.
    const Ray touch{{2.0, 0.5, 0.0}, glm::normalize(dvec3(-1, 0, 1))};
    EXPECT_EQ(roots_on_line(o, touch).size() % 2, 0u);
    if (const auto h = intersect(o, touch, 0.0, 1e30)) {
        EXPECT_NEAR(h->t, root2, 1e-12);
    }
    EXPECT_FALSE(intersect(o, touch, root2 + 1e-9, 1e30));
    // From a cap point, the half-line through a vertex: the top cap from above, tilted so that the
    // outline's line from its point passes through the corner (1, 1).
    const Ray onto{{0.0, 2.0, 0.0}, dvec3(0.5, -1.0, 0.5)};
    const auto cap = intersect(o, onto, 0.0, 1e30);
    ASSERT_TRUE(cap);
    EXPECT_DOUBLE_EQ(cap->t, 1.0);
    EXPECT_EQ(cap->normal, dvec3(0, 1, 0));
    // The same through the corner (1, -1) and (-1, 1), every way round.
    for (dvec2 corner : {dvec2(1, -1), dvec2(-1, 1), dvec2(-1, -1)}) {
        const auto h = intersect(o, {{0.0, 2.0, 0.0}, dvec3(0.5 * corner.x, -1.0, 0.5 * corner.y)}, 0.0, 1e30);
        ASSERT_TRUE(h);
        EXPECT_DOUBLE_EQ(h->t, 1.0);
    }
    // A star's points: vertical rays over a grid that holds every corner's x and z exactly
    // (half-lines through vertices, turning back or passing through), against the polygon test.
    std::vector<dvec2> star;
    for (int k = 0; k < 10; ++k) {
        const double a = k * M_PI / 5.0, r = k % 2 ? 0.4 : 1.0;
        star.push_back({std::round(r * std::cos(a) * 64.0) / 64.0, std::round(r * std::sin(a) * 64.0) / 64.0});
    }
    std::vector<PrismSegment> s;
    prism_test_polygon(s, star);
    const Prism st = make_prism(std::move(s), 0.0, 0.5);
    int checked = 0;
    for (int i = -70; i <= 70; ++i)
        for (int j = -70; j <= 70; ++j) {
            const dvec2 q(i / 64.0, j / 64.0);
            bool on_edge = false;  // a point on the outline may go either way
            for (std::size_t k = 0; k < star.size(); ++k) {
                const dvec2 a = star[k], b = star[(k + 1) % star.size()];
                const double cross = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
                const double along = glm::dot(q - a, b - a);
                on_edge = on_edge || (std::abs(cross) < 1e-12 && along >= 0.0 && along <= glm::dot(b - a, b - a));
            }
            if (on_edge) continue;
            const bool want = prism_test_polygon_holds({star}, q);
            EXPECT_EQ(inside(st, {q.x, 0.25, q.y}), want) << q.x << ", " << q.y;
            const auto down = intersect(st, {{q.x, 2.0, q.y}, {0, -1, 0}}, 0.0, 1e30);
            EXPECT_EQ(down.has_value(), want) << q.x << ", " << q.y;
            if (down) {
                EXPECT_DOUBLE_EQ(down->t, 1.5);
            }
            const auto up = intersect(st, {{q.x, 0.25, q.y}, {0, 1, 0}}, 0.0, 1e30);  // from inside: the top cap
            EXPECT_EQ(up.has_value(), want) << q.x << ", " << q.y;
            ++checked;
        }
    EXPECT_GT(checked, 15000);
    // Along a wall, in its plane: either the wall's run (one entry and one exit, at its corners)
    // or nothing, never an odd count.
    for (double dir : {1.0, -1.0}) {
        const Ray along{{1.0, 0.5, -3.0 * dir}, {0, 0, dir}};
        EXPECT_EQ(roots_on_line(o, along).size() % 2, 0u);
        if (const auto h = intersect(o, along, 0.0, 1e30)) {
            EXPECT_NEAR(h->t, 2.0, 1e-12);
        }
    }
}

TEST(Prism, OpenHasNoCapsAndShowsItsInside) {
    const Prism closed = prism_test_box_prism({-1, -1}, {1, 1}, 0.0, 1.0);
    const Prism open = prism_test_box_prism({-1, -1}, {1, 1}, 0.0, 1.0, true);
    const Ray down{{0.2, 3.0, 0.1}, {0, -1, 0}};
    ASSERT_TRUE(intersect(closed, down, 0.0, 1e30));
    EXPECT_FALSE(intersect(open, down, 0.0, 1e30));
    // Slanted into the open top: the far wall, from inside.
    const Ray slant{{0.0, 2.0, 0.0}, glm::normalize(dvec3(1.0, -1.5, 0.0))};
    const auto closed_hit = intersect(closed, slant, 0.0, 1e30);
    const auto open_hit = intersect(open, slant, 0.0, 1e30);
    ASSERT_TRUE(closed_hit && open_hit);
    EXPECT_EQ(closed_hit->normal, dvec3(0, 1, 0));
    EXPECT_NEAR(open_hit->t, std::sqrt(1.0 + 2.25), 1e-12);  // x = 1 at y = 0.5
    EXPECT_NEAR(glm::distance(open_hit->normal, dvec3(1, 0, 0)), 0.0, 1e-12);
    // Open: the walls only, on its line.
    EXPECT_EQ(roots_on_line(open, {{0.2, -3.0, 0.1}, {0, 1, 0}}).size(), 0u);
    EXPECT_EQ(roots_on_line(closed, {{0.2, -3.0, 0.1}, {0, 1, 0}}).size(), 2u);
    EXPECT_EQ(roots_on_line(open, {{-3.0, 0.5, 0.1}, {1, 0, 0}}).size(), 2u);
}

TEST(Prism, FarFromTheOriginAndFarAwayItKeepsItsPrecision) {
    const Prism o = prism_test_box_prism({1e4 - 1.0, -1.0}, {1e4 + 1.0, 1.0}, 0.0, 1.0);
    const auto h = intersect(o, {{1e4 - 1e5, 0.5, 0.3}, {1, 0, 0}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1e5 - 1.0, 1e-9 * 1e5);
    EXPECT_EQ(h->normal, dvec3(-1, 0, 0));
}

// A convex polyhedron as half-spaces n . p <= c: the ray's first entry (or exit, from inside) by
// clipping (Cyrus-Beck), with the plane's outward normal.
struct PrismTestPlane {
    dvec3 n;
    double c;
};

std::optional<SurfaceHit> prism_test_clip(const std::vector<PrismTestPlane>& planes, const Ray& ray, double t_min) {
    double enter = -1e300, leave = 1e300;
    dvec3 enter_n(0.0), leave_n(0.0);
    for (const PrismTestPlane& h : planes) {
        const double dn = glm::dot(h.n, ray.dir), dist = h.c - glm::dot(h.n, ray.origin);
        if (dn == 0.0) {
            if (dist < 0.0) return std::nullopt;
            continue;
        }
        const double t = dist / dn;
        if (dn < 0.0 && t > enter) {
            enter = t;
            enter_n = glm::normalize(h.n);
        }
        if (dn > 0.0 && t < leave) {
            leave = t;
            leave_n = glm::normalize(h.n);
        }
    }
    if (!(enter < leave)) return std::nullopt;
    if (enter > t_min) return SurfaceHit{enter, enter_n};
    if (leave > t_min) return SurfaceHit{leave, leave_n};
    return std::nullopt;
}

// How near p is to two of the planes (an edge, where either answer goes).
double prism_test_plane_edge_distance(const std::vector<PrismTestPlane>& planes, const dvec3& p) {
    std::vector<double> d;
    for (const PrismTestPlane& h : planes) d.push_back(std::abs(glm::dot(h.n, p) - h.c) / glm::length(h.n));
    std::sort(d.begin(), d.end());
    return d[1];
}

TEST(Prism, ConicSweepOfASquareIsThePyramid) {
    for (double y0 : {0.5, 0.0}) {  // a frustum, and the pyramid to its apex
        const double y1 = 1.5;
        std::vector<PrismSegment> s;
        prism_test_polygon(s, {{-1, -0.8}, {1.2, -0.8}, {1.2, 1}, {-1, 1}});
        const Prism o = make_prism(std::move(s), y1, y0, false, true);
        // x <= 1.2 y, -x <= y, z <= y, -z <= 0.8 y, y0 <= y <= y1.
        const std::vector<PrismTestPlane> planes = {{{1, -1.2, 0}, 0}, {{-1, -1, 0}, 0}, {{0, -1, 1}, 0}, {{0, -0.8, -1}, 0},
                                                    {{0, 1, 0}, y1}, {{0, -1, 0}, -y0}};
        std::mt19937 rng(17);
        int hits = 0, compared = 0;
        for (int i = 0; i < 6000; ++i) {
            Ray ray;
            if (i % 3 == 2) {  // from inside
                const double y = y0 + 0.05 + 0.9 * (y1 - y0 - 0.05) * std::uniform_real_distribution<double>(0, 1)(rng);
                ray.origin = prism_test_random_point(rng, {-0.9 * y, y, -0.7 * y}, {1.1 * y, y, 0.9 * y});
                ray.dir = prism_test_random_direction(rng);
            } else {
                ray.origin = 6.0 * prism_test_random_direction(rng);
                ray.dir = glm::normalize(prism_test_random_point(rng, {-2, -0.2, -1.6}, {2, 1.8, 1.8}) - ray.origin);
            }
            const auto want = prism_test_clip(planes, ray, 1e-9);
            const auto got = intersect(o, ray, 1e-9, 1e30);
            if (want.has_value() != got.has_value()) {
                const auto& one = want ? *want : *got;
                const dvec3 at = ray.origin + one.t * ray.dir;
                // An edge, or (the pyramid) the apex's sliver, 1e-7 of its height.
                EXPECT_TRUE(prism_test_plane_edge_distance(planes, at) < 1e-9 || (y0 == 0.0 && at.y < 2e-7)) << "ray " << i << " y0 " << y0;
                continue;
            }
            if (!want) continue;
            ++hits;
            EXPECT_NEAR(got->t, want->t, 1e-10 * (1.0 + want->t)) << "ray " << i << " y0 " << y0;
            if (prism_test_plane_edge_distance(planes, ray.origin + want->t * ray.dir) < 1e-7) continue;
            ++compared;
            EXPECT_NEAR(glm::distance(got->normal, want->normal), 0.0, 1e-10) << "ray " << i << " y0 " << y0;
            // Inside agrees just past the hit.
            EXPECT_EQ(inside(o, ray.origin + (got->t + 1e-6) * ray.dir), glm::dot(want->normal, ray.dir) < 0.0) << "ray " << i;
        }
        EXPECT_GT(hits, 2500);
        EXPECT_GT(compared, 2500);
    }
}

TEST(Prism, ConicSweepBelowTheApexIsTheMirroredPyramid) {
    // Heights below 0: the outline scaled by a negative y, turned half round.
    std::vector<PrismSegment> s;
    prism_test_polygon(s, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const Prism o = make_prism(std::move(s), -2.0, -1.0, false, true);
    EXPECT_TRUE(inside(o, {-0.5, -1.5, -0.5}));   // (x / y, z / y) = (1/3, 1/3)
    EXPECT_FALSE(inside(o, {0.5, -1.5, 0.5}));
    const auto h = intersect(o, {{-0.5, 5.0, -0.5}, {0, -1, 0}}, 0.0, 1e30);  // down onto the top cap at y = -1? (x/y = 0.5: inside)
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 6.0);
    EXPECT_EQ(h->normal, dvec3(0, 1, 0));
    EXPECT_THROW(make_prism({prism_test_line({0, 0}, {1, 0}), prism_test_line({1, 0}, {0, 1}), prism_test_line({0, 1}, {0, 0})}, -1.0, 1.0,
                            false, true),
                 std::invalid_argument);
}

TEST(Prism, TextureIsPlanarXZ) {
    const Prism o = prism_test_box_prism({-1, -1}, {1, 1}, 0.0, 1.0);
    EXPECT_EQ(texture_uv(o, {0.25, 0.5, -0.75}), dvec2(0.25, -0.75));
}

TEST(Prism, MakePrismRefusesOpenContoursBadDegreesAndFlatHeights) {
    std::vector<PrismSegment> open;
    open.push_back(prism_test_line({0, 0}, {1, 0}));
    open.push_back(prism_test_line({1, 0}, {1, 1}));
    EXPECT_THROW(make_prism(open, 0.0, 1.0), std::invalid_argument);
    open.push_back(prism_test_line({1, 1}, {0, 0}));
    EXPECT_NO_THROW(make_prism(open, 0.0, 1.0));
    EXPECT_THROW(make_prism(open, 1.0, 1.0), std::invalid_argument);
    open.push_back(prism_test_line({5, 5}, {6, 5}));  // a second contour that does not close
    EXPECT_EQ(prism_open_contour(open), 3);
    EXPECT_THROW(make_prism(open, 0.0, 1.0), std::invalid_argument);
    std::vector<PrismSegment> bad{prism_test_line({0, 0}, {1, 0})};
    bad[0].degree = 4;
    EXPECT_THROW(make_prism(bad, 0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(make_prism({}, 0.0, 1.0), std::invalid_argument);
}

// POV-Ray's power forms (source/core/shape/prism.cpp's Compute_Prism) of its splines' pieces.
dvec2 prism_test_pov_quadratic(dvec2 p0, dvec2 p1, dvec2 p2, double u) {
    const dvec2 B = 0.5 * p0 - p1 + 0.5 * p2, C = -0.5 * p0 + 0.5 * p2, D = p1;
    return (B * u + C) * u + D;
}
dvec2 prism_test_pov_cubic(dvec2 p0, dvec2 p1, dvec2 p2, dvec2 p3, double u) {
    const dvec2 A = -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3, B = p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3;
    const dvec2 C = -0.5 * p0 + 0.5 * p2, D = p1;
    return ((A * u + B) * u + C) * u + D;
}
dvec2 prism_test_bezier(const PrismSegment& s, double u) {
    dvec2 w[4] = {s.p[0], s.p[1], s.p[2], s.p[3]};
    for (int k = 1; k <= s.degree; ++k)
        for (int i = 0; i + k <= s.degree; ++i) w[i] = (1.0 - u) * w[i] + u * w[i + 1];
    return w[0];
}

const Prism& prism_test_read(const Scene& scene) { return std::get<Prism>(scene.objects.at(0).shape); }

Scene prism_test_scene(const std::string& keys) {
    return parse_scene("[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"prism\"\n" + keys, "prism.toml");
}

TEST(Prism, ReaderTurnsPovRaySplinesIntoTheSameCurves) {
    // Quadratic: two sub-paths (a control point before each).
    const std::vector<dvec2> q = {{0.6, -0.9}, {1, 0}, {0.6, 0.9}, {0, 1}, {-0.6, 0.9}, {-1, 0}, {-0.6, -0.9}, {0, -1}, {0.6, -0.9}, {1, 0},
                                  {0.3, -0.2}, {0.4, 0}, {0.2, 0.2}, {0, 0.1}, {0.4, 0}};
    std::string text = "spline = \"quadratic\"\nheight1 = 1\nheight2 = -0.5\npoints = [";
    for (const dvec2& p : q) text += "[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "], ";
    text += "]\n";
    const Scene qs = prism_test_scene(text);
    const Prism& qp = prism_test_read(qs);
    EXPECT_EQ(qp.y0, -0.5);
    EXPECT_EQ(qp.y1, 1.0);
    ASSERT_EQ(qp.segments.size(), 8u + 3u);
    std::vector<std::array<int, 3>> pieces;
    for (int i = 1; i <= 8; ++i) pieces.push_back({i - 1, i, i + 1});
    for (int i = 11; i <= 13; ++i) pieces.push_back({i - 1, i, i + 1});
    for (std::size_t k = 0; k < pieces.size(); ++k)
        for (double u : {0.0, 0.3, 0.7, 1.0}) {
            const dvec2 want = prism_test_pov_quadratic(q[pieces[k][0]], q[pieces[k][1]], q[pieces[k][2]], u);
            EXPECT_LT(glm::distance(prism_test_bezier(qp.segments[k], u), want), 1e-12) << k << " " << u;
        }
    // Cubic: a control point before and after.
    const std::vector<dvec2> c = {{-0.6, -0.6}, {0, -0.8}, {0.7, -0.5}, {0.6, 0.3}, {0.1, 0.2}, {-0.3, 0.7}, {-0.8, 0.1}, {-0.6, -0.6}, {0, -0.8}, {0.7, -0.5}};
    text = "spline = \"cubic\"\npoints = [";
    for (const dvec2& p : c) text += "[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "], ";
    text += "]\n";
    const Scene cs = prism_test_scene(text);
    const Prism& cp = prism_test_read(cs);
    ASSERT_EQ(cp.segments.size(), 7u);
    for (std::size_t k = 0; k < 7; ++k)
        for (double u : {0.0, 0.3, 0.7, 1.0}) {
            const dvec2 want = prism_test_pov_cubic(c[k], c[k + 1], c[k + 2], c[k + 3], u);
            EXPECT_LT(glm::distance(prism_test_bezier(cp.segments[k], u), want), 1e-12) << k << " " << u;
        }
    // Bezier: the control points as they are; linear: the corners.
    const Scene bs = prism_test_scene("spline = \"bezier\"\npoints = [[0, -1], [1, 0], [1, 1], [0, 0.5], [0, 0.5], [-1, 1], [-1, 0], [0, -1]]\n");
    const Prism& bp = prism_test_read(bs);
    ASSERT_EQ(bp.segments.size(), 2u);
    EXPECT_EQ(bp.segments[1].p[2], dvec2(-1, 0));
    EXPECT_EQ(bp.segments[1].p[3], bp.segments[0].p[0]);
    const Scene ls = prism_test_scene("points = [[0, 0], [1, 0], [1, 1], [0, 0], [2, 2], [3, 2], [3, 3], [2, 2]]\nopen = true\n");
    const Prism& lp = prism_test_read(ls);
    ASSERT_EQ(lp.segments.size(), 6u);
    EXPECT_TRUE(lp.open);
    EXPECT_EQ(lp.segments[5].p[1], dvec2(2, 2));
    // Always placed: traced in its own coordinates.
    EXPECT_TRUE(ls.objects.at(0).placement && ls.objects.at(0).placement->shape_in_object_space);
}

}  // namespace
}  // namespace prism_test
}  // namespace lancer::cpu
