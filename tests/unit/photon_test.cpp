// The CPU reference's photon maps against optics worked out independently: the irradiance a
// point light of known power gives a plane (Phi cos theta / (4 pi r^2)), with the error
// shrinking as photons are added; the caustic a glass sphere focuses onto a plane, against the
// rays of geometric optics traced in closed form; and the kd-tree's gather against brute force.
#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "cpu/dielectric.hpp"
#include "cpu/photon_map.hpp"
#include "cpu/photon_tracer.hpp"
#include "cpu/tracer.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(KdTree, GathersExactlyThePhotonsABruteForceSearchFinds) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<cpu::Photon> photons;
    for (int i = 0; i < 5000; ++i)
        photons.push_back({{u(rng), u(rng) * 0.1, u(rng)}, glm::normalize(dvec3(u(rng), -1.0, u(rng))), dvec3(i + 1.0, 1.0, 0.5)});
    cpu::KdTree tree(photons);
    EXPECT_EQ(tree.size(), photons.size());
    for (int q = 0; q < 200; ++q) {
        dvec3 p(u(rng), u(rng) * 0.1, u(rng));
        dvec3 n = q % 2 ? dvec3(0.0, 1.0, 0.0) : dvec3(0.0, -1.0, 0.0);
        double r = 0.02 + 0.3 * (q % 7) / 7.0;
        dvec3 brute(0.0);
        for (const cpu::Photon& ph : photons)
            if (glm::length(ph.position - p) <= r && glm::dot(ph.direction, n) < 0.0) brute += ph.power;
        dvec3 got = tree.power_within(p, n, r);
        EXPECT_NEAR(got.r, brute.r, 1e-9 * std::max(1.0, brute.r)) << "query " << q;
        EXPECT_NEAR(got.g, brute.g, 1e-9 * std::max(1.0, brute.g));
    }
}

// A white floor under a point light of 100 W at height 2, photons straight from the light.
Scene floor_under_light(int photons) {
    return test::scene_from_text(R"(
        [camera]
        eye = [0, 5, -5]
        look_at = [0, 0, 0]
        [photons]
        count = )" + std::to_string(photons) + R"(
        [material.white]
        diffuse = 1
        [[object]]
        type = "plane"
        normal = [0, 1, 0]
        material = "white"
        [[light]]
        position = [0, 2, 0]
        power = 100
    )");
}

TEST(PhotonMap, IrradianceUnderAPointLightConvergesToTheInverseSquareLaw) {
    const double power = 100.0, height = 2.0, radius = 0.2;
    const double xs[] = {0.0, 0.5, 1.0, 1.5, 2.0, 3.0};
    double previous = INFINITY;
    for (int photons : {20000, 80000, 320000, 1280000}) {
        Scene scene = floor_under_light(photons);
        cpu::Tracer tracer(scene);
        cpu::StoredPhotons pass = cpu::shoot_photons(tracer, 0, 2, /*keep_direct=*/true);
        EXPECT_TRUE(pass.caustic.empty());
        EXPECT_TRUE(pass.global.empty());  // nothing to bounce back to the floor
        // Half the directions reach the floor, with all their power.
        dvec3 total(0.0);
        for (const cpu::Photon& p : pass.direct) total += p.power;
        EXPECT_NEAR(total.g, power / 2.0, 5.0 * power / 2.0 / std::sqrt(photons / 2.0));
        cpu::KdTree tree(pass.direct);
        double sum2 = 0.0;
        for (double x : xs) {
            double d2 = x * x + height * height;
            double expected = power * (height / std::sqrt(d2)) / (4.0 * kPi * d2);
            double estimate = tree.power_within({x, 0.0, 0.0}, {0.0, 1.0, 0.0}, radius).g / (kPi * radius * radius);
            double rel = (estimate - expected) / expected;
            sum2 += rel * rel;
        }
        double rms = std::sqrt(sum2 / std::size(xs));
        // Expected: about 1/sqrt(photons in the disc), plus under 1% of bias from the disc's size.
        EXPECT_LT(rms, previous) << photons << " photons";
        previous = rms;
        if (photons == 1280000) { EXPECT_LT(rms, 0.05); }
    }
}

TEST(PhotonMap, SameSeedSamePhotonsOnAnyNumberOfThreads) {
    Scene scene = floor_under_light(3000);
    cpu::Tracer tracer(scene);
    cpu::StoredPhotons a = cpu::shoot_photons(tracer, 2, 1, true), b = cpu::shoot_photons(tracer, 2, 5, true);
    ASSERT_EQ(a.direct.size(), b.direct.size());
    for (std::size_t i = 0; i < a.direct.size(); ++i) EXPECT_EQ(a.direct[i].position, b.direct[i].position);
    cpu::StoredPhotons c = cpu::shoot_photons(tracer, 3, 1, true);  // another pass: other photons
    EXPECT_NE(a.direct[0].position, c.direct[0].position);
}

// The ray from the light at (0, D) at angle theta from straight down through a glass ball of
// radius R at the origin, refracted in and out in closed form (2-D, the meridional plane):
// where it meets the floor y = -P, and the fraction of power it keeps (Fresnel twice).
struct Landing {
    bool hits = false;
    double x = 0.0, kept = 0.0;
};
Landing through_ball(double theta, double D, double R, double n, double P) {
    glm::dvec2 s(0.0, D), d(std::sin(theta), -std::cos(theta));
    double b = glm::dot(s, d), c = glm::dot(s, s) - R * R, disc = b * b - c;
    if (disc <= 0.0) return {};
    glm::dvec2 p1 = s + (-b - std::sqrt(disc)) * d;
    glm::dvec2 n1 = p1 / R;
    double cos_i = -glm::dot(d, n1);
    cpu::Fresnel f1 = cpu::fresnel(cos_i, 1.0, n);
    glm::dvec2 t = (1.0 / n) * d + ((1.0 / n) * cos_i - f1.cos_t) * n1;
    t = glm::normalize(t);
    glm::dvec2 p2 = p1 - 2.0 * glm::dot(p1, t) * t;
    glm::dvec2 n2 = p2 / R;  // outward; the ray meets it from inside
    double cos_i2 = glm::dot(t, n2);
    cpu::Fresnel f2 = cpu::fresnel(cos_i2, n, 1.0);
    if (f2.reflectance >= 1.0) return {};
    glm::dvec2 out = glm::normalize(n * t - (n * cos_i2 - f2.cos_t) * n2);  // the normal facing the ray is -n2
    if (out.y >= 0.0) return {};
    double u = (-P - p2.y) / out.y;
    return {true, p2.x + u * out.x, (1.0 - f1.reflectance) * (1.0 - f2.reflectance)};
}

TEST(PhotonMap, CausticUnderAGlassSphereIsWhereGeometricOpticsFocusesIt) {
    const double D = 20.0, R = 1.0, n = 1.5, P = 2.0, watts = 1000.0;
    const double theta_sphere = std::asin(R / D);
    const double outer = theta_sphere * 1.02;  // a hard-edged spot just covering the ball
    Scene scene = test::scene_from_text(R"(
        [camera]
        eye = [0, 5, -5]
        look_at = [0, 0, 0]
        [photons]
        count = 200000
        max_bounces = 4
        [material.glass]
        transmission = 1
        ior = 1.5
        [material.floor]
        diffuse = 1
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "glass"
        [[object]]
        type = "plane"
        point = [0, -2, 0]
        normal = [0, 1, 0]
        material = "floor"
        [[light]]
        type = "spot"
        position = [0, 20, 0]
        direction = [0, -1, 0]
        power = 1000
        inner_angle = )" + std::to_string(outer * 180.0 / kPi) + "\nouter_angle = " + std::to_string(outer * 180.0 / kPi) + "\n");
    cpu::Tracer tracer(scene);
    cpu::StoredPhotons pass = cpu::shoot_photons(tracer, 0, 2);

    // Geometric optics: rays uniform in solid angle (weight sin theta), each landing at radius
    // |x| with the power Fresnel lets through twice. Rays near the ball's rim leave almost
    // sideways and land far out; the caustic is the light that lands within W of the axis,
    // where nothing else arrives (light reflected off the ball lands beyond its radius).
    const double W = 0.6 * R;
    struct Ray1 {
        double r, power;
    };
    std::vector<Ray1> rays;
    const int steps = 400000;
    const double per_sr = watts / (2.0 * kPi * (1.0 - std::cos(outer)));
    double analytic_power = 0.0;
    for (int i = 0; i < steps; ++i) {
        double theta = theta_sphere * (i + 0.5) / steps;
        Landing l = through_ball(theta, D, R, n, P);
        if (!l.hits || std::abs(l.x) > W) continue;
        double w = per_sr * 2.0 * kPi * std::sin(theta) * (theta_sphere / steps) * l.kept;
        rays.push_back({std::abs(l.x), w});
        analytic_power += w;
    }
    auto quantile = [](std::vector<Ray1> v, double q) {
        std::sort(v.begin(), v.end(), [](const Ray1& a, const Ray1& b) { return a.r < b.r; });
        double total = 0.0;
        for (const Ray1& x : v) total += x.power;
        double acc = 0.0;
        for (const Ray1& x : v)
            if ((acc += x.power) >= q * total) return x.r;
        return v.back().r;
    };

    std::vector<Ray1> landed;
    dvec3 centroid(0.0);
    double photon_power = 0.0;
    for (const cpu::Photon& p : pass.caustic) {
        if (std::abs(p.position.y + P) > 1e-6) continue;
        double r = std::hypot(p.position.x, p.position.z);
        if (r > W) continue;
        landed.push_back({r, p.power.g});
        centroid += p.power.g * p.position;
        photon_power += p.power.g;
    }
    ASSERT_GT(landed.size(), 10000u);
    centroid /= photon_power;
    const double median = quantile(rays, 0.5), q90 = quantile(rays, 0.9);
    EXPECT_NEAR(centroid.x, 0.0, 0.02 * median);
    EXPECT_NEAR(centroid.z, 0.0, 0.02 * median);
    // The power that arrives (light bounced inside the ball adds a little), and how it spreads.
    EXPECT_NEAR(photon_power, analytic_power, 0.04 * analytic_power);
    EXPECT_NEAR(quantile(landed, 0.5), median, 0.03 * median);
    EXPECT_NEAR(quantile(landed, 0.9), q90, 0.03 * q90);
    // Focused: most of the light the ball lets through lands within a disc far smaller than it.
    EXPECT_LT(q90, 0.5 * R);
}

}  // namespace
}  // namespace lancer
