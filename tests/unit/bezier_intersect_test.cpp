// The CPU reference's ray/Bezier-patch intersection (host/cpu/shapes/bezier.cpp) on the teapot:
// the known rays of the design notes, aimed rays, shared edges and corners (no cracks), apexes,
// a flat patch against the rectangle, tangent and degenerate rays.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "unit/bezier_test_support.hpp"

namespace lancer::cpu {
namespace {

using surface::BezierPatch;
using surface::evaluate;
using test::all_hits;
using test::distinct_ts;
using test::teapot;
using test::uniform;

std::set<int> patches_hitting_at(const std::vector<test::SetHit>& hits, double t) {
    std::set<int> out;
    for (const auto& h : hits)
        if (std::abs(h.t - t) <= 1e-9 * t) out.insert(h.patch);
    return out;
}

// Every hit must be a point of its patch on the ray: to 1e-9 (design notes, section 3.2), or
// for tangent rays, where Newton converges slowly, to the intersector's acceptance bound.
void expect_on_ray_and_patch(const std::vector<test::SetHit>& hits, const std::vector<BezierPatch>& set, const Ray& r,
                             double tolerance = 1e-9) {
    for (const auto& h : hits) {
        ASSERT_TRUE(std::isfinite(h.t) && h.u >= 0.0 && h.u <= 1.0 && h.v >= 0.0 && h.v <= 1.0);
        dvec3 s = evaluate(set[h.patch], h.u, h.v);
        EXPECT_LE(glm::length(s - (r.origin + h.t * r.dir)), tolerance * (1.0 + glm::length(s)));
    }
}

TEST(BezierIntersect, RayThroughTheFourPatchCornerHitsAtEightAndTwelve) {
    Ray r{{0, -10, 0.9}, {0, 1, 0}};
    auto hits = all_hits(teapot(), r);
    expect_on_ray_and_patch(hits, teapot(), r);
    auto ts = distinct_ts(hits);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 8.0, 1e-12);
    EXPECT_NEAR(ts[1], 12.0, 1e-12);
    // (0, -2, 0.9) and (0, 2, 0.9) are corners of four body patches each; every one reports it.
    EXPECT_EQ(patches_hitting_at(hits, 8.0), (std::set<int>{4, 5, 8, 9}));
    EXPECT_EQ(patches_hitting_at(hits, 12.0), (std::set<int>{6, 7, 10, 11}));
}

TEST(BezierIntersect, RayDownTheAxisHitsBothApexes) {
    Ray r{{0, 0, 10}, {0, 0, -1}};
    auto hits = all_hits(teapot(), r);
    expect_on_ray_and_patch(hits, teapot(), r);
    auto ts = distinct_ts(hits);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 6.85, 1e-12);  // lid apex, z = 3.15
    EXPECT_NEAR(ts[1], 10.0, 1e-12);  // bottom centre, z = 0
    EXPECT_EQ(patches_hitting_at(hits, 6.85), (std::set<int>{20, 21, 22, 23}));
    EXPECT_EQ(patches_hitting_at(hits, 10.0), (std::set<int>{28, 29, 30, 31}));
    // Each apex patch reports its apex once, though every v on the collapsed edge solves.
    for (int k : {20, 28}) EXPECT_EQ(intersect_all(teapot()[k], r, 0.0, 1e30).size(), 1u) << "patch " << k + 1;
    auto h = intersect(teapot()[20], r, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(std::abs(h->normal.z), 1.0, 1e-12);  // the limit normal at the apex
}

TEST(BezierIntersect, RayBesideTheCornerCrossesTheBody) {
    Ray r{{0.3, -10, 0.9}, {0, 1, 0}};
    auto hits = all_hits(teapot(), r);
    expect_on_ray_and_patch(hits, teapot(), r);
    auto ts = distinct_ts(hits);
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 8.0214787, 1e-7);
    EXPECT_NEAR(ts[1], 11.9785213, 1e-7);
    EXPECT_NEAR(ts[0] + ts[1], 20.0, 1e-12);  // the body is symmetric in y
}

TEST(BezierIntersect, NearestHitCarriesItsNormalAndParameters) {
    Ray r{{0.3, -10, 0.9}, {0, 1, 0}};
    auto h = test::nearest_hit(teapot(), r);
    ASSERT_TRUE(h);
    auto s = intersect(teapot()[h->patch], r, 0.0, 1e30);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->t, h->t);
    EXPECT_EQ(s->uv, glm::dvec2(h->u, h->v));
    EXPECT_LE(glm::length(s->normal - surface::unit_normal(teapot()[h->patch], h->u, h->v)), 0.0);
    EXPECT_NEAR(std::abs(s->normal.y), std::sqrt(1.0 - 0.15 * 0.15), 2e-3);  // x = 0.3 on a circle of radius ~2
}

// 3000 rays aimed at random points S(u0, v0) of random teapot patches (design notes, section 3.1):
// the aimed patch reports t = 1 to 1e-9 and nothing nearer than t = 1 is missed by the set.
TEST(BezierIntersect, AimedRaysHitTheirTargets) {
    std::mt19937 rng(20240601);
    const auto& set = teapot();
    int missed = 0, checked_uv = 0;
    for (int n = 0; n < 3000; ++n) {
        int k = static_cast<int>(rng() % set.size());
        double u0 = uniform(rng), v0 = uniform(rng);
        dvec3 target = evaluate(set[k], u0, v0);
        dvec3 origin = target + uniform(rng, 1.0, 10.0) * test::random_unit(rng);
        Ray r{origin, target - origin};
        bool found = false;
        auto hits = intersect_all(set[k], r, 0.0, 1e30);
        for (std::size_t i = 1; i < hits.size(); ++i)  // distinct points, nearest first
            EXPECT_GT(hits[i].t - hits[i - 1].t, 1e-9 * hits[i].t);
        for (const PatchHit& h : hits) {
            if (std::abs(h.t - 1.0) > 1e-9) continue;
            found = true;
            auto j = surface::evaluate_jet(set[k], u0, v0);
            if (glm::length(glm::cross(j.su, j.sv)) > 1e-2) {  // (u, v) is unique where the patch is regular
                EXPECT_NEAR(h.u, u0, 1e-6);
                EXPECT_NEAR(h.v, v0, 1e-6);
                ++checked_uv;
            }
        }
        if (!found) {
            ++missed;
            ADD_FAILURE() << "patch " << k + 1 << " (u, v) = (" << u0 << ", " << v0 << ") from " << origin.x << ", "
                          << origin.y << ", " << origin.z;
        }
        auto nearest = test::nearest_hit(set, r);
        ASSERT_TRUE(nearest);
        EXPECT_LE(nearest->t, 1.0 + 1e-9);
    }
    EXPECT_EQ(missed, 0);
    EXPECT_GT(checked_uv, 2500);
}

// Rays through points a hair away from the collapsed edges (lid apex, bottom centre), where the
// resultant has a highly multiple root, and exactly through them.
TEST(BezierIntersect, RaysNearTheApexesHitTheirTargets) {
    std::mt19937 rng(77);
    const auto& set = teapot();
    for (int k : {20, 21, 22, 23, 28, 29, 30, 31})
        for (int e = 1; e <= 15; ++e)
            for (int n = 0; n < 25; ++n) {
                double u0 = e == 15 ? 0.0 : std::pow(10.0, -e - uniform(rng));
                double v0 = uniform(rng);
                dvec3 target = evaluate(set[k], u0, v0);
                dvec3 origin = target + uniform(rng, 1.0, 10.0) * test::random_unit(rng);
                Ray r{origin, target - origin};
                bool found = false;
                for (const PatchHit& h : intersect_all(set[k], r, 0.0, 1e30)) found |= std::abs(h.t - 1.0) <= 1e-9;
                EXPECT_TRUE(found) << "patch " << k + 1 << " u0 " << u0 << " v0 " << v0;
            }
}

bool patch_hits_at_one(const BezierPatch& p, const Ray& r) {
    for (const PatchHit& h : intersect_all(p, r, 0.0, 1e30))
        if (std::abs(h.t - 1.0) <= 1e-9) return true;
    return false;
}

// Rays that stress runs (200,000 rays aimed within 1e-14..1 of the teapot's apexes) found
// missed by versions without the Newton seeds beside collapsed edges (the first four) or without
// candidates along a parameter line that lies wholly on the ray (the last two: nearly horizontal
// rays exactly through the lid apex).
TEST(BezierIntersect, RegressionRaysBesideTheApexes) {
    struct Case {
        int patch;  // from 0
        double u0, v0;
        dvec3 origin;
    };
    const Case cases[] = {
        {21,
         3.3090976991603109e-11,
         0.29941124040482919,
         {9.2691204918238963, -1.9964537018416861, 0.6813921482575207}},
        {23,
         3.9265009902418698e-11,
         0.87445616309587204,
         {-3.9734140906306927, 6.2241631732168976, 6.8685334685965884}},
        {28,
         6.1350270438267614e-09,
         0.60362278599165342,
         {0.81169027405233984, -0.93542381135170538, 0.96912097844146794}},
        {30, 1.500927908365533e-11, 0.64229047326572508, {-1.983967252004659, 1.7617029284093522, 0.38076910912929973}},
        {23, 0.0, 0.55110053467519227, {-0.24322532553975101, 1.6428575908848531, 3.1495426921391774}},
        {20, 0.0, 0.69530029746464328, {-0.45219947380949721, -6.6091133964707183, 3.1494409951604476}},
    };
    for (const Case& c : cases) {
        dvec3 target = evaluate(teapot()[c.patch], c.u0, c.v0);
        EXPECT_TRUE(patch_hits_at_one(teapot()[c.patch], {c.origin, target - c.origin})) << "patch " << c.patch + 1;
    }
}

struct Edge {
    int patch;
    int which;  // 0: u = 0, 1: u = 1, 2: v = 0, 3: v = 1
};

std::array<dvec3, 4> edge_points(const BezierPatch& p, int which) {
    std::array<dvec3, 4> e;
    for (int s = 0; s < 4; ++s) {
        int i = which == 0 ? 0 : which == 1 ? 3 : s;
        int j = which == 2 ? 0 : which == 3 ? 3 : s;
        e[s] = surface::control_point(p, i, j);
    }
    return e;
}

glm::dvec2 edge_param(int which, double s) {
    switch (which) {
        case 0:
            return {0.0, s};
        case 1:
            return {1.0, s};
        case 2:
            return {s, 0.0};
        default:
            return {s, 1.0};
    }
}

// No cracks (design notes, section 3.6): a ray aimed at a point of an edge that two patches share
// hits both of them, and a ray aimed at a corner hits every patch that has that corner.
TEST(BezierIntersect, SharedEdgesAndCornersHaveNoCracks) {
    const auto& set = teapot();
    std::mt19937 rng(99);
    int shared = 0, rays = 0;
    for (int a = 0; a < 32; ++a)
        for (int ea = 0; ea < 4; ++ea) {
            auto pa = edge_points(set[a], ea);
            if (pa[0] == pa[1] && pa[1] == pa[2] && pa[2] == pa[3]) continue;  // collapsed: an apex
            for (int b = a + 1; b < 32; ++b)
                for (int eb = 0; eb < 4; ++eb) {
                    auto pb = edge_points(set[b], eb);
                    bool same = pa == pb;
                    bool reversed = pa[0] == pb[3] && pa[1] == pb[2] && pa[2] == pb[1] && pa[3] == pb[0];
                    if (!same && !reversed) continue;
                    ++shared;
                    for (int i = 0; i <= 10; ++i) {
                        glm::dvec2 uv = edge_param(ea, i / 10.0);
                        dvec3 target = evaluate(set[a], uv.x, uv.y);
                        for (int n = 0; n < 3; ++n) {
                            dvec3 origin = target + uniform(rng, 1.0, 8.0) * test::random_unit(rng);
                            Ray r{origin, target - origin};
                            ++rays;
                            EXPECT_TRUE(patch_hits_at_one(set[a], r))
                                << "patch " << a + 1 << " edge " << ea << " s " << i / 10.0;
                            EXPECT_TRUE(patch_hits_at_one(set[b], r))
                                << "patch " << b + 1 << " edge " << eb << " s " << i / 10.0;
                        }
                    }
                }
        }
    EXPECT_GE(shared, 40);  // the body, spout, handle and lid rings are stitched along their seams

    std::map<std::array<double, 3>, std::vector<int>> corners;
    for (int k = 0; k < 32; ++k)
        for (int c : {0, 3, 12, 15}) {
            dvec3 q = set[k].points[c];
            auto& list = corners[{q.x, q.y, q.z}];
            if (list.empty() || list.back() != k) list.push_back(k);
        }
    int multi = 0;
    for (const auto& [key, patches] : corners) {
        if (patches.size() < 2) continue;
        ++multi;
        dvec3 target(key[0], key[1], key[2]);
        for (int n = 0; n < 4; ++n) {
            dvec3 origin = target + uniform(rng, 1.0, 8.0) * test::random_unit(rng);
            Ray r{origin, target - origin};
            for (int k : patches) EXPECT_TRUE(patch_hits_at_one(set[k], r)) << "corner patch " << k + 1;
        }
    }
    EXPECT_GE(multi, 20);
    EXPECT_GT(rays, 1000);
}

// A flat patch with control points on a parallelogram is that parallelogram, with (u, v) its
// parallelogram coordinates: the patch and the rectangle intersectors must agree.
TEST(BezierIntersect, FlatBilinearPatchIsTheRectangle) {
    std::mt19937 rng(5);
    int hits = 0, misses = 0;
    for (int n = 0; n < 600; ++n) {
        dvec3 corner(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
        dvec3 eu(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
        dvec3 ev(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
        dvec3 nrm = glm::cross(eu, ev);
        if (glm::length(nrm) < 0.1) continue;
        BezierPatch p;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) p.points[4 * i + j] = corner + (i / 3.0) * eu + (j / 3.0) * ev;
        double a = uniform(rng, -0.2, 1.2), b = uniform(rng, -0.2, 1.2);
        if (std::min({std::abs(a), std::abs(1 - a), std::abs(b), std::abs(1 - b)}) < 1e-6) continue;
        dvec3 origin(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
        Ray r{origin, glm::normalize(corner + a * eu + b * ev - origin)};
        if (std::abs(glm::dot(glm::normalize(nrm), r.dir)) < 1e-3) continue;  // grazing: t ill-conditioned
        auto rect = intersect(Rectangle{corner, eu, ev}, r, 0.0, 1e30);
        auto patch = intersect(p, r, 0.0, 1e30);
        ASSERT_EQ(bool(rect), bool(patch)) << "a " << a << " b " << b;
        if (!rect) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_NEAR(patch->t, rect->t, 1e-12 * rect->t);
        EXPECT_NEAR(patch->uv.x, rect->uv.x, 1e-10);
        EXPECT_NEAR(patch->uv.y, rect->uv.y, 1e-10);
        EXPECT_LE(glm::length(patch->normal - rect->normal), 1e-12);
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 50);
}

TEST(BezierIntersect, RespectsTheInterval) {
    const BezierPatch& front = teapot()[4];
    Ray r{{0.3, -10, 0.9}, {0, 1, 0}};
    ASSERT_TRUE(intersect(front, r, 0.0, 1e30));
    EXPECT_FALSE(intersect(front, r, 0.0, 8.0));
    EXPECT_FALSE(intersect(front, r, 8.1, 1e30));
    EXPECT_FALSE(intersect(front, {{0.3, 10, 0.9}, {0, 1, 0}}, 0.0, 1e30));  // pointing away
    auto ts = distinct_ts(all_hits(teapot(), r, 9.0, 1e30));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(ts[0], 11.9785213, 1e-7);
}

TEST(BezierIntersect, DirectionNeedNotBeUnit) {
    auto ts = distinct_ts(all_hits(teapot(), {{0, -10, 0.9}, {0, 4, 0}}));
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 2.0, 1e-12);
    EXPECT_NEAR(ts[1], 3.0, 1e-12);
}

TEST(BezierIntersect, NonsenseRaysAreMissesNotCrashes) {
    const BezierPatch& p = teapot()[0];
    const double nan = std::nan(""), inf = INFINITY;
    EXPECT_TRUE(intersect_all(p, {{0, 0, 10}, {0, 0, 0}}, 0.0, 1e30).empty());
    EXPECT_TRUE(intersect_all(p, {{nan, 0, 10}, {0, 0, -1}}, 0.0, 1e30).empty());
    EXPECT_TRUE(intersect_all(p, {{0, 0, 10}, {0, nan, -1}}, 0.0, 1e30).empty());
    EXPECT_TRUE(intersect_all(p, {{inf, 0, 10}, {0, 0, -1}}, 0.0, 1e30).empty());
    EXPECT_TRUE(intersect_all(p, {{1.4, 0, 10}, {0, 0, -1}}, 0.0, nan).empty());
    BezierPatch point;  // every control point the same: no area to hit
    EXPECT_TRUE(intersect_all(point, {{0, 0, 10}, {0, 0, -1}}, 0.0, 1e30).empty());
}

// A ray lying in the plane of a flat patch: the pencil is singular. Whatever comes back must be
// points of the patch on the ray.
TEST(BezierIntersect, RayInThePlaneOfAFlatPatchIsHandled) {
    BezierPatch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.points[4 * i + j] = dvec3(i / 3.0, j / 3.0, 0.0);
    for (Ray r : {Ray{{-1, 0.5, 0}, {1, 0, 0}}, Ray{{-1, -1, 0}, glm::normalize(dvec3(1, 1, 0))}}) {
        for (const PatchHit& h : intersect_all(p, r, 0.0, 1e30)) {
            ASSERT_TRUE(std::isfinite(h.t));
            EXPECT_LE(glm::length(evaluate(p, h.u, h.v) - (r.origin + h.t * r.dir)), 1e-9);
        }
    }
}

// Tangent rays (design notes, section 3.8): the body's widest circle, z = 0.9, touched from the
// side, and rays tangent to random surface points offset by tiny distances. No NaN, no crash,
// every hit a point of the patch on the ray. A touching point (a double root) may or may not be
// reported; how often it is, is recorded.
TEST(BezierIntersect, TangentRaysAreHandled) {
    Ray touch{{-10, 2, 0.9}, {1, 0, 0}};
    auto hits = all_hits(teapot(), touch);
    expect_on_ray_and_patch(hits, teapot(), touch, 1e-7);
    for (const auto& h : hits) EXPECT_NEAR(h.t, 10.0, 1e-3);
    int touching = 0, touched = 0;

    std::mt19937 rng(8);
    const auto& set = teapot();
    for (int n = 0; n < 300; ++n) {
        int k = static_cast<int>(rng() % set.size());
        double u0 = uniform(rng, 0.05, 0.95), v0 = uniform(rng, 0.05, 0.95);
        auto j = surface::evaluate_jet(set[k], u0, v0);
        dvec3 nrm = surface::unit_normal(set[k], u0, v0);
        dvec3 tangent = glm::normalize(uniform(rng, -1, 1) * j.su + uniform(rng, -1, 1) * j.sv);
        double offset = std::array<double, 7>{0.0, 1e-12, -1e-12, 1e-8, -1e-8, 1e-4, -1e-4}[n % 7];
        Ray r{j.s + offset * nrm - 5.0 * tangent, tangent};
        auto h = all_hits(set, r);
        expect_on_ray_and_patch(h, set, r, 1e-7);
        if (offset == 0.0) {
            ++touching;
            for (const auto& x : h)
                if (std::abs(x.t - 5.0) < 1e-3) {
                    ++touched;
                    break;
                }
        }
    }
    RecordProperty("touching_points_reported", std::to_string(touched) + " of " + std::to_string(touching));
    // Counting near-double eigenvalues (|Im u| <= 1e-5) as real is what finds most of them.
    EXPECT_GE(touched, touching * 9 / 10);
}

// The teapot is mirror-symmetric in y: a ray and its mirror image see the same distances.
TEST(BezierIntersect, MirrorImageRaysAgree) {
    std::mt19937 rng(11);
    int hits = 0;
    for (int n = 0; n < 300; ++n) {
        dvec3 origin = dvec3(uniform(rng, -6, 6), uniform(rng, -6, 6), uniform(rng, -2, 6));
        dvec3 toward(uniform(rng, -3, 3.5), uniform(rng, -2, 2), uniform(rng, 0, 3.15));
        Ray r{origin, glm::normalize(toward - origin)};
        Ray m{{origin.x, -origin.y, origin.z}, {r.dir.x, -r.dir.y, r.dir.z}};
        auto a = test::nearest_hit(teapot(), r);
        auto b = test::nearest_hit(teapot(), m);
        ASSERT_EQ(bool(a), bool(b)) << n;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 1e-9 * a->t);
    }
    EXPECT_GT(hits, 100);
}

// The renderer calls the intersector from every core at once (LAPACK workspace is per thread).
TEST(BezierIntersect, ConcurrentCallsGiveTheSameAnswers) {
    std::mt19937 rng(12);
    std::vector<Ray> rays;
    for (int n = 0; n < 200; ++n) {
        dvec3 origin(uniform(rng, -6, 6), uniform(rng, -6, 6), uniform(rng, -2, 6));
        dvec3 toward(uniform(rng, -3, 3.5), uniform(rng, -2, 2), uniform(rng, 0, 3.15));
        rays.push_back({origin, glm::normalize(toward - origin)});
    }
    auto trace = [&](std::vector<std::vector<test::SetHit>>& out) {
        for (const Ray& r : rays) out.push_back(all_hits(teapot(), r));
    };
    std::vector<std::vector<test::SetHit>> serial;
    trace(serial);
    std::vector<std::vector<std::vector<test::SetHit>>> parallel(4);
    std::vector<std::thread> threads;
    for (auto& out : parallel) threads.emplace_back([&] { trace(out); });
    for (auto& t : threads) t.join();
    int hits = 0;
    for (const auto& out : parallel) {
        ASSERT_EQ(out.size(), serial.size());
        for (std::size_t i = 0; i < serial.size(); ++i) {
            ASSERT_EQ(out[i].size(), serial[i].size());
            for (std::size_t k = 0; k < serial[i].size(); ++k) {
                EXPECT_EQ(out[i][k].t, serial[i][k].t);
                EXPECT_EQ(out[i][k].patch, serial[i][k].patch);
                ++hits;
            }
        }
    }
    EXPECT_GT(hits, 4 * 100);
}

}  // namespace
}  // namespace lancer::cpu
