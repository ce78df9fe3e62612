// The reference's blob (host/cpu/shapes/blob.cpp): one component against the sphere or capsule
// it is, merging and carving components against the field's own closed forms, and aimed random
// rays against a march of the field (written here apart, from the distance to each segment).
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer::cpu {
namespace blob_test {  // its own names in the unity build
namespace {

constexpr double kFar = 1e30;

BlobComponent ball(const dvec3& c, double radius, double strength) { return BlobComponent{c, c, radius, strength}; }
BlobComponent stick(const dvec3& a, const dvec3& b, double radius, double strength) { return BlobComponent{a, b, radius, strength}; }

Blob blob(double threshold, std::vector<BlobComponent> components) {
    Blob o;
    o.threshold = threshold;
    o.components = std::move(components);
    prepare_blob(o);
    return o;
}

// The radius where one component's field is the threshold.
double surface_radius(double radius, double strength, double threshold) { return radius * std::sqrt(1.0 - std::sqrt(threshold / strength)); }

// The field, from each point's distance to each segment.
double field(const Blob& o, const dvec3& p) {
    double sum = 0.0;
    for (const BlobComponent& k : o.components) {
        const dvec3 ab = k.b - k.a;
        const double ab2 = glm::dot(ab, ab);
        const double x = ab2 > 0.0 ? std::clamp(glm::dot(p - k.a, ab) / ab2, 0.0, 1.0) : 0.0;
        const dvec3 away = p - (k.a + x * ab);
        const double q = glm::dot(away, away) / (k.radius * k.radius);
        if (q < 1.0) sum += k.strength * (1.0 - q) * (1.0 - q);
    }
    return sum;
}

// The outward unit normal by central differences of the field.
dvec3 numeric_normal(const Blob& o, const dvec3& p) {
    const double h = 1e-6;
    dvec3 g;
    for (int i = 0; i < 3; ++i) {
        dvec3 e(0.0);
        e[i] = h;
        g[i] = field(o, p + e) - field(o, p - e);
    }
    return -glm::normalize(g);
}

// The components whose bounding ball (about the segment's middle) the ray's line passes through.
Blob near_line(const Blob& o, const Ray& ray) {
    Blob near = o;
    near.components.clear();
    const dvec3 d = glm::normalize(ray.dir);
    for (const BlobComponent& k : o.components) {
        const dvec3 w = ray.origin - 0.5 * (k.a + k.b);
        const double reach = 0.5 * glm::length(k.b - k.a) + k.radius;
        if (glm::length(w - glm::dot(w, d) * d) < reach * 1.001) near.components.push_back(k);
    }
    return near;
}

// Every root of threshold - field in (t0, t1) by a march of `steps` samples: bisection where the
// sign changes, and where a sample is a small extremum without a change, a golden-section search
// for the extremum, bisected from both sides if it crosses (a ray that dips through the surface
// between two samples).
std::vector<double> march(const Blob& whole, const Ray& ray, double t0, double t1, int steps) {
    const Blob o = near_line(whole, ray);
    auto g = [&](double t) { return o.threshold - field(o, ray.origin + t * ray.dir); };
    auto bisect = [&](double lo, double hi) {
        const bool lo_positive = g(lo) > 0.0;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            if ((g(mid) > 0.0) == lo_positive) lo = mid; else hi = mid;
        }
        return 0.5 * (lo + hi);
    };
    std::vector<double> ts(steps + 1), vs(steps + 1);
    for (int i = 0; i <= steps; ++i) {
        ts[i] = t0 + (t1 - t0) * i / steps;
        vs[i] = g(ts[i]);
    }
    std::vector<double> roots;
    for (int i = 0; i < steps; ++i)
        if ((vs[i] > 0.0) != (vs[i + 1] > 0.0)) roots.push_back(bisect(ts[i], ts[i + 1]));
    for (int i = 1; i < steps; ++i) {
        const double sign = vs[i] > 0.0 ? 1.0 : -1.0;  // +1: look for a dip below 0, -1: a rise above
        const bool same = (vs[i - 1] > 0.0) == (vs[i] > 0.0) && (vs[i + 1] > 0.0) == (vs[i] > 0.0);
        if (!same || !(sign * vs[i] < sign * vs[i - 1] && sign * vs[i] <= sign * vs[i + 1])) continue;
        if (std::abs(vs[i]) > 1e-2 * o.threshold) continue;
        double lo = ts[i - 1], hi = ts[i + 1];
        const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int k = 0; k < 200; ++k) {
            const double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
            if (sign * g(x1) < sign * g(x2)) hi = x2; else lo = x1;
        }
        const double extremum = 0.5 * (lo + hi);
        if (sign * g(extremum) >= 0.0) continue;
        roots.push_back(bisect(ts[i - 1], extremum));
        roots.push_back(bisect(extremum, ts[i + 1]));
    }
    std::sort(roots.begin(), roots.end());
    return roots;
}

// The line's stretch through the blob's box, grown a little.
std::pair<double, double> through_box(const Blob& o, const Ray& ray) {
    const dvec3 lo = o.lo - 0.01, hi = o.hi + 0.01;
    double t0 = -kFar, t1 = kFar;
    for (int i = 0; i < 3; ++i) {
        if (ray.dir[i] == 0.0) continue;
        const double a = (lo[i] - ray.origin[i]) / ray.dir[i], b = (hi[i] - ray.origin[i]) / ray.dir[i];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    return {t0, t1};
}

// A ray from a point on a sphere of radius `distance` about the box's centre toward a random
// point of the box.
Ray aimed(const Blob& o, std::mt19937& rng, double distance) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    const dvec3 centre = 0.5 * (o.lo + o.hi);
    const dvec3 from = centre + distance * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
    const dvec3 to = o.lo + (o.hi - o.lo) * dvec3(unit(rng), unit(rng), unit(rng));
    return Ray{from, glm::normalize(to - from)};
}

// intersect() against the march's first root beyond 0 (and its next), for `rays` aimed rays;
// `hits` counts the rays that hit.
void expect_agrees_with_march(const Blob& o, int rays, double step, unsigned seed, int& hits) {
    std::mt19937 rng(seed);
    hits = 0;
    for (int i = 0; i < rays; ++i) {
        const Ray ray = aimed(o, rng, 3.0 * glm::length(o.hi - o.lo));
        const auto [t0, t1] = through_box(o, ray);
        const std::vector<double> roots = march(o, ray, t0, t1, int(std::ceil((t1 - t0) / step)));
        const auto h = intersect(o, ray, 0.0, kFar);
        ASSERT_EQ(bool(h), !roots.empty()) << i;
        if (!h) continue;
        ++hits;
        EXPECT_NEAR(h->t, roots.front(), 1e-9 * roots.front()) << i;
        const dvec3 p = ray.origin + h->t * ray.dir;
        EXPECT_NEAR(glm::length(h->normal), 1.0, 1e-12) << i;
        EXPECT_GT(glm::dot(h->normal, numeric_normal(o, p)), 1.0 - 1e-8) << i;
        // And the next root, from just past this one.
        const auto after = std::upper_bound(roots.begin(), roots.end(), h->t + 1e-7);
        const auto next = intersect(o, ray, h->t + 1e-7, kFar);
        ASSERT_EQ(bool(next), after != roots.end()) << i;
        if (next) {
            EXPECT_NEAR(next->t, *after, 1e-9 * next->t) << i;
        }
    }
}

TEST(Blob, OneSphereIsTheSphereOfItsThresholdRadius) {
    const dvec3 c(0.3, -0.2, 0.5);
    const Blob o = blob(0.5, {ball(c, 2.0, 1.5)});
    const double R = surface_radius(2.0, 1.5, 0.5);  // about 1.30
    auto h = intersect(o, {c - dvec3(10, 0, 0), {1, 0, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10.0 - R, 1e-13);
    EXPECT_NEAR(glm::length(h->normal - dvec3(-1, 0, 0)), 0.0, 1e-12);
    // Aimed rays, and rays through the field short of the surface (R < miss < 2), against the sphere.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0, misses = 0;
    for (int i = 0; i < 1000; ++i) {
        const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)) - 0.5);
        const dvec3 across = glm::normalize(glm::cross(dir, dvec3(unit(rng), unit(rng), unit(rng)) - 0.5));
        const double offset = 1.9 * unit(rng);
        const Ray ray{c + offset * across - (3.0 + 10.0 * unit(rng)) * dir, dir};
        const auto expected = sphere_hit_t(c, R, ray, 0.0, kFar);
        const auto got = intersect(o, ray, 0.0, kFar);
        ASSERT_EQ(bool(got), bool(expected)) << i << " offset " << offset;
        if (!got) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_NEAR(got->t, *expected, 1e-12 * *expected) << i;
        EXPECT_NEAR(glm::length(got->normal - (ray.origin + got->t * dir - c) / R), 0.0, 1e-9) << i;
    }
    EXPECT_GT(hits, 500);
    EXPECT_GT(misses, 200);
}

// The nearest t > 0 where a ray from outside enters the capsule of radius R about [a, b].
std::optional<double> capsule_entry(const dvec3& a, const dvec3& b, double R, const Ray& ray) {
    std::optional<double> best;
    auto take = [&](std::optional<double> t) {
        if (t && (!best || *t < *best)) best = t;
    };
    take(sphere_hit_t(a, R, ray, 0.0, kFar));
    take(sphere_hit_t(b, R, ray, 0.0, kFar));
    // The side: |(o + t d - a) x u| = R with 0 <= (o + t d - a).u <= |b - a|.
    const dvec3 u = glm::normalize(b - a);
    const dvec3 w = ray.origin - a, wp = w - glm::dot(w, u) * u, dp = ray.dir - glm::dot(ray.dir, u) * u;
    const double A = glm::dot(dp, dp), B = glm::dot(wp, dp), C = glm::dot(wp, wp) - R * R;
    if (A > 0.0 && B * B - A * C >= 0.0) {
        const double t = (-B - std::sqrt(B * B - A * C)) / A;
        const double along = glm::dot(w + t * ray.dir, u);
        if (t > 0.0 && along >= 0.0 && along <= glm::length(b - a)) take(t);
    }
    return best;
}

TEST(Blob, OneCylinderIsItsCapsule) {
    const dvec3 a(-1.0, 0.5, 0.2), b(1.5, -0.3, 0.4);
    const Blob o = blob(0.7, {stick(a, b, 0.8, 2.0)});
    const double R = surface_radius(0.8, 2.0, 0.7);
    const dvec3 u = glm::normalize(b - a), n = glm::normalize(glm::cross(u, dvec3(0, 0, 1)));
    // At the body, square on.
    auto h = intersect(o, {0.5 * (a + b) + 5.0 * n, -n}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - R, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - n), 0.0, 1e-12);
    // Along the axis, both ways: the caps' poles.
    h = intersect(o, {b + 5.0 * u, -u}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - R, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - u), 0.0, 1e-12);
    h = intersect(o, {a - 5.0 * u, u}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - R, 1e-12);
    EXPECT_NEAR(glm::length(h->normal + u), 0.0, 1e-12);
    EXPECT_NEAR(roots_on_line(o, {a - 5.0 * u, u}).back(), 5.0 + glm::length(b - a) + R, 1e-12);
    // Parallel to the axis, off it: a cap's sphere.
    h = intersect(o, {b + 0.6 * R * n + 5.0 * u, -u}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - 0.8 * R, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(0.6 * n + 0.8 * u)), 0.0, 1e-12);
    // Through the rim where the side meets a cap, across the end plane there: the root is where
    // the ray leaves one stretch (the body) for the next (the cap), found once.
    const dvec3 rim = b + R * n, across = glm::normalize(-n + 0.5 * u);
    const std::vector<double> line = roots_on_line(o, {rim - 4.0 * across, across});
    ASSERT_EQ(line.size(), 2u);
    EXPECT_NEAR(line[0], 4.0, 1e-12);
    // Aimed rays, against the capsule.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0, caps = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = aimed(o, rng, 6.0);
        const auto expected = capsule_entry(a, b, R, ray);
        const auto got = intersect(o, ray, 0.0, kFar);
        ASSERT_EQ(bool(got), bool(expected)) << i;
        if (!got) continue;
        ++hits;
        EXPECT_NEAR(got->t, *expected, 1e-12 * *expected) << i;
        const dvec3 p = ray.origin + got->t * ray.dir;
        const double along = glm::dot(p - a, u);
        if (along < 0.0 || along > glm::length(b - a)) ++caps;
        const dvec3 nearest = a + std::clamp(along, 0.0, glm::length(b - a)) * u;
        EXPECT_NEAR(glm::length(got->normal - (p - nearest) / R), 0.0, 1e-9) << i;
    }
    EXPECT_GT(hits, 300);
    EXPECT_GT(caps, 50);
}

TEST(Blob, TwoSpheresMergeThroughANeck) {
    // Strength 1, radius 1, 1.2 apart, threshold 0.5: at their middle the field is
    // 2 (1 - 0.36 - y^2)^2, the threshold at y^2 = 0.14; alone, each sphere's surface is 0.54 from
    // its centre, short of the middle.
    const Blob merged = blob(0.5, {ball({-0.6, 0, 0}, 1.0, 1.0), ball({0.6, 0, 0}, 1.0, 1.0)});
    auto h = intersect(merged, {{0, -5, 0}, {0, 1, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - std::sqrt(0.14), 1e-12);
    EXPECT_NEAR(glm::length(h->normal - dvec3(0, -1, 0)), 0.0, 1e-12);
    const double R = surface_radius(1.0, 1.0, 0.5);
    // Along the line of centres: one solid, in at the first's far side, out at the second's.
    std::vector<double> roots = roots_on_line(merged, {{-5, 0, 0}, {1, 0, 0}});
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], 5.0 - 0.6 - R, 1e-12);
    EXPECT_NEAR(roots[1], 5.0 + 0.6 + R, 1e-12);
    // 1.8 apart, they stay two: the middle is outside, the line of centres meets four walls.
    const Blob apart = blob(0.5, {ball({-0.9, 0, 0}, 1.0, 1.0), ball({0.9, 0, 0}, 1.0, 1.0)});
    EXPECT_FALSE(intersect(apart, {{0, -5, 0}, {0, 1, 0}}, 0.0, kFar));
    roots = roots_on_line(apart, {{-5, 0, 0}, {1, 0, 0}});
    ASSERT_EQ(roots.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[i] - 5.0, -roots[3 - i] + 5.0, 1e-12) << i;
    EXPECT_NEAR(roots[1] - 5.0, -0.9 + R, 1e-12);  // the other's field ends short of the inner walls
    // Aimed rays, against the march.
    int hits;
    expect_agrees_with_march(merged, 2000, 2e-3, 11, hits);
    EXPECT_GT(hits, 600);
    expect_agrees_with_march(apart, 1000, 2e-3, 12, hits);
    EXPECT_GT(hits, 250);
}

TEST(Blob, NegativeComponentCarvesAHole) {
    // (1 - d^2 / 4)^2 - (1 - d^2)^2 = 0.5 within the negative one's radius 1, x = d^2:
    // 15 x^2 - 24 x + 8 = 0; beyond it (1 - x / 4)^2 = 0.5.
    const Blob o = blob(0.5, {ball({0, 0, 0}, 2.0, 1.0), ball({0, 0, 0}, 1.0, -1.0)});
    const double hole = std::sqrt((24.0 - std::sqrt(96.0)) / 30.0), outer = std::sqrt(4.0 * (1.0 - std::sqrt(0.5)));
    const dvec3 dir = glm::normalize(dvec3(1, 2, -0.5));
    const std::vector<double> roots = roots_on_line(o, {dvec3(0.0), dir});
    ASSERT_EQ(roots.size(), 4u);
    EXPECT_NEAR(roots[0], -outer, 1e-12);
    EXPECT_NEAR(roots[1], -hole, 1e-12);
    EXPECT_NEAR(roots[2], hole, 1e-12);
    EXPECT_NEAR(roots[3], outer, 1e-12);
    EXPECT_FALSE(inside(o, dvec3(0.0)));
    EXPECT_TRUE(inside(o, 0.9 * dir));
    EXPECT_FALSE(inside(o, 1.1 * dir));
    // From the hole's middle, the hole's wall faces in.
    auto h = intersect(o, {dvec3(0.0), dir}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, hole, 1e-12);
    EXPECT_NEAR(glm::length(h->normal + dir), 0.0, 1e-12);
    // An off-centre negative one bites a dent: against the march.
    const Blob bitten = blob(0.5, {ball({0, 0, 0}, 2.0, 1.0), ball({0.9, 0.3, 0}, 0.8, -2.0), stick({-1, -1, 0}, {-1, 1, 0.5}, 0.5, -0.7)});
    int hits;
    expect_agrees_with_march(bitten, 1000, 2e-3, 13, hits);
    EXPECT_GT(hits, 200);
}

TEST(Blob, FromInsideItLeaves) {
    const dvec3 c(1, 2, 3);
    const Blob o = blob(0.3, {ball(c, 1.5, 1.0)});
    const double R = surface_radius(1.5, 1.0, 0.3);
    const dvec3 dir = glm::normalize(dvec3(-1, 0.5, 2));
    auto h = intersect(o, {c, dir}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, R, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - dir), 0.0, 1e-12);
    // From outside, t_min past the entry: the exit.
    h = intersect(o, {c - 5.0 * dir, dir}, 5.0 - R + 1e-9, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 + R, 1e-12);
    EXPECT_TRUE(inside(o, c + 0.99 * R * dir));
    EXPECT_FALSE(inside(o, c + 1.01 * R * dir));
}

TEST(Blob, GrazingHitsOnlyWhereItReachesTheSurface) {
    const Blob o = blob(0.5, {ball({0, 0, 0}, 1.0, 1.0)});
    const double R = surface_radius(1.0, 1.0, 0.5);
    auto at = [](double y) { return Ray{{-5, y, 0}, {1, 0, 0}}; };
    // Just within: two close roots; just beyond: none.
    const double within = R * (1.0 - 1e-8);
    auto h = intersect(o, at(within), 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - std::sqrt(R * R - within * within), 1e-9);
    EXPECT_EQ(roots_on_line(o, at(within)).size(), 2u);
    EXPECT_FALSE(intersect(o, at(R * (1.0 + 1e-8)), 0.0, kFar));
    EXPECT_TRUE(roots_on_line(o, at(R * (1.0 + 1e-8))).empty());
    // Through the field short of the threshold, and beyond the field.
    EXPECT_FALSE(intersect(o, at(0.5 * (R + 1.0)), 0.0, kFar));
    EXPECT_FALSE(intersect(o, at(1.5), 0.0, kFar));
    // Stopped short, pointed away.
    EXPECT_FALSE(intersect(o, at(0.0), 0.0, 5.0 - R - 1e-9));
    EXPECT_FALSE(intersect(o, {{-5, 0, 0}, {-1, 0, 0}}, 0.0, kFar));
    // A capsule grazed along its side.
    const Blob side = blob(0.5, {stick({-1, 0, 0}, {1, 0, 0}, 1.0, 1.0)});
    h = intersect(side, {{0.3, within, -5}, {0, 0, 1}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0 - std::sqrt(R * R - within * within), 1e-9);
    EXPECT_FALSE(intersect(side, {{0.3, R * (1.0 + 1e-8), -5}, {0, 0, 1}}, 0.0, kFar));
}

TEST(Blob, TouchingIsOneRootAndALineAlongTheSurfaceToo) {
    // Tangent to within rounding: one touching root, not a run of pieces each told a root.
    const Blob o = blob(0.5, {ball({0, 0, 0}, 1.0, 1.0)});
    const double R = surface_radius(1.0, 1.0, 0.5);
    const Ray tangent{{-5, R, 0}, {1, 0, 0}};
    std::vector<double> roots = roots_on_line(o, tangent);
    ASSERT_EQ(roots.size(), 1u);
    EXPECT_NEAR(roots[0], 5.0, 1e-5);  // where g's rounding hides its double root: the root of its bound
    auto h = intersect(o, tangent, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0, 1e-5);
    // Along a capsule's side (1 - y^2)^2 = 0.25 to rounding from x = -1 to 1: one touching run
    // from the cap's side up to the body, and on to the other cap.
    const Blob side = blob(0.25, {stick({-1, 0, 0}, {1, 0, 0}, 1.0, 1.0)});
    const Ray along{{-5, std::sqrt(0.5), 0}, {1, 0, 0}};
    roots = roots_on_line(side, along);
    ASSERT_EQ(roots.size(), 1u);
    EXPECT_NEAR(roots[0], 4.0, 1e-5);
    h = intersect(side, along, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-5);
    EXPECT_NEAR(glm::length(h->normal - dvec3(0, 1, 0)), 0.0, 1e-5);
}

TEST(Blob, DirectionLengthIsTheRaysOwnParameter) {
    const Blob o = blob(0.4, {ball({0, 0, 0}, 1.0, 1.0), stick({0.5, 0, 0}, {1.5, 0.5, 0}, 0.6, 0.8), ball({-0.5, 0.4, 0.3}, 0.7, -0.5)});
    std::mt19937 rng(17);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Ray unit_ray = aimed(o, rng, 5.0);
        const auto reference = intersect(o, unit_ray, 0.0, kFar);
        for (double k : {1e-3, 0.37, 7.5}) {
            const Ray ray{unit_ray.origin, k * unit_ray.dir};
            const auto h = intersect(o, ray, 0.0, kFar);
            ASSERT_EQ(bool(h), bool(reference)) << i << " " << k;
            if (!h) continue;
            EXPECT_NEAR(h->t * k, reference->t, 1e-12 * reference->t) << i << " " << k;
            EXPECT_NEAR(glm::length(h->normal - reference->normal), 0.0, 1e-9) << i << " " << k;
            // t_min and t_max are the ray's own too.
            EXPECT_FALSE(intersect(o, ray, 0.0, 0.999 * reference->t / k)) << i << " " << k;
            const std::vector<double> line = roots_on_line(o, ray), unit_line = roots_on_line(o, unit_ray);
            ASSERT_EQ(line.size(), unit_line.size()) << i << " " << k;
            for (std::size_t j = 0; j < line.size(); ++j) EXPECT_NEAR(line[j] * k, unit_line[j], 1e-12 * 10.0) << i << " " << k;
        }
        hits += bool(reference);
    }
    EXPECT_GT(hits, 50);
}

// Random components in [-2, 2]^3: spheres and cylinders, a fifth negative.
Blob random_blob(int count, double small, double large, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<BlobComponent> components;
    for (int i = 0; i < count; ++i) {
        const dvec3 a = 4.0 * dvec3(unit(rng), unit(rng), unit(rng)) - 2.0;
        const dvec3 b = unit(rng) < 0.3 ? a + 0.6 * (dvec3(unit(rng), unit(rng), unit(rng)) - 0.5) : a;
        const double radius = small + (large - small) * unit(rng);
        const double strength = unit(rng) < 0.2 ? -(0.3 + 0.7 * unit(rng)) : 0.5 + unit(rng);
        components.push_back({a, b, radius, strength});
    }
    return blob(0.4, components);
}

TEST(Blob, RootsOnLineAlternateInsideAndOutside) {
    const Blob o = random_blob(40, 0.4, 1.0, 21);
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int crossings = 0;
    for (int i = 0; i < 300; ++i) {
        // From a point in the box (roots behind it too), any direction length.
        const dvec3 from = o.lo + (o.hi - o.lo) * dvec3(unit(rng), unit(rng), unit(rng));
        const Ray ray{from, (0.2 + 3.0 * unit(rng)) * dvec3(normal(rng), normal(rng), normal(rng))};
        const std::vector<double> roots = roots_on_line(o, ray);
        const auto [t0, t1] = through_box(o, ray);
        const std::vector<double> marched = march(o, ray, t0, t1, 20000);
        ASSERT_EQ(roots.size(), marched.size()) << i;
        ASSERT_EQ(roots.size() % 2, 0u) << i;
        crossings += int(roots.size());
        const double scale = glm::length(ray.dir);
        for (std::size_t j = 0; j < roots.size(); ++j) {
            EXPECT_NEAR(roots[j], marched[j], 1e-9 * (1.0 + std::abs(roots[j]) * scale) / scale) << i << " " << j;
            if (j > 0) {
                EXPECT_LT(roots[j - 1], roots[j]) << i;
            }
            // Between consecutive roots the field's side alternates, inside first.
            if (j + 1 < roots.size()) {
                EXPECT_EQ(inside(o, ray.origin + 0.5 * (roots[j] + roots[j + 1]) * ray.dir), j % 2 == 0) << i << " " << j;
            }
        }
        if (!roots.empty()) {
            EXPECT_FALSE(inside(o, ray.origin + (roots.front() - 1e-6 / scale) * ray.dir)) << i;
            EXPECT_FALSE(inside(o, ray.origin + (roots.back() + 1e-6 / scale) * ray.dir)) << i;
        }
    }
    EXPECT_GT(crossings, 300);
}

TEST(Blob, HundredsOfSmallComponentsAgreeWithAMarch) {
    const Blob o = random_blob(300, 0.15, 0.4, 31);
    int hits;
    expect_agrees_with_march(o, 2000, 1e-3, 32, hits);
    EXPECT_GT(hits, 1000);
}

TEST(Blob, FarFromTheOriginItKeepsItsPrecision) {
    const dvec3 far(3e4, -2e4, 1e4);
    const Blob o = blob(0.5, {ball(far, 0.01, 1.0), ball(far + dvec3(0.012, 0, 0), 0.01, 1.0)});
    const double R = surface_radius(0.01, 1.0, 0.5);
    auto h = intersect(o, {far - dvec3(1, 0, 0), {1, 0, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1.0 - R, 1e-12);
    // From far off, along the merged pair's neck plane.
    const dvec3 middle = far + dvec3(0.006, 0, 0);
    const double neck = std::sqrt(0.01 * 0.01 * (1.0 - std::sqrt(0.25)) - 0.006 * 0.006);  // 2 (1 - q)^2 = 0.5
    h = intersect(o, {middle - dvec3(0, 1e3, 0), {0, 1, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1e3 - neck, 1e-10);
}

TEST(Blob, TextureIsXAndYAcrossTheBox) {
    const Blob o = blob(0.5, {ball({0, 0, 0}, 1.0, 1.0), stick({1, 1, 1}, {2, 1, 1}, 0.5, 1.0), ball({5, 5, 5}, 1.0, -1.0)});
    EXPECT_EQ(o.lo, dvec3(-1, -1, -1));  // the negative one is not in the box
    EXPECT_EQ(o.hi, dvec3(2.5, 1.5, 1.5));
    const glm::dvec2 uv = texture_uv(o, dvec3(0.75, 0.5, 7.0));
    EXPECT_DOUBLE_EQ(uv.x, 0.5);
    EXPECT_DOUBLE_EQ(uv.y, 0.6);
    EXPECT_DOUBLE_EQ(texture_uv(o, o.lo).x, 0.0);
    EXPECT_DOUBLE_EQ(texture_uv(o, o.hi).y, 1.0);
}

}  // namespace
}  // namespace blob_test
}  // namespace lancer::cpu
