// The reference's lathe (host/cpu/shapes/lathe.cpp), read from TOML by its reader
// (host/scene/parse_lathe.cpp): linear lathes against the capped cylinder and cone they are,
// solved here in closed form; quadratic, cubic and Bezier lathes against a march of an inside
// test written here from POV-Ray's own power form of its splines (lathe.cpp's Compute_Lathe: the
// A, B, C, D of each piece), so that the reader's conversion to Bezier segments is checked too; a
// circle of Bezier arcs against the torus; rays level, along the axis and grazing; the reader's
// refusals at their line and column.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/lathe_crossing.hpp"
#include "support/test_support.hpp"

namespace lancer::cpu {
namespace lathe_test {  // its own names in the unity build
namespace {

constexpr double kFar = 1e30;
const dvec3 kLatheX(1, 0, 0), kLatheY(0, 1, 0);

const std::string kLatheHead = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"lathe\"\n";

struct LathePt {
    double r, y;
};

std::string lathe_points_toml(const std::vector<LathePt>& points) {
    std::string s = "points = [";
    for (std::size_t i = 0; i < points.size(); ++i) {
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, "%s[%.17g, %.17g]", i ? ", " : "", points[i].r, points[i].y);
        s += buffer;
    }
    return s + "]\n";
}

Lathe lathe_of(const std::string& spline, const std::vector<LathePt>& points) {
    const Scene s = test::scene_from_text(kLatheHead + "spline = \"" + spline + "\"\n" + lathe_points_toml(points));
    return std::get<Lathe>(s.objects.at(0).shape);
}

// ---- closed forms: the capped frustum between (r0, y0) and (r1, y1), y0 < y1 (a cylinder where
// r0 = r1), with its discs where their radii are above 0.

struct LatheCrossing {
    double t;
    dvec3 normal;
};

std::vector<LatheCrossing> frustum_crossings(double r0, double y0, double r1, double y1, const Ray& ray) {
    const dvec3 o = ray.origin, d = ray.dir;
    std::vector<LatheCrossing> out;
    // r = r0 + k (y - y0): x^2 + z^2 - (r0 + k (y - y0))^2 = A t^2 + B t + C.
    const double k = (r1 - r0) / (y1 - y0);
    const double e0 = r0 + k * (o.y - y0), e1 = k * d.y;
    const double A = d.x * d.x + d.z * d.z - e1 * e1;
    const double B = 2.0 * (o.x * d.x + o.z * d.z - e0 * e1);
    const double C = o.x * o.x + o.z * o.z - e0 * e0;
    std::vector<double> ts;
    if (A == 0.0) {
        if (B != 0.0) ts.push_back(-C / B);
    } else {
        const double disc = B * B - 4.0 * A * C;
        if (disc >= 0.0) {
            const double h = -0.5 * (B + std::copysign(std::sqrt(disc), B));
            if (h != 0.0) ts.push_back(C / h);
            ts.push_back(h / A);
        }
    }
    for (double t : ts) {
        const dvec3 p = o + t * d;
        if (!(p.y > y0 && p.y < y1)) continue;
        const double r = r0 + k * (p.y - y0);
        if (r < 0.0) continue;  // the cone's other nappe
        const double rho = std::hypot(p.x, p.z);
        out.push_back({t, glm::normalize(dvec3(p.x / rho, -k, p.z / rho))});
    }
    for (const auto& [y, r, ny] : {std::tuple{y0, r0, -1.0}, std::tuple{y1, r1, 1.0}}) {
        if (d.y == 0.0 || r <= 0.0) continue;
        const double t = (y - o.y) / d.y;
        const dvec3 p = o + t * d;
        if (p.x * p.x + p.z * p.z < r * r) out.push_back({t, dvec3(0, ny, 0)});
    }
    std::sort(out.begin(), out.end(), [](const LatheCrossing& a, const LatheCrossing& b) { return a.t < b.t; });
    return out;
}

// The closed linear lathe of that frustum: from the axis out along the base, up the side, in
// along the cap (or, reversed, the other way round).
Lathe frustum_lathe(double r0, double y0, double r1, double y1, bool reversed) {
    std::vector<LathePt> p{{0, y0}, {r0, y0}, {r1, y1}, {0, y1}};
    if (reversed) std::reverse(p.begin(), p.end());
    return lathe_of("linear", p);
}

// Random rays aimed at points in the frustum's box from around it (some level, some along the
// axis): every root and the nearest hit against the closed form; returns how many rays hit.
int expect_frustum_twin(double r0, double y0, double r1, double y1, int rays, unsigned seed) {
    const double R = std::max(r0, r1);
    int hits = 0;
    for (bool reversed : {false, true}) {
        const Lathe o = frustum_lathe(r0, y0, r1, y1, reversed);
        EXPECT_TRUE(o.closed);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::normal_distribution<double> normal;
        for (int i = 0; i < rays; ++i) {
            const dvec3 target(R * (2.0 * unit(rng) - 1.0), y0 + (y1 - y0) * unit(rng), R * (2.0 * unit(rng) - 1.0));
            dvec3 from = target + 4.0 * R * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
            if (i % 9 == 0) from.y = target.y;  // level
            if (i % 13 == 0) from = dvec3(0.0, y0 - 3.0, 0.0), from.x = from.z = 0.0;
            Ray ray{from, glm::normalize(target - from)};
            if (i % 13 == 0) ray.dir = kLatheY;  // up the axis
            const std::vector<LatheCrossing> expected = frustum_crossings(r0, y0, r1, y1, ray);
            const std::vector<double> roots = roots_on_line(o, ray);
            EXPECT_EQ(roots.size(), expected.size()) << i;
            if (roots.size() != expected.size()) continue;
            for (std::size_t j = 0; j < roots.size(); ++j) EXPECT_NEAR(roots[j], expected[j].t, 1e-9 * R) << i << " " << j;
            const auto h = intersect(o, ray, 0.0, kFar);
            auto ahead = std::find_if(expected.begin(), expected.end(), [](const LatheCrossing& c) { return c.t > 0.0; });
            EXPECT_EQ(bool(h), ahead != expected.end()) << i;
            if (!h || ahead == expected.end()) continue;
            ++hits;
            EXPECT_NEAR(h->t, ahead->t, 1e-9 * R) << i;
            EXPECT_NEAR(glm::length(h->normal - ahead->normal), 0.0, 1e-9) << i << " reversed " << reversed;
        }
    }
    return hits;
}

TEST(Lathe, LinearRectangleIsTheCappedCylinder) {
    EXPECT_GT(expect_frustum_twin(1.5, -1.0, 1.5, 2.0, 1500, 7), 2000);
    const Lathe o = frustum_lathe(1.5, -1.0, 1.5, 2.0, false);
    // Level rays: through the side, at a corner's height (the rim), from inside.
    auto h = intersect(o, {{-10, 0.3, 0}, kLatheX}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 8.5, 1e-12);
    EXPECT_NEAR(glm::length(h->normal + kLatheX), 0.0, 1e-12);
    h = intersect(o, {{0.2, 0.3, 0.1}, kLatheX}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, std::sqrt(1.5 * 1.5 - 0.01) - 0.2, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(dvec3(h->t + 0.2, 0, 0.1))), 0.0, 1e-12);
    EXPECT_TRUE(intersect(o, {{-10, 2.0, 0}, kLatheX}, 0.0, kFar));     // in the cap's plane: its rim
    EXPECT_FALSE(intersect(o, {{-10, 2.001, 0}, kLatheX}, 0.0, kFar));  // just above it
    // Up the axis: the base, then the cap.
    const std::vector<double> axis = roots_on_line(o, {{0, -5, 0}, kLatheY});
    ASSERT_EQ(axis.size(), 2u);
    EXPECT_NEAR(axis[0], 4.0, 1e-12);
    EXPECT_NEAR(axis[1], 7.0, 1e-12);
    // Grazing the side: a touching line is a hit there; just outside, nothing.
    auto touching = intersect(o, {{-10, 0.5, 1.5}, kLatheX}, 0.0, kFar);
    ASSERT_TRUE(touching);
    EXPECT_NEAR(touching->t, 10.0, 1e-6);
    for (double delta : {1e-3, 1e-6, 1e-9}) {
        const double z = 1.5 - delta;
        auto g = intersect(o, {{-10, 0.5, z}, kLatheX}, 0.0, kFar);
        ASSERT_TRUE(g) << delta;
        EXPECT_NEAR(g->t, 10.0 - std::sqrt(2.25 - z * z), 1e-7) << delta;
        EXPECT_FALSE(intersect(o, {{-10, 0.5, 1.5 + delta}, kLatheX}, 0.0, kFar)) << delta;
    }
    // Nearly level rays (the pairs of roots of F about the point nearest the axis).
    for (double slope : {1e-3, 1e-6, 1e-9, 1e-12}) {
        const Ray ray{{-10, 0.3, 0.4}, glm::normalize(dvec3(1, slope, 0))};
        const std::vector<LatheCrossing> expected = frustum_crossings(1.5, -1.0, 1.5, 2.0, ray);
        const std::vector<double> roots = roots_on_line(o, ray);
        ASSERT_EQ(roots.size(), 2u) << slope;
        EXPECT_NEAR(roots[0], expected[0].t, 1e-9) << slope;
        EXPECT_NEAR(roots[1], expected[1].t, 1e-9) << slope;
    }
    // Inside: between the discs and within the wall.
    EXPECT_TRUE(inside(o, {0.3, 0.5, -1.2}));
    EXPECT_FALSE(inside(o, {1.2, 0.5, -1.2}));
    EXPECT_FALSE(inside(o, {0.3, 2.1, 0.3}));
    EXPECT_FALSE(inside(o, {0.3, -1.1, 0.3}));
}

TEST(Lathe, LinearSlantIsTheCappedCone) {
    EXPECT_GT(expect_frustum_twin(1.2, -1.0, 0.4, 1.5, 1500, 11), 1500);
    EXPECT_GT(expect_frustum_twin(0.3, -0.5, 1.1, 0.5, 800, 12), 800);  // widening upward
    // A cone to its apex on the axis (no cap): the apex is one point.
    const Lathe o = lathe_of("linear", {{0, 0}, {1, 0}, {0, 2}});
    EXPECT_TRUE(o.closed);
    auto h = intersect(o, {{-5, 1, 0}, kLatheX}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(dvec3(-2, 1, 0))), 0.0, 1e-12);
    h = intersect(o, {{0, 5, 0}, -kLatheY}, 0.0, kFar);  // down the axis onto the apex
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.0, 1e-12);
}

// ---- POV-Ray's splines from its own power form, and an inside test and a march from it.

struct PovPiece {
    LathePt A, B, C, D;  // P(w) = ((A w + B) w + C) w + D, w in [0, 1]
    double r(double w) const { return ((A.r * w + B.r) * w + C.r) * w + D.r; }
    double y(double w) const { return ((A.y * w + B.y) * w + C.y) * w + D.y; }
};

// POV-Ray's lathe.cpp, Compute_Lathe.
std::vector<PovPiece> pov_pieces(const std::string& spline, const std::vector<LathePt>& P) {
    std::vector<PovPiece> out;
    auto lin = [](double a, const LathePt& p, double b, const LathePt& q, double c = 0, const LathePt& s = {0, 0},
                  double e = 0, const LathePt& u = {0, 0}) {
        return LathePt{a * p.r + b * q.r + c * s.r + e * u.r, a * p.y + b * q.y + c * s.y + e * u.y};
    };
    const std::size_t n = P.size();
    if (spline == "linear") {
        for (std::size_t i = 0; i + 1 < n; ++i) out.push_back({{0, 0}, {0, 0}, lin(-1, P[i], 1, P[i + 1]), P[i]});
    } else if (spline == "quadratic") {
        for (std::size_t i = 0; i + 2 < n; ++i)
            out.push_back({{0, 0}, lin(0.5, P[i], -1, P[i + 1], 0.5, P[i + 2]), lin(-0.5, P[i], 0.5, P[i + 2]), P[i + 1]});
    } else if (spline == "cubic") {
        for (std::size_t i = 0; i + 3 < n; ++i)
            out.push_back({lin(-0.5, P[i], 1.5, P[i + 1], -1.5, P[i + 2], 0.5, P[i + 3]),
                           lin(1, P[i], -2.5, P[i + 1], 2, P[i + 2], -0.5, P[i + 3]), lin(-0.5, P[i], 0.5, P[i + 2]), P[i + 1]});
    } else {
        for (std::size_t i = 0; i + 3 < n; i += 4)
            out.push_back({lin(-1, P[i], 3, P[i + 1], -3, P[i + 2], 1, P[i + 3]), lin(3, P[i], -6, P[i + 1], 3, P[i + 2]),
                           lin(-3, P[i], 3, P[i + 1]), P[i]});
    }
    return out;
}

// Even-odd, as POV-Ray's Inside: the pieces' crossings of the height p.y beyond the point's
// radius, found by sampling each piece's y(w) - p.y at 64 steps and bisecting each change.
struct PovLathe {
    std::vector<PovPiece> pieces;
    std::vector<std::pair<double, double>> heights;  // each piece's, from its samples, widened
};
PovLathe pov_lathe(const std::string& spline, const std::vector<LathePt>& points) {
    PovLathe o{pov_pieces(spline, points), {}};
    for (const PovPiece& g : o.pieces) {
        double lo = g.y(0.0), hi = lo;
        for (int k = 1; k <= 256; ++k) {
            lo = std::min(lo, g.y(k / 256.0));
            hi = std::max(hi, g.y(k / 256.0));
        }
        o.heights.push_back({lo - 1e-3, hi + 1e-3});
    }
    return o;
}

bool pov_inside(const PovLathe& lathe, const dvec3& p) {
    const double rho = std::hypot(p.x, p.z);
    int crossings = 0;
    for (std::size_t i = 0; i < lathe.pieces.size(); ++i) {
        const PovPiece& g = lathe.pieces[i];
        if (p.y < lathe.heights[i].first || p.y > lathe.heights[i].second) continue;
        constexpr int kSteps = 64;
        double w0 = 0.0, f0 = g.y(0.0) - p.y;
        for (int k = 1; k <= kSteps; ++k) {
            const double w1 = double(k) / kSteps, f1 = g.y(w1) - p.y;
            if ((f0 > 0.0) != (f1 > 0.0)) {
                double a = w0, b = w1;
                for (int j = 0; j < 50; ++j) {
                    const double m = 0.5 * (a + b);
                    if (((g.y(m) - p.y) > 0.0) == (f0 > 0.0)) a = m; else b = m;
                }
                if (g.r(0.5 * (a + b)) > rho) ++crossings;
            }
            w0 = w1;
            f0 = f1;
        }
    }
    return crossings & 1;
}

// The points along the ray where pov_inside changes, over [t0, t1] in `steps` samples, bisected.
std::vector<double> pov_march(const PovLathe& pieces, const Ray& ray, double t0, double t1, int steps) {
    std::vector<double> out;
    bool before = pov_inside(pieces, ray.origin + t0 * ray.dir);
    double ta = t0;
    for (int k = 1; k <= steps; ++k) {
        const double tb = t0 + (t1 - t0) * k / steps;
        const bool now = pov_inside(pieces, ray.origin + tb * ray.dir);
        if (now != before) {
            double a = ta, b = tb;
            for (int j = 0; j < 60; ++j) {
                const double m = 0.5 * (a + b);
                if (pov_inside(pieces, ray.origin + m * ray.dir) == before) a = m; else b = m;
            }
            out.push_back(0.5 * (a + b));
        }
        before = now;
        ta = tb;
    }
    return out;
}

// A vase, an egg cup and a bottle: closed curves with walls well thicker than the march's step.
struct LatheCase {
    const char* spline;
    std::vector<LathePt> points;
};
const LatheCase kLatheCases[] = {
    // a vase from the axis up the outside, over a thick lip, down the inside to the axis
    {"cubic", {{0, -0.2}, {0, 0}, {0.8, 0.1}, {1.0, 0.7}, {0.6, 1.4}, {0.7, 1.9}, {0.4, 1.9}, {0.3, 1.4}, {0.6, 0.7},
               {0.3, 0.3}, {0, 0.3}, {-0.2, 0.3}}},
    // an egg cup: a quadratic spline closed on itself (its first point a control point)
    {"quadratic", {{0.5, -0.2}, {0.3, 0.0}, {0.9, 0.2}, {1.0, 0.9}, {0.7, 1.3}, {0.5, 0.8}, {0.3, 0.0}}},
    // a bottle of Bezier pieces, closed on the axis
    {"bezier", {{0, 0}, {0.4, 0}, {0.8, 0}, {0.8, 0.3},
                {0.8, 0.3}, {0.8, 1.0}, {0.9, 1.2}, {0.4, 1.5},
                {0.4, 1.5}, {0.2, 1.6}, {0.3, 2.0}, {0.25, 2.2},
                {0.25, 2.2}, {0.1, 2.25}, {0.05, 2.2}, {0, 2.2}}},
};

TEST(Lathe, SplinesAgreeWithAMarchOfPovRaysInsideForAimedRandomRays) {
    int crossings = 0, level = 0;
    for (const LatheCase& c : kLatheCases) {
        const Lathe o = lathe_of(c.spline, c.points);
        ASSERT_TRUE(o.closed) << c.spline;
        const PovLathe pov = pov_lathe(c.spline, c.points);
        const std::vector<PovPiece>& pieces = pov.pieces;
        ASSERT_EQ(pieces.size(), o.segments.size());
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::normal_distribution<double> normal;
        for (int i = 0; i < 350; ++i) {
            const dvec3 target(o.r_max * (2.0 * unit(rng) - 1.0), o.y_lo + (o.y_hi - o.y_lo) * unit(rng),
                               o.r_max * (2.0 * unit(rng) - 1.0));
            dvec3 from = target + 3.0 * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
            if (i % 6 == 0) {
                from.y = target.y;  // level
                ++level;
            }
            const Ray ray{from, (0.3 + 2.0 * unit(rng)) * glm::normalize(target - from)};
            const double scale = glm::length(ray.dir);
            const double span = 8.0 / scale;
            const std::vector<double> roots = roots_on_line(o, ray);
            std::vector<double> marched = pov_march(pov, ray, -span, span, 4000);
            ASSERT_EQ(roots.size(), marched.size()) << c.spline << " " << i;
            crossings += int(roots.size());
            for (std::size_t j = 0; j < roots.size(); ++j) {
                EXPECT_NEAR(roots[j], marched[j], 1e-9 / scale) << c.spline << " " << i << " " << j;
                if (j + 1 < roots.size()) {
                    const dvec3 mid = ray.origin + 0.5 * (roots[j] + roots[j + 1]) * ray.dir;
                    EXPECT_EQ(inside(o, mid), j % 2 == 0) << c.spline << " " << i << " " << j;
                }
            }
            // The nearest hit ahead is the first root ahead; its normal points out of the inside.
            const auto ahead = std::upper_bound(roots.begin(), roots.end(), 0.0);
            const auto h = intersect(o, ray, 0.0, kFar);
            ASSERT_EQ(bool(h), ahead != roots.end()) << c.spline << " " << i;
            if (!h) continue;
            EXPECT_NEAR(h->t, *ahead, 1e-12 * (1.0 + std::abs(*ahead))) << c.spline << " " << i;
            const dvec3 p = ray.origin + h->t * ray.dir;
            EXPECT_FALSE(pov_inside(pov, p + 1e-6 * h->normal)) << c.spline << " " << i;
            EXPECT_TRUE(pov_inside(pov, p - 1e-6 * h->normal)) << c.spline << " " << i;
            // uv = (segment, s): the point on that piece at s is the hit's.
            const PovPiece& g = pieces.at(std::size_t(h->uv.x));
            EXPECT_NEAR(g.r(h->uv.y), std::hypot(p.x, p.z), 1e-9) << c.spline << " " << i;
            EXPECT_NEAR(g.y(h->uv.y), p.y, 1e-9) << c.spline << " " << i;
        }
    }
    EXPECT_GT(crossings, 1500);
    EXPECT_GT(level, 150);
}

// ---- a circle of four Bezier arcs about (R, 0): the torus, to the arcs' own error.

TEST(Lathe, BezierCircleIsTheTorusWithinTheArcsError) {
    const double R = 1.0, a = 0.4, k = 0.5522847498 * a;  // the arcs stray from the circle by 2.7e-4 of a
    const std::vector<LathePt> p{{R + a, 0},     {R + a, k},     {R + k, a},     {R, a},      // counterclockwise
                                 {R, a},         {R - k, a},     {R - a, k},     {R - a, 0},
                                 {R - a, 0},     {R - a, -k},    {R - k, -a},    {R, -a},
                                 {R, -a},        {R + k, -a},    {R + a, -k},    {R + a, 0}};
    const Lathe o = lathe_of("bezier", p);
    ASSERT_TRUE(o.closed);
    Torus torus;
    torus.major_radius = R;
    torus.minor_radius = a;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int compared = 0;
    for (int i = 0; i < 3000; ++i) {
        const dvec3 target((R + a) * (2.0 * unit(rng) - 1.0), a * (2.0 * unit(rng) - 1.0), (R + a) * (2.0 * unit(rng) - 1.0));
        const dvec3 from = target + 4.0 * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        const Ray ray{from, glm::normalize(target - from)};
        const auto t = intersect(torus, ray, 0.0, kFar);
        const auto l = intersect(o, ray, 0.0, kFar);
        // Away from grazing (where 2.7e-4 of a decides hit or miss), hit for hit.
        if (t && std::abs(glm::dot(t->normal, ray.dir)) < 0.1) continue;
        if (!t) {
            // A miss of the torus by more than the arcs' error is a miss of the lathe.
            const auto wider = [&] {
                Torus w = torus;
                w.minor_radius = a * 1.001;
                return intersect(w, ray, 0.0, kFar);
            }();
            if (!wider) {
                EXPECT_FALSE(l) << i;
            }
            continue;
        }
        ASSERT_TRUE(l) << i;
        ++compared;
        EXPECT_NEAR(l->t, t->t, 3e-4 * a / std::abs(glm::dot(t->normal, ray.dir))) << i;
        EXPECT_NEAR(glm::length(l->normal - t->normal), 0.0, 3e-3) << i;
        EXPECT_EQ(inside(o, ray.origin + (l->t + 1e-3) * ray.dir), true) << i;
    }
    EXPECT_GT(compared, 1000);
}

// ---- the reader: POV-Ray's splines, which points the curve passes through, closed or open.

TEST(LatheReader, SplinesPassThroughPovRaysPoints) {
    // Cubic: through points 1 .. n - 2, with POV-Ray's tangents; quadratic: through 1 .. n - 1.
    for (const LatheCase& c : kLatheCases) {
        const Lathe o = lathe_of(c.spline, c.points);
        const std::vector<PovPiece> pieces = pov_pieces(c.spline, c.points);
        for (std::size_t k = 0; k < o.segments.size(); ++k)
            for (double w : {0.0, 0.25, 0.5, 0.9, 1.0}) {
                // The Bezier segment at w against POV-Ray's piece at w (de Casteljau here).
                std::array<double, 4> r = o.segments[k].r, y = o.segments[k].y;
                for (int level = o.degree; level > 0; --level)
                    for (int i = 0; i < level; ++i) {
                        r[i] = (1 - w) * r[i] + w * r[i + 1];
                        y[i] = (1 - w) * y[i] + w * y[i + 1];
                    }
                EXPECT_NEAR(r[0], pieces[k].r(w), 1e-14) << c.spline << " " << k << " " << w;
                EXPECT_NEAR(y[0], pieces[k].y(w), 1e-14) << c.spline << " " << k << " " << w;
            }
    }
    EXPECT_EQ(lathe_of("linear", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}).segments.size(), 3u);
    EXPECT_EQ(lathe_of("quadratic", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}).segments.size(), 2u);
    EXPECT_EQ(lathe_of("cubic", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}).segments.size(), 1u);
    // Open where the curve neither closes on itself nor ends on the axis at both ends.
    EXPECT_FALSE(lathe_of("linear", {{0, 0}, {1, 0}, {1, 1}}).closed);
    EXPECT_TRUE(lathe_of("linear", {{0.5, 0}, {1, 0}, {1, 1}, {0.5, 0}}).closed);
    EXPECT_FALSE(inside(lathe_of("linear", {{0, 0}, {1, 0}, {1, 1}}), {0.5, 0.5, 0}));
    // An open lathe is a surface: hit from both sides.
    const Lathe open = lathe_of("linear", {{1, 0}, {1, 1}});
    EXPECT_TRUE(intersect(open, {{0, 0.5, 0}, kLatheX}, 0.0, kFar));
    EXPECT_TRUE(intersect(open, {{-5, 0.5, 0}, kLatheX}, 0.0, kFar));
}

void expect_lathe_refused(const std::string& body, const std::string& message) {
    try {
        test::scene_from_text(kLatheHead + body);
        ADD_FAILURE() << "accepted: " << body;
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
}

TEST(LatheReader, RefusesWhatPovRayRefusesAndCurvesBelowTheAxis) {
    expect_lathe_refused("points = [[1, 0]]\n", "a lathe with a linear spline needs at least 2 points, not 1");
    expect_lathe_refused("spline = \"quadratic\"\npoints = [[1, 0], [1, 1]]\n", "needs at least 3 points, not 2");
    expect_lathe_refused("spline = \"cubic\"\npoints = [[0, 0], [1, 0], [1, 1]]\n", "needs at least 4 points, not 3");
    expect_lathe_refused("spline = \"bezier\"\npoints = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 2]]\n", "4 points per segment, not 5");
    expect_lathe_refused("spline = \"spiral\"\npoints = [[0, 0], [1, 0]]\n", "spiral");
    expect_lathe_refused("points = [[0, 0], [-1, 0.5], [0, 1]]\n", "points[1]: a radius must not be negative, not -1");
    // Cubic: the end points are only tangents, and may be negative; the curve may not.
    EXPECT_NO_THROW(test::scene_from_text(kLatheHead + "spline = \"cubic\"\npoints = [[-0.5, 0], [0, 0], [1, 0.5], [0, 1], [-0.5, 1]]\n"));
    expect_lathe_refused("spline = \"cubic\"\npoints = [[3, -1], [0, 0], [0.05, 1], [0, 2], [0, 3]]\n", "dips below the axis");
    expect_lathe_refused("spline = \"bezier\"\npoints = [[0, 0], [-1, 0.3], [-1, 0.6], [0, 1]]\n", "dips below the axis");
    expect_lathe_refused("points = [[0, 0], [0, 1]]\n", "every radius is 0");
    expect_lathe_refused("points = [[0, 0], [1, 0], [1, 0], [0, 0]]\n", "encloses no area");
}

// A curve that meets itself is refused (its one side would face inward on a loop turning the
// other way); one that comes close is not: the exact test for linear splines, refinement for
// curved ones (pieces under 1e-9 of the curve's size taken to meet).
TEST(LatheReader, RefusesACurveThatMeetsItselfNotOneThatComesClose) {
    // Linear: a notch whose tip comes within 1e-12 of the base, then onto it.
    EXPECT_NO_THROW(test::scene_from_text(kLatheHead + "points = [[0, 0], [1, 0], [1, 1], [0.5, 1e-12], [0, 1], [0, 0]]\n"));
    expect_lathe_refused("points = [[0, 0], [1, 0], [1, 1], [0.5, 0], [0, 1], [0, 0]]\n",
                         "points[2]: the lathe's curve crosses itself (segment 0 meets segment 2");
    expect_lathe_refused("points = [[0.2, 0], [1.2, 1.5], [0.2, 1.5], [1.0, 0], [0.2, 0]]\n", "(segment 0 meets segment 2");
    // Linear: turning back along itself.
    expect_lathe_refused("points = [[1, 0], [1, 1], [1, 0.5]]\n", "(segment 0 meets segment 1");
    // Bezier: two arcs, the first out to r = 1.75 at y = 0.5, the third in to 1.75 + gap there.
    auto arcs = [](double gap) {
        return fmt::format("spline = \"bezier\"\npoints = [[1, 0], [2, 0.25], [2, 0.75], [1, 1], [1, 1], [1, 1], [1, 1], "
                           "[{0:.17g}, 1], [{0:.17g}, 1], [{1:.17g}, 0.75], [{1:.17g}, 0.25], [{0:.17g}, 0]]\n",
                           2.5 + gap, 1.5 + gap);
    };
    EXPECT_NO_THROW(test::scene_from_text(kLatheHead + arcs(1e-6)));
    expect_lathe_refused(arcs(-1e-3), "(segment 0 meets segment 2");
    expect_lathe_refused(arcs(0.0), "(segment 0 meets segment 2");  // touching
    // Cubic: the third piece back across the first.
    expect_lathe_refused("spline = \"cubic\"\npoints = [[1, -1], [1, 0], [3, 1], [0.5, 1], [2, 0], [2, -1]]\n",
                         "(segment 0 meets segment 2");
    // A curve closed on itself, and one closed on the axis, are not crossings.
    EXPECT_NO_THROW(lathe_of("linear", {{0.5, 0}, {1, 0}, {1, 1}, {0.5, 0}}));
    EXPECT_NO_THROW(lathe_of("bezier", {{1, 0}, {2, 0.3}, {2, 0.7}, {1, 1}, {1, 1}, {0.5, 0.7}, {0.5, 0.3}, {1, 0}}));
    for (const LatheCase& c : kLatheCases) EXPECT_NO_THROW(lathe_of(c.spline, c.points)) << c.spline;
}

// The test is O(n log n) for a linear spline: 10^5 points of a circle, and a sawtooth of
// 10^5 long thin teeth (whose boxes all overlap), each well under a second.
TEST(LatheReader, CrossingTestFindsTheOneCrossingOfALargeLathe) {
    const int n = 100000;
    std::vector<LathePt> circle, teeth;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        circle.push_back({2.0 + std::cos(a), std::sin(a)});
        teeth.push_back({1.0 + double(i) / n + (i % 2 ? 1.0 : 0.0), i % 2 ? 1.0 : 0.0});
    }
    circle.push_back(circle.front());
    EXPECT_FALSE(find_lathe_crossing(lathe_of("linear", circle)));
    EXPECT_FALSE(find_lathe_crossing(lathe_of("linear", teeth)));
    // One tooth bent back across the one before it, in the middle of the 10^5.
    teeth[n / 2 + 1].r = teeth[n / 2 - 2].r - 1e-3;
    EXPECT_THROW(lathe_of("linear", teeth), UserError);  // the reader refuses it
}

// A curved lathe whose pieces' boxes all overlap one another is refused up front, never checked
// pair by pair for minutes.
TEST(LatheReader, CurvedLatheTooCrowdedToCheckIsRefused) {
    std::vector<LathePt> teeth;
    for (int i = 0; i < 20000; ++i) teeth.push_back({1.0 + i * 1e-5 + (i % 2 ? 1.0 : 0.0), i % 2 ? 1.0 : 0.0});
    try {
        lathe_of("cubic", teeth);
        FAIL() << "a crowded cubic lathe was accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("pairs of the curve's pieces overlap"), std::string::npos) << e.what();
    }
}

// Texture (u, v): the angle about y from +x toward +z, and POV-Ray's v, (segment + s) / count,
// from the hit's (segment, s).
TEST(Lathe, TextureIsTheAngleAndPovRaysV) {
    const Lathe o = lathe_of("linear", {{0, 0}, {1, 0}, {1, 2}, {0, 2}});
    const auto h = intersect(o, {{0, 0.5, -5}, {0, 0, 1}}, 0.0, kFar);  // the side at y = 0.5, from -z
    ASSERT_TRUE(h);
    EXPECT_EQ(h->uv.x, 1.0);
    EXPECT_NEAR(h->uv.y, 0.25, 1e-12);
    const glm::dvec2 uv = texture_uv(o, dvec3(0, 0.5, -1), h->uv);
    EXPECT_NEAR(uv.x, 0.75, 1e-12);  // -z: three quarters of the way round from +x toward +z
    EXPECT_NEAR(uv.y, (1.0 + 0.25) / 3.0, 1e-12);
    EXPECT_NEAR(texture_uv(o, dvec3(0, 0.5, 1), h->uv).x, 0.25, 1e-12);
    EXPECT_NEAR(texture_uv(o, dvec3(1, 0.5, 0), h->uv).x, 0.0, 1e-12);
}

}  // namespace
}  // namespace lathe_test
}  // namespace lancer::cpu
