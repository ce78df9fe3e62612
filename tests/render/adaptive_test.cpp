// Adaptive anti-aliasing: one ray per pixel, the full N x N grid (or finer grids in steps) where
// a pixel differs from a neighbour, or its samples among themselves, by more than the threshold. A refined pixel is exactly that pixel of a
// full render and an unrefined one exactly that pixel of a one-sample render, so both are checked
// bit for bit; which pixels are refined is checked against the scene's geometry, found with the
// reference tracer's own ray queries.
#include <cstring>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/tracer.hpp"
#include "image/adaptive.hpp"
#include "image/diff.hpp"
#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

class Adaptive : public ::testing::TestWithParam<test::Backend> {};

bool same_rgb(const glm::vec4& a, const glm::vec4& b) { return std::memcmp(&a, &b, 3 * sizeof(float)) == 0; }

Scene seed(int samples, std::optional<double> threshold) {
    Scene scene = test::shipped_scene("seed", 96, 54, samples);
    scene.render.aa_threshold = threshold;
    return scene;
}

TEST_P(Adaptive, ZeroThresholdIsTheFullGridBitForBit) {
    const FloatImage full = test::render_on(GetParam(), seed(3, std::nullopt));
    const FloatImage adaptive = test::render_on(GetParam(), seed(3, 0.0));
    ASSERT_EQ(adaptive.pixels.size(), full.pixels.size());
    EXPECT_EQ(adaptive.refined_pixels, static_cast<long long>(full.pixels.size()));
    EXPECT_EQ(full.refined_pixels, -1);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < full.pixels.size(); ++i) differing += !same_rgb(adaptive.pixels[i], full.pixels[i]);
    EXPECT_EQ(differing, 0u);
    // The rays counted: each pixel's first ray and everything its grid traced.
    const FloatImage one = test::render_on(GetParam(), seed(1, std::nullopt));
    for (std::size_t i = 0; i < full.pixels.size(); ++i)
        ASSERT_EQ(adaptive.pixels[i].a, one.pixels[i].a + full.pixels[i].a) << "pixel " << i;
}

// Unrefined pixels are the one-sample render's (one camera ray: sky pixels count exactly 1 ray),
// refined ones the full grid's; at POV-Ray's default 0.3 the open sky at the top is not refined.
TEST_P(Adaptive, FlatRegionsGetOneRayAndRefinedPixelsTheGrid) {
    const FloatImage full = test::render_on(GetParam(), seed(3, std::nullopt));
    const FloatImage one = test::render_on(GetParam(), seed(1, std::nullopt));
    const FloatImage adaptive = test::render_on(GetParam(), seed(3, 0.3));
    const std::vector<std::uint32_t> refined = pixels_to_refine(one, 0.3);
    ASSERT_EQ(adaptive.refined_pixels, static_cast<long long>(refined.size()));
    ASSERT_GT(refined.size(), 0u);
    ASSERT_LT(refined.size(), full.pixels.size() / 2);
    std::vector<char> is_refined(full.pixels.size(), 0);
    for (std::uint32_t p : refined) is_refined[p] = 1;
    for (std::size_t i = 0; i < full.pixels.size(); ++i) {
        if (is_refined[i]) {
            ASSERT_TRUE(same_rgb(adaptive.pixels[i], full.pixels[i])) << "refined pixel " << i;
            ASSERT_EQ(adaptive.pixels[i].a, one.pixels[i].a + full.pixels[i].a) << "refined pixel " << i;
        } else {
            ASSERT_EQ(std::memcmp(&adaptive.pixels[i], &one.pixels[i], sizeof(glm::vec4)), 0) << "pixel " << i;
        }
    }
    const int w = adaptive.width;
    for (int y = 0; y < 6; ++y)  // sky: nothing in the top rows
        for (int x = 0; x < w; ++x) {
            EXPECT_FALSE(is_refined[std::size_t(y) * w + x]) << x << "," << y;
            EXPECT_EQ(adaptive.at(x, y).a, 1.0f) << x << "," << y;
        }
    double camera_rays = double(full.pixels.size()) + double(refined.size()) * 9.0;
    EXPECT_LT(camera_rays / double(full.pixels.size()), 5.0);
}

// What the centre of a pixel sees, as far as edges go: the object, its pigment (checker cells)
// and which point lights the object itself hides from it (cast shadows).
using Look = std::tuple<const Object*, glm::dvec3, std::vector<bool>>;

Look look_through(const Scene& scene, const cpu::Tracer& tracer, const CameraBasis& cam, int x, int y) {
    const RenderSettings& rs = scene.render;
    const glm::dvec3 dir = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, rs.width, rs.height));
    cpu::Hit hit;
    if (!tracer.closest_hit({cam.eye, dir}, 0.0, 1e30, hit)) return {nullptr, glm::dvec3(0.0), {}};
    const glm::dvec3 p = cam.eye + hit.t * dir;
    glm::dvec3 n = hit.normal;
    if (glm::dot(n, dir) > 0.0) n = -n;
    const Material& m = scene.materials[hit.object->material];
    std::vector<bool> lit;
    for (const Light& light : scene.lights) {
        const glm::dvec3 to_light = light.position - p;
        const double d = glm::length(to_light);
        // Cast shadows only: at a terminator (N.L = 0) the shading fades smoothly to nothing.
        lit.push_back(glm::dot(to_light, n) <= 0.0 || !tracer.occluded({p + 1e-6 * n, to_light / d}, 0.0, d));
    }
    return {hit.object, cpu::pigment_at(m, p), lit};
}

// Every pair of neighbouring pixels whose centres see different objects (silhouettes), different
// checker cells (pigments) or a different set of lights (shadow edges) is refined, both pixels.
TEST_P(Adaptive, EveryPixelOnAnEdgeOfSeedIsRefined) {
    // At POV-Ray's default 0.3 some true edges of seed are below the threshold and stay one ray:
    // the far edge of the floor against the sky differs by 0.24, a mirror's outline against the
    // sky it reflects by less. A threshold of 0.1 must find every edge but the mirror's.
    const double threshold = 0.05;
    const Scene scene = seed(3, threshold);
    const FloatImage one = test::render_on(GetParam(), seed(1, std::nullopt));
    std::vector<char> is_refined(one.pixels.size(), 0);
    for (std::uint32_t p : pixels_to_refine(one, threshold)) is_refined[p] = 1;
    const FloatImage adaptive = test::render_on(GetParam(), scene);
    ASSERT_EQ(adaptive.refined_pixels, static_cast<long long>(std::count(is_refined.begin(), is_refined.end(), 1)));
    // and it still leaves most of the picture (sky, the inside of checker cells) at one ray.
    EXPECT_LT(adaptive.refined_pixels, static_cast<long long>(one.pixels.size() / 2));

    const cpu::Tracer tracer(scene);
    const CameraBasis cam = make_camera_basis(scene.camera, scene.render.width, scene.render.height);
    const int w = scene.render.width, h = scene.render.height;
    std::vector<Look> looks;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) looks.push_back(look_through(scene, tracer, cam, x, y));
    int silhouettes = 0, pigments = 0, shadows = 0;
    auto check = [&](std::size_t a, std::size_t b) {
        const Look& la = looks[a];
        const Look& lb = looks[b];
        if (la == lb) return;
        // A mirror shows what it reflects, not its own pigment and shadows; its outline against the
        // sky it reflects differs by 0.1 at most, no edge to the eye either.
        auto mirror = [&](const Object* o) { return o && scene.materials[o->material].reflection > 0.5; };
        if (mirror(std::get<0>(la)) || mirror(std::get<0>(lb))) return;
        silhouettes += std::get<0>(la) != std::get<0>(lb);
        pigments += std::get<0>(la) == std::get<0>(lb) && std::get<1>(la) != std::get<1>(lb);
        shadows += std::get<0>(la) == std::get<0>(lb) && std::get<2>(la) != std::get<2>(lb);
        EXPECT_TRUE(is_refined[a] && is_refined[b])
            << "edge between pixels " << a % w << "," << a / w << " and " << b % w << "," << b / w << ": objects "
            << (std::get<0>(la) ? std::get<0>(la) - scene.objects.data() : -1) << " "
            << (std::get<0>(lb) ? std::get<0>(lb) - scene.objects.data() : -1) << ", pigment " << std::get<1>(la).x
            << " " << std::get<1>(lb).x << ", colour difference " << color_difference(one.pixels[a], one.pixels[b]);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (x + 1 < w) check(i, i + 1);
            if (y + 1 < h) check(i, i + w);
        }
    // The scene has all three kinds of edge, so the test looked at each.
    EXPECT_GT(silhouettes, 50);
    EXPECT_GT(pigments, 50);
    EXPECT_GT(shadows, 10);
}

// At the threshold that finds every edge of seed (above) the picture is the full grid's by the
// image tests' metric. At POV-Ray's default 0.3 it is not (46.9 dB, but 0.95% of the pixels of
// this 96x54 render off by more than 4/255, beyond the metric's 0.1%: low-contrast edges left at
// one ray; docs/rendering.md, "Adaptive anti-aliasing"), so only its PSNR is held here.
TEST_P(Adaptive, EdgeThresholdLooksLikeTheFullGrid) {
    const Rgb8Image full = to_srgb8(test::render_on(GetParam(), seed(3, std::nullopt)));
    const Rgb8Image adaptive = to_srgb8(test::render_on(GetParam(), seed(3, 0.05)));
    test::expect_same_picture(std::string("adaptive_") + test::backend_name(GetParam()), adaptive, full);
    const ImageDiff at_default = compare_images(to_srgb8(test::render_on(GetParam(), seed(3, 0.3))), full, 4);
    EXPECT_GT(at_default.psnr_db, 40.0);
}

Scene deeper(int depth, AaMethod method, double threshold) {
    Scene scene = seed(3, threshold);
    scene.render.aa_depth = depth;
    scene.render.aa_method = method;
    return scene;
}

// Refining in steps (1, then 2 x 2, then 3 x 3) still ends on the full grid at T = 0, in either
// method, every pixel having traced all three.
TEST_P(Adaptive, ZeroThresholdInStepsIsTheFullGridBitForBit) {
    const FloatImage full = test::render_on(GetParam(), seed(3, std::nullopt));
    const FloatImage two = test::render_on(GetParam(), seed(2, std::nullopt));
    const FloatImage one = test::render_on(GetParam(), seed(1, std::nullopt));
    for (AaMethod method : {AaMethod::Neighbours, AaMethod::Spread}) {
        const FloatImage adaptive = test::render_on(GetParam(), deeper(2, method, 0.0));
        const auto pixels = static_cast<long long>(full.pixels.size());
        EXPECT_EQ(adaptive.refined_pixels, pixels);
        EXPECT_EQ(adaptive.camera_rays, pixels * (1 + 4 + 9));
        for (std::size_t i = 0; i < full.pixels.size(); ++i) {
            ASSERT_TRUE(same_rgb(adaptive.pixels[i], full.pixels[i])) << "pixel " << i;
            ASSERT_EQ(adaptive.pixels[i].a, one.pixels[i].a + two.pixels[i].a + full.pixels[i].a) << "pixel " << i;
        }
    }
}

// The sRGB channel-wise spread of the 2 x 2 grid's samples of each pixel: the samples of pixel
// (x, y) are the pixel centres (2x + i, 2y + j) of a one-ray render twice the size.
std::vector<double> spread_of_two_by_two(const FloatImage& doubled) {
    const int w = doubled.width / 2, h = doubled.height / 2;
    std::vector<double> spread(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const glm::vec3 c(doubled.at(2 * x + i, 2 * y + j));
                    lo = glm::min(lo, c);
                    hi = glm::max(hi, c);
                }
            spread[std::size_t(y) * w + x] = sample_spread(lo, hi);
        }
    return spread;
}

// In steps at POV-Ray's 0.3: each pixel is exactly the one-ray, the 2 x 2 or the 3 x 3 render's
// pixel (its ray count says which), and it went on exactly when the rule says: after the first
// ray by its neighbours; after the 2 x 2 grid by its neighbours in the picture as it then was
// and, in the spread method, also by its own samples' spread.
TEST_P(Adaptive, EachStepRefinesThePixelsItsRuleChooses) {
    const double threshold = 0.3;
    const FloatImage full = test::render_on(GetParam(), seed(3, std::nullopt));
    const FloatImage two = test::render_on(GetParam(), seed(2, std::nullopt));
    const FloatImage one = test::render_on(GetParam(), seed(1, std::nullopt));
    Scene twice = seed(1, std::nullopt);
    twice.render.width *= 2;
    twice.render.height *= 2;
    const std::vector<double> spread = spread_of_two_by_two(test::render_on(GetParam(), twice));

    const std::vector<std::uint32_t> first = pixels_to_refine(one, threshold);
    std::vector<char> after_first(one.pixels.size(), 0);
    FloatImage between = one;  // the picture after the 2 x 2 step, before the last
    for (std::uint32_t p : first) {
        after_first[p] = 1;
        between.pixels[p] = two.pixels[p];
    }
    std::vector<char> by_neighbours(one.pixels.size(), 0);
    for (std::uint32_t p : pixels_to_refine(between, threshold, after_first)) by_neighbours[p] = 1;

    for (AaMethod method : {AaMethod::Neighbours, AaMethod::Spread}) {
        SCOPED_TRACE(method == AaMethod::Spread ? "spread" : "neighbours");
        const FloatImage adaptive = test::render_on(GetParam(), deeper(2, method, threshold));
        ASSERT_EQ(adaptive.refined_pixels, static_cast<long long>(first.size()));
        long long rays = 0;
        int by_spread_alone = 0;
        for (std::size_t i = 0; i < one.pixels.size(); ++i) {
            const float a = adaptive.pixels[i].a;
            if (!after_first[i]) {
                ASSERT_EQ(std::memcmp(&adaptive.pixels[i], &one.pixels[i], sizeof(glm::vec4)), 0) << "pixel " << i;
                rays += 1;
                continue;
            }
            const bool last_step = a == one.pixels[i].a + two.pixels[i].a + full.pixels[i].a;
            ASSERT_TRUE(last_step || a == one.pixels[i].a + two.pixels[i].a) << "pixel " << i;
            ASSERT_TRUE(same_rgb(adaptive.pixels[i], last_step ? full.pixels[i] : two.pixels[i])) << "pixel " << i;
            rays += last_step ? 1 + 4 + 9 : 1 + 4;
            // The spread is computed here from another render's rays: where it is within a
            // level of the threshold, rounding may decide either way.
            const bool spread_says = spread[i] > threshold + 1.5 / 255, spread_stops = spread[i] < threshold - 1.5 / 255;
            if (method == AaMethod::Neighbours || (!spread_says && spread_stops)) {
                EXPECT_EQ(last_step, bool(by_neighbours[i])) << "pixel " << i << ", spread " << spread[i];
            } else if (spread_says) {
                EXPECT_TRUE(last_step) << "pixel " << i << ", spread " << spread[i];
                by_spread_alone += !by_neighbours[i];
            }
        }
        EXPECT_EQ(adaptive.camera_rays, rays);
        if (method == AaMethod::Spread) {
            EXPECT_GT(by_spread_alone, 0) << "no pixel tested the spread";
        }
    }
}

// The GPU packs a render's scene once for all its steps (a parametric surface's cells take
// 20-120 ms each time), and packs the next render's scene afresh.
TEST(AdaptiveGpu, ARenderPacksItsSceneOnceForAllItsSteps) {
    GpuRenderer& gpu = test::gpu_renderer();
    std::size_t before = gpu.scenes_packed();
    const FloatImage steps = gpu.render(deeper(2, AaMethod::Spread, 0.0), {});
    EXPECT_EQ(gpu.scenes_packed(), before + 1);
    Scene moved = deeper(2, AaMethod::Spread, 0.0);
    moved.camera.eye += dvec3(0.5, 0.0, 0.0);
    const FloatImage other = gpu.render(moved, {});
    EXPECT_EQ(gpu.scenes_packed(), before + 2);
    EXPECT_NE(std::memcmp(steps.pixels.data(), other.pixels.data(), steps.pixels.size() * sizeof(glm::vec4)), 0);
}

// The GPU chooses the pixels to refine on the device (gpu/passes/refine_selection.hpp): it never calls
// the host's pixels_to_refine, and every step's picture is the one the host's choice gives, byte
// for byte (the host chooses where the device cannot hold the picture).
TEST(AdaptiveGpu, ChoosesOnTheDeviceWhatTheHostWould) {
    GpuRenderer& gpu = test::gpu_renderer();
    struct HostChoiceOff {
        GpuRenderer& gpu;
        ~HostChoiceOff() { gpu.choose_on_host(false); }
    } restore{gpu};
    for (AaMethod method : {AaMethod::Neighbours, AaMethod::Spread}) {
        SCOPED_TRACE(method == AaMethod::Spread ? "spread" : "neighbours");
        const Scene scene = deeper(2, method, 0.3);
        auto pictures = [&] {
            std::vector<FloatImage> steps;
            gpu.render_in_steps(scene, {}, [&](const FloatImage& image, int, int, bool) { steps.push_back(image); });
            return steps;
        };
        const std::size_t calls = pixels_to_refine_calls(), selections = gpu.device_selections();
        const std::vector<FloatImage> on_device = pictures();
        EXPECT_EQ(pixels_to_refine_calls(), calls);
        EXPECT_EQ(gpu.device_selections(), selections + 2);
        gpu.choose_on_host(true);
        const std::vector<FloatImage> on_host = pictures();
        gpu.choose_on_host(false);
        EXPECT_EQ(pixels_to_refine_calls(), calls + 2);
        EXPECT_EQ(gpu.device_selections(), selections + 2);
        ASSERT_EQ(on_device.size(), 3u);
        ASSERT_EQ(on_host.size(), on_device.size());
        for (std::size_t k = 0; k < on_device.size(); ++k) {
            SCOPED_TRACE("step " + std::to_string(k));
            ASSERT_EQ(on_device[k].pixels.size(), on_host[k].pixels.size());
            EXPECT_EQ(std::memcmp(on_device[k].pixels.data(), on_host[k].pixels.data(),
                                  on_host[k].pixels.size() * sizeof(glm::vec4)),
                      0);
            EXPECT_EQ(on_device[k].refined_pixels, on_host[k].refined_pixels);
            EXPECT_EQ(on_device[k].camera_rays, on_host[k].camera_rays);
        }
        EXPECT_NE(std::memcmp(on_device[0].pixels.data(), on_device[2].pixels.data(),
                              on_device[0].pixels.size() * sizeof(glm::vec4)),
                  0);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, Adaptive, ::testing::Values(test::Backend::Gpu, test::Backend::Cpu),
                         [](const auto& info) { return std::string(test::backend_name(info.param)); });

}  // namespace
}  // namespace lancer
