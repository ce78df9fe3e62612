// The GPU's photon mapping against the CPU reference's: different code (a hashed grid built by
// a compute sort in float; a kd-tree in double), the same estimate. Both render the same small
// scene (a caustic, colour bleeding) with six seeds; region by region, the means over the seeds
// must agree within their confidence bounds, also with the ball a smooth glass mesh. And the GPU
// gives the same bytes run after run.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/load_scene.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

constexpr int kSeeds = 6;
constexpr int kRegionsX = 4, kRegionsY = 3;

Scene with_photon_settings(Scene scene, std::uint32_t seed) {
    scene.photons->seed = seed;
    scene.photons->passes = 4;
    scene.photons->count = 20000;
    return scene;
}

Scene small_scene(std::uint32_t seed) { return with_photon_settings(load_scene(test::source_path("tests/data/photons/small.toml")), seed); }

// The same scene with its glass ball as an icosphere mesh shaded smooth: photons bend along its
// vertex normals on both backends, as camera rays do.
Scene smooth_mesh_scene(std::uint32_t seed) {
    static const std::string dir = [] {
        std::string d = test::fresh_dir("photon-smooth-mesh");
        test::write_file(d + "/ball.obj", test::obj_text(test::icosphere(2, glm::dvec3(0.0, 0.7, 0.0), 0.6)));
        return d;
    }();
    std::string text = test::read_file(test::source_path("tests/data/photons/small.toml"));
    const std::string sphere = "type = \"sphere\"\ncenter = [0, 0.7, 0]\nradius = 0.6";
    text.replace(text.find(sphere), sphere.size(), "type = \"mesh\"\nfile = \"" + dir + "/ball.obj\"\nsmooth = true");
    return with_photon_settings(test::scene_from_text(text), seed);
}

// Per region, the mean of r + g + b over its pixels.
std::vector<double> region_means(const FloatImage& image) {
    std::vector<double> sums(kRegionsX * kRegionsY, 0.0), counts(sums.size(), 0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            int r = (y * kRegionsY / image.height) * kRegionsX + x * kRegionsX / image.width;
            const glm::vec4& p = image.at(x, y);
            sums[r] += double(p.r) + p.g + p.b;
            counts[r] += 1.0;
        }
    for (std::size_t r = 0; r < sums.size(); ++r) sums[r] /= counts[r];
    return sums;
}

void expect_regions_agree(Scene (*make_scene)(std::uint32_t)) {
    std::vector<std::vector<double>> gpu, cpu;
    for (int s = 0; s < kSeeds; ++s) {
        Scene scene = make_scene(std::uint32_t(s));
        gpu.push_back(region_means(test::gpu_renderer().render(scene, {})));
        cpu.push_back(region_means(CpuRenderer().render(scene, {})));
    }
    for (int r = 0; r < kRegionsX * kRegionsY; ++r) {
        auto stats = [&](const std::vector<std::vector<double>>& v, double& mean, double& var) {
            mean = 0.0;
            for (const auto& x : v) mean += x[r] / kSeeds;
            var = 0.0;
            for (const auto& x : v) var += (x[r] - mean) * (x[r] - mean) / (kSeeds - 1);
        };
        double mg, vg, mc, vc;
        stats(gpu, mg, vg);
        stats(cpu, mc, vc);
        // Four standard errors of the difference, and 1% for float against double.
        double bound = 4.0 * std::sqrt(vg / kSeeds + vc / kSeeds) + 0.01 * std::max(mg, mc);
        EXPECT_NEAR(mg, mc, bound) << "region " << r << ": gpu " << mg << " +- " << std::sqrt(vg) << ", cpu " << mc
                                   << " +- " << std::sqrt(vc);
    }
}

TEST(PhotonBackends, AgreeRegionByRegionWithinTheirConfidenceBounds) { expect_regions_agree(small_scene); }

TEST(PhotonBackends, AgreeThroughASmoothGlassMesh) { expect_regions_agree(smooth_mesh_scene); }

TEST(PhotonBackends, GpuGivesTheSameBytesRunAfterRun) {
    Scene scene = small_scene(3);
    FloatImage a = test::gpu_renderer().render(scene, {});
    FloatImage b = test::gpu_renderer().render(scene, {});
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec4)));
}

}  // namespace
}  // namespace lancer
