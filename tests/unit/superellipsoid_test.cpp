// The reference's superellipsoid (host/cpu/shapes/superellipsoid.cpp) against POV-Ray's
// g(x, y, z) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n), evaluated here as written: a march of g
// along thousands of aimed random rays for exponents from the cube's (e = 0.001) to the
// octahedron's (e = 2) and mixed; tangent lines near edges and corners, moved off the surface
// by a hair (outside: a convex solid is behind its tangent plane, so a miss; inside: a hit on
// each side of the point of contact); rays from inside (the exit); normals against finite
// differences of g; the sphere (e = n = 1) and the box (small e, n) in closed form; the ray's own
// parameter far away; the reader's keys and texture mapping.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "support/test_support.hpp"

namespace lancer::cpu {
namespace superellipsoid_test {  // its own names in the unity build
namespace {

constexpr double kNoEnd = std::numeric_limits<double>::infinity();

// POV-Ray's g, with the larger of |x| and |y|, m, taken out of its first term,
// m^q s^(q/p) with s = (|x|/m)^p + (|y|/m)^p in [1, 2], that product taken as the exponential of
// its log, so that exponents of 2000 neither underflow nor overflow there (written as is,
// |x|^2000 is 0 for |x| < 0.7, and with n = 2 that term is not small; with e = 2 and n = 0.001,
// s^2000 overflows where m^2000 underflows).
double pov_g(const Superellipsoid& o, const dvec3& x) {
    const double p = 2.0 / o.e, q = 2.0 / o.n;
    const double m = std::max(std::abs(x.x), std::abs(x.y));
    if (m == 0.0) return std::pow(std::abs(x.z), q);
    const double s = std::pow(std::abs(x.x) / m, p) + std::pow(std::abs(x.y) / m, p);
    return std::exp(q * std::log(m) + q / p * std::log(s)) + std::pow(std::abs(x.z), q);
}

// g^(n/2): its level 1 is the surface, of slope about 1 across it, so a distance can be read off.
double level(const Superellipsoid& o, const dvec3& x) { return std::pow(pov_g(o, x), o.n / 2.0); }

bool inside(const Superellipsoid& o, const dvec3& x) { return pov_g(o, x) < 1.0; }

// g's gradient, differentiated by hand: q S^(q/p - 1) |x|^(p - 1) sign(x), ..., q |z|^(q - 1) sign(z)
// with S = |x|^p + |y|^p, the first two with m taken out as in pov_g:
// q m^(q - 1) s^(q/p - 1) (|x|/m)^(p - 1), s = (|x|/m)^p + (|y|/m)^p.
dvec3 exact_normal(const Superellipsoid& o, const dvec3& x) {
    const double p = 2.0 / o.e, q = 2.0 / o.n;
    const double m = std::max(std::abs(x.x), std::abs(x.y));
    const dvec3 a = glm::abs(x), sign(x.x < 0.0 ? -1.0 : 1.0, x.y < 0.0 ? -1.0 : 1.0, x.z < 0.0 ? -1.0 : 1.0);
    dvec3 g(0.0, 0.0, q * std::pow(a.z, q - 1.0) * sign.z);
    if (m > 0.0) {
        const double s = std::pow(a.x / m, p) + std::pow(a.y / m, p);
        const double across = q * std::exp((q - 1.0) * std::log(m) + (q / p - 1.0) * std::log(s));
        g.x = across * std::pow(a.x / m, p - 1.0) * sign.x;
        g.y = across * std::pow(a.y / m, p - 1.0) * sign.y;
    }
    return glm::normalize(g);
}

// The line's stretch through [-1, 1]^3, where the solid is (empty: first > second).
std::pair<double, double> through_cube(const Ray& ray) {
    double lo = -kNoEnd, hi = kNoEnd;
    for (int i = 0; i < 3; ++i) {
        const double a = (-1.0 - ray.origin[i]) / ray.dir[i], b = (1.0 - ray.origin[i]) / ray.dir[i];
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
    }
    return {lo, hi};
}

// The unit normal from central differences of g.
dvec3 difference_normal(const Superellipsoid& o, const dvec3& x) {
    const double h = 1e-7;
    dvec3 g;
    for (int i = 0; i < 3; ++i) {
        dvec3 a = x, b = x;
        a[i] += h;
        b[i] -= h;
        g[i] = (pov_g(o, a) - pov_g(o, b)) / (2.0 * h);
    }
    return glm::normalize(g);
}

const std::array<Superellipsoid, 10> kShapes = {{{0.001, 0.001},
                                                 {0.05, 0.05},
                                                 {0.5, 0.5},
                                                 {1.0, 1.0},
                                                 {2.0, 2.0},
                                                 {0.001, 2.0},
                                                 {2.0, 0.001},
                                                 {0.05, 1.0},
                                                 {0.3, 1.7},
                                                 {1.5, 0.2}}};

std::string name(const Superellipsoid& o) { return "e = " + std::to_string(o.e) + ", n = " + std::to_string(o.n); }

// A hit must be on the surface, with a unit normal close to g's direction (away from the
// kinks of |x| at a zero coordinate, where e or n is 2).
void expect_on_surface(const Superellipsoid& o, const Ray& ray, const SurfaceHit& hit, const std::string& what) {
    const dvec3 x = ray.origin + hit.t * ray.dir;
    EXPECT_NEAR(level(o, x), 1.0, 1e-11) << what << " at t = " << hit.t;
    EXPECT_NEAR(glm::length(hit.normal), 1.0, 1e-12) << what;
    if (glm::all(glm::greaterThan(glm::abs(x), dvec3(1e-3)))) {
        EXPECT_LT(glm::length(hit.normal - difference_normal(o, x)), 2e-5) << what << " at " << x.x << ", " << x.y << ", " << x.z;
    }
}

// Random rays aimed into [-1.1, 1.1]^3 from 3 away: the first change of sides of g along the
// line, marched in steps of 1e-3 from the box's entry, must bracket the reference's hit, and
// where the march sees none the reference's hit (if any) is on a chord shorter than a step.
TEST(Superellipsoid, AgreesWithAMarchOfGAlongAimedRandomRays) {
    std::mt19937 rng(46);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double step = 1e-3;
    for (const Superellipsoid& o : kShapes) {
        int hits = 0, thin = 0;
        for (int i = 0; i < 1500; ++i) {
            const dvec3 target(1.1 * unit(rng), 1.1 * unit(rng), 1.1 * unit(rng));
            const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)));
            const Ray ray{target - 3.0 * dir, dir};
            if (inside(o, ray.origin)) continue;
            const auto hit = intersect(o, ray, 0.0, kNoEnd);
            std::optional<double> change;  // the step in which the march first comes inside
            const auto [t0, t1] = through_cube(ray);
            for (double t = std::max(t0, 0.0) - step; t < t1; t += step)
                if (inside(o, ray.origin + (t + step) * ray.dir)) {
                    change = t;
                    break;
                }
            const std::string what = name(o) + ", ray " + std::to_string(i);
            if (change) {
                ASSERT_TRUE(hit) << what << ": the march comes inside at t = " << *change;
                EXPECT_GE(hit->t, *change - 1e-12) << what;
                EXPECT_LE(hit->t, *change + step + 1e-12) << what;
            } else if (hit) {
                // Missed by the march: then the line is inside for less than a step.
                const auto out = intersect(o, Ray{ray.origin + (hit->t + 1e-9) * ray.dir, ray.dir}, 0.0, kNoEnd);
                ASSERT_TRUE(out) << what << ": no exit after the entry at " << hit->t;
                EXPECT_LT(out->t, 2.0 * step) << what;
                ++thin;
            }
            if (!hit) continue;
            ++hits;
            expect_on_surface(o, ray, *hit, what);
        }
        EXPECT_GT(hits, 500) << name(o);
        EXPECT_LT(thin, 15) << name(o);
    }
}

// From random points inside, the hit is the exit: the march leaves there, and nothing before.
TEST(Superellipsoid, FromInsideTheHitIsTheExit) {
    std::mt19937 rng(47);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const Superellipsoid& o : kShapes) {
        int tried = 0;
        for (int i = 0; i < 400; ++i) {
            const dvec3 origin(unit(rng), unit(rng), unit(rng));
            if (!(pov_g(o, origin) < 0.99)) continue;
            ++tried;
            const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)));
            const Ray ray{origin, dir};
            const auto hit = intersect(o, ray, 1e-9, kNoEnd);
            const std::string what = name(o) + ", ray " + std::to_string(i);
            ASSERT_TRUE(hit) << what;
            for (double t = 0.0; t < hit->t - 1e-9; t += 2e-3) ASSERT_TRUE(inside(o, origin + t * dir)) << what << " t = " << t;
            EXPECT_FALSE(inside(o, origin + (hit->t + 1e-9) * dir)) << what;
            expect_on_surface(o, ray, *hit, what);
            EXPECT_GT(glm::dot(hit->normal, dir), 0.0) << what << ": the normal faces out";
        }
        EXPECT_GT(tried, 50) << name(o);
    }
}

// Tangent lines at points near the edges and corners (the surface's point toward a direction
// close to a corner's or an edge's), moved off the surface along the normal by a hair: outside,
// the whole line is outside (the solid is convex), a miss; inside, it crosses the surface on
// each side of the point of contact, close to it.
TEST(Superellipsoid, GrazingLinesNearEdgesAndCornersHitExactlyWhenInside) {
    std::mt19937 rng(48);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const Superellipsoid& o : kShapes) {
        int entered = 0;
        for (int i = 0; i < 300; ++i) {
            // Toward a corner (i even) or an edge's middle (odd), turned a little.
            dvec3 toward = i % 2 == 0 ? dvec3(1.0, 1.0, 1.0) : dvec3(1.0, 1.0, 0.0);
            if (i % 3 == 1) toward = dvec3(toward.z, toward.x, toward.y);
            toward = glm::normalize(toward * dvec3(unit(rng) < 0.0 ? -1.0 : 1.0, unit(rng) < 0.0 ? -1.0 : 1.0, 1.0) +
                                    0.05 * dvec3(unit(rng), unit(rng), unit(rng)));
            // The surface's point toward it: level is homogeneous of degree 1.
            const dvec3 x = toward / level(o, toward);
            if (!(std::abs(level(o, x) - 1.0) < 1e-13)) continue;
            const dvec3 normal = exact_normal(o, x);
            dvec3 along = glm::cross(normal, dvec3(unit(rng), unit(rng), unit(rng)));
            along = glm::normalize(along);
            for (double hair : {1e-7, 1e-9}) {
                const std::string what = name(o) + ", line " + std::to_string(i) + ", " + std::to_string(hair);
                const dvec3 out = x + hair * normal, in = x - hair * normal;
                EXPECT_FALSE(intersect(o, Ray{out - 4.0 * along, along}, 0.0, kNoEnd)) << what << ": outside";
                const Ray ray{in - 4.0 * along, along};
                const auto hit = intersect(o, ray, 0.0, kNoEnd);
                if (pov_g(o, in) >= 1.0) continue;  // the point inside rounded out (the cube's flat faces)
                ASSERT_TRUE(hit) << what << ": inside";
                ++entered;
                EXPECT_LE(hit->t, 4.0 + 1e-12) << what;
                EXPECT_NEAR(level(o, ray.origin + hit->t * ray.dir), 1.0, 1e-11) << what;
                // The exit: from the point of contact, and as CSG finds it, the reversed line's first hit.
                const auto exit = intersect(o, ray, 4.0, kNoEnd);
                ASSERT_TRUE(exit) << what << ": no exit";
                EXPECT_GE(exit->t, 4.0) << what;
                EXPECT_NEAR(level(o, ray.origin + exit->t * ray.dir), 1.0, 1e-11) << what;
                const auto back = intersect(o, Ray{in + 4.0 * along, -along}, -kNoEnd, kNoEnd);
                ASSERT_TRUE(back) << what << ": no exit backward";
                // The same point to the rounding of the reversed line's origin (4e-16) over the line's
                // shallow slope through the surface there.
                EXPECT_NEAR(4.0 - back->t, exit->t - 4.0, 1e-5) << what;
                EXPECT_NEAR(level(o, in + (4.0 - back->t) * along), 1.0, 1e-11) << what;
            }
        }
        EXPECT_GT(entered, 200) << name(o);
    }
}

TEST(Superellipsoid, OneOneIsTheUnitSphere) {
    std::mt19937 rng(49);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Superellipsoid o{1.0, 1.0};
    for (int i = 0; i < 500; ++i) {
        const dvec3 origin = 3.0 * dvec3(unit(rng), unit(rng), unit(rng));
        const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)) * 0.5 - origin / 3.0);
        const double b = glm::dot(origin, dir), disc = b * b - (glm::dot(origin, origin) - 1.0);
        const auto hit = intersect(o, Ray{origin, dir}, 0.0, kNoEnd);
        if (disc < 1e-9 || glm::dot(origin, origin) < 1.0) continue;
        ASSERT_EQ(bool(hit), -b - std::sqrt(disc) > 0.0) << i;
        if (!hit) continue;
        EXPECT_NEAR(hit->t, -b - std::sqrt(disc), 1e-12) << i;
        EXPECT_LT(glm::length(hit->normal - (origin + hit->t * dir)), 1e-12) << i;
    }
}

// e = n = 0.001 is |x|^2000 + |y|^2000 + |z|^2000 = 1: the box, flat in its faces' middles, its
// edges and corners 3.5e-4 and 5.5e-4 inside the cube's (1 - 2^(-1/2000), 1 - 3^(-1/2000)).
TEST(Superellipsoid, SmallExponentsAreTheBox) {
    const Superellipsoid o{0.001, 0.001};
    std::mt19937 rng(50);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const dvec3 origin = 3.0 * dvec3(unit(rng), unit(rng), unit(rng));
        const dvec3 dir = glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)) - origin / 3.0);
        const auto box = intersect(Box{}, Ray{origin, dir}, 0.0, kNoEnd);
        const auto hit = intersect(o, Ray{origin, dir}, 0.0, kNoEnd);
        if (hit) {
            ASSERT_TRUE(box) << i << ": the superellipsoid is inside the box";
        }
        if (!hit) {
            if (!box) continue;
            // Missed where the box is hit: within the rounded edges' reach of two faces.
            const dvec3 x = glm::abs(origin + box->t * dir);
            const int near_faces = (x.x > 1.0 - 2e-3) + (x.y > 1.0 - 2e-3) + (x.z > 1.0 - 2e-3);
            EXPECT_GE(near_faces, 2) << i << ": a miss away from the box's edges";
            continue;
        }
        EXPECT_NEAR(hit->t, box->t, 2e-3) << i;
        if (std::abs(hit->t - box->t) < 1e-9) {
            EXPECT_LT(glm::length(hit->normal - box->normal), 1e-5) << i;
        }
    }
    // Straight at a face's middle: the face, flat to rounding.
    const auto face = intersect(o, Ray{dvec3(0.2, -0.3, -5.0), dvec3(0.0, 0.0, 1.0)}, 0.0, kNoEnd);
    ASSERT_TRUE(face);
    EXPECT_NEAR(face->t, 4.0, 1e-12);
    EXPECT_LT(glm::length(face->normal - dvec3(0.0, 0.0, -1.0)), 1e-12);
}

// t is in units of the ray's direction, however long, and far away the hit keeps double's
// precision of the line (the search starts from the line's point nearest the centre).
TEST(Superellipsoid, DirectionLengthAndDistanceKeepTheRaysOwnParameter) {
    const Superellipsoid o{0.3, 1.7};
    const dvec3 dir = glm::normalize(dvec3(0.3, 0.1, 1.0));
    const Ray near{dvec3(0.1, 0.2, 0.0) - 3.0 * dir, dir};
    const auto a = intersect(o, near, 0.0, kNoEnd);
    ASSERT_TRUE(a);
    const auto b = intersect(o, Ray{near.origin, 7.0 * dir}, 0.0, kNoEnd);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->t * 7.0, a->t, 1e-12);
    const auto far = intersect(o, Ray{near.origin - 1e6 * dir, dir}, 0.0, kNoEnd);
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t - 1e6, a->t, 1e-9);
    // Within (t_min, t_max) only: past the entry, the exit; before the entry, nothing.
    const auto exit = intersect(o, near, a->t + 1e-6, kNoEnd);
    ASSERT_TRUE(exit);
    EXPECT_GT(exit->t, a->t + 0.1);
    EXPECT_FALSE(intersect(o, near, 0.0, a->t - 1e-9));
    // The whole line, as CSG asks: the entry.
    const auto line = intersect(o, near, -kNoEnd, kNoEnd);
    ASSERT_TRUE(line);
    EXPECT_NEAR(line->t, a->t, 1e-12);
}

// The reader: e and n, each in [0.001, 2] (the bad files test the messages); transforms place
// it; (u, v) are x and y across [-1.01, 1.01], as when it was an implicit surface in that box.
TEST(Superellipsoid, ReaderPlacementAndTexture) {
    const Scene scene = test::scene_from_text(R"(
        [camera]
        eye = [0, 0, -6]
        look_at = [0, 0, 0]
        [[object]]
        type = "superellipsoid"
        e = 0.25
        n = 0.5
        transform = { scale = 2, translate = [0, 0, 1] }
    )");
    const Object& object = scene.objects.at(0);
    const auto& s = std::get<Superellipsoid>(object.shape);
    EXPECT_EQ(s.e, 0.25);
    EXPECT_EQ(s.n, 0.5);
    ASSERT_TRUE(object.placement);
    const auto hit = intersect(object, Ray{dvec3(0.0, 0.0, -6.0), dvec3(0.0, 0.0, 1.0)}, 0.0, kNoEnd);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-12);  // the face at z = 1 - 2
    const glm::dvec2 uv = texture_uv(s, dvec3(1.0, -1.01, 0.3));
    EXPECT_NEAR(uv.x, 2.01 / 2.02, 1e-15);
    EXPECT_NEAR(uv.y, 0.0, 1e-15);
    EXPECT_THROW(test::scene_from_text("[camera]\neye = [0, 0, -6]\n[[object]]\ntype = \"superellipsoid\"\ne = 0\nn = 1\n"),
                 SceneError);
    EXPECT_THROW(test::scene_from_text("[camera]\neye = [0, 0, -6]\n[[object]]\ntype = \"superellipsoid\"\ne = 1\nn = 2.5\n"),
                 SceneError);
}

}  // namespace
}  // namespace superellipsoid_test
}  // namespace lancer::cpu
