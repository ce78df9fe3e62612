// Adaptive anti-aliasing's choice of the pixels to refine, made on the device
// (gpu/passes/refine_selection.hpp), against the host's definition: pixels_to_refine, and the spread rule
// through HostAdaptivePicture, which the CPU reference uses. The device must list the same pixels
// in the same order, on pictures made to catch each way it could go wrong: colours on either side
// of an sRGB level (an encoding off by one rounding), code differences whose sum's rounding
// depends on their split (a comparison of the summed codes), flat regions, picture edges,
// NaN and infinities, several scan blocks, and later steps with their candidates and spread.
#include <bit>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/passes/refine_selection.hpp"
#include "image/adaptive.hpp"
#include "image/difference_tables.hpp"
#include "image/image.hpp"
#include "render/host_adaptive_picture.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// The selection with its own layout and buffers, on the shared test renderer's device (under the
// validation layer).
struct DeviceSelection {
    const gpu::Context& context = test::gpu_renderer().context();
    gpu::TraceLayout layout{context};
    gpu::TraceResources resources{context, layout.set_layout()};
    gpu::RefineSelection selection{context, layout, gpu::embedded_spirv(gpu::kSelectShader)};

    std::vector<std::uint32_t> first_choice(const FloatImage& picture, double threshold) {
        selection.start(picture, resources);
        const std::uint32_t count = selection.choose(threshold, false, resources, {}, 0.0);
        std::vector<std::uint32_t> list = selection.list(resources);
        EXPECT_EQ(list.size(), count);
        return list;
    }
};

float random_channel(std::mt19937& rng) {
    std::uniform_real_distribution<float> value(-0.1f, 1.2f);
    std::uniform_int_distribution<int> special(0, 199);
    switch (special(rng)) {
        case 0: return std::numeric_limits<float>::quiet_NaN();
        case 1: return std::numeric_limits<float>::infinity();
        case 2: return -std::numeric_limits<float>::infinity();
        default: return value(rng);
    }
}

FloatImage random_picture(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    FloatImage image(w, h);
    for (glm::vec4& p : image.pixels) p = glm::vec4(random_channel(rng), random_channel(rng), random_channel(rng), 1.0f);
    return image;
}

// A float of sRGB code `code` right at one end of its level: the level's first float, or its last.
float at_level_edge(int code, bool last) {
    const auto& starts = srgb8_level_starts();
    if (!last) return starts[code];
    return code == 255 ? 1.0f : std::nextafter(starts[code + 1], 0.0f);
}

// Codes around 60..162 per channel, every channel at an end of its level: neighbours' code
// differences sum to 153 (0.6 = 153/255 exactly) often enough that both roundings of the sum occur.
glm::vec4 level_colour(std::mt19937& rng) {
    std::uniform_int_distribution<int> code(60, 162), end(0, 1);
    glm::vec4 c(1.0f);
    for (int k = 0; k < 3; ++k) c[k] = at_level_edge(code(rng), end(rng) == 1);
    return c;
}

FloatImage level_picture(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    FloatImage image(w, h);
    for (glm::vec4& p : image.pixels) p = level_colour(rng);
    return image;
}

// Large flat regions with straight and curved edges, a slow ramp (small differences
// everywhere) and single odd pixels on the picture's border.
FloatImage edges_picture(int w, int h) {
    FloatImage image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec4 c(0.2f, 0.3f, 0.4f, 1.0f);
            if (x > w / 2) c = glm::vec4(0.8f, 0.1f, 0.1f, 1.0f);
            const float dx = float(x - w / 4), dy = float(y - h / 2);
            if (dx * dx + dy * dy < float(h * h) / 9.0f) c = glm::vec4(0.05f, 0.9f, 0.2f, 1.0f);
            if (y > 3 * h / 4) c = glm::vec4(float(x) / float(w), 0.5f, 0.5f, 1.0f);
            image.pixels[std::size_t(y) * w + x] = c;
        }
    image.pixels[0] = glm::vec4(1.0f);
    image.pixels[image.pixels.size() - 1] = glm::vec4(0.0f);
    image.pixels[std::size_t(w) - 1] = glm::vec4(1.0f, 0.0f, 1.0f, 1.0f);
    return image;
}

FloatImage flat_picture(int w, int h) {
    FloatImage image(w, h);
    for (glm::vec4& p : image.pixels) p = glm::vec4(0.3f, 0.6f, 0.1f, 1.0f);
    return image;
}

// How many pairs of neighbours have code differences summing to exactly `sum`, and of those
// how many differ by more than `threshold`.
std::pair<int, int> pairs_summing_to(const FloatImage& image, int sum, double threshold) {
    int pairs = 0, differing = 0;
    auto look = [&](const glm::vec4& a, const glm::vec4& b) {
        int s = 0;
        for (int c = 0; c < 3; ++c) s += std::abs(int(encode_srgb8(a[c])) - int(encode_srgb8(b[c])));
        if (s != sum) return;
        ++pairs;
        differing += color_difference(a, b) > threshold;
    };
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (x + 1 < image.width) look(image.at(x, y), image.at(x + 1, y));
            if (y + 1 < image.height) look(image.at(x, y), image.at(x, y + 1));
        }
    return {pairs, differing};
}

TEST(RefineSelection, FirstChoiceIsPixelsToRefine) {
    DeviceSelection device;
    struct Case {
        const char* name;
        FloatImage picture;
    };
    const Case cases[] = {{"random", random_picture(97, 61, 1)},
                          {"levels", level_picture(97, 61, 2)},
                          {"edges", edges_picture(131, 70)},
                          {"flat", flat_picture(64, 64)},
                          {"seed", test::render_on(test::Backend::Gpu, test::shipped_scene("seed", 96, 54, 1))},
                          {"one pixel", random_picture(1, 1, 3)},
                          {"one row", level_picture(300, 1, 4)},
                          {"one column", level_picture(1, 300, 5)}};
    for (const Case& c : cases)
        for (double threshold : {0.3, 0.6, 0.05, 1.0, 0.0, 3.0}) {
            SCOPED_TRACE(std::string(c.name) + ", threshold " + std::to_string(threshold));
            const std::vector<std::uint32_t> expected = pixels_to_refine(c.picture, threshold);
            EXPECT_EQ(device.first_choice(c.picture, threshold), expected);
        }
    // The pictures did what they are here for.
    const std::pair<int, int> splits = pairs_summing_to(cases[1].picture, 153, 0.6);
    EXPECT_GT(splits.second, 0);
    EXPECT_LT(splits.second, splits.first);
    EXPECT_TRUE(pixels_to_refine(cases[3].picture, 0.05).empty());
    EXPECT_EQ(pixels_to_refine(cases[3].picture, 0.0).size(), cases[3].picture.pixels.size());
}

// More blocks than the single workgroup that adds up the block totals takes at once.
TEST(RefineSelection, FirstChoiceOverManyBlocks) {
    DeviceSelection device;
    const FloatImage picture = level_picture(640, 400, 6);
    ASSERT_GT(picture.pixels.size(), std::size_t(3 * gpu::SELECT_BLOCK * gpu::SELECT_WORKGROUP));
    EXPECT_EQ(device.first_choice(picture, 0.6), pixels_to_refine(picture, 0.6));
}

// What a synthetic refinement traced for pixel p at step k: a colour at the ends of sRGB levels,
// the spread of its samples around it (wide for some pixels, narrow for others), and its rays.
ListedPixel traced(std::uint32_t p, int k) {
    std::mt19937 rng(p * 7919u + unsigned(k));
    ListedPixel t;
    t.colour = level_colour(rng);
    t.colour.a = float(4 * k + 1);
    std::uniform_real_distribution<float> width(0.0f, 0.4f);
    const float w = p % 3 == 0 ? width(rng) : 0.01f;
    t.lo = glm::vec3(t.colour) - w;
    t.hi = glm::vec3(t.colour) + glm::vec3(w, 0.5f * w, 0.0f);
    return t;
}

// Later steps: the candidates are the last step's pixels, the picture has their new colours
// (merged on the device band by band), and with the spread a pixel whose samples spread goes on
// too. Three steps of each method, the device against HostAdaptivePicture.
TEST(RefineSelection, LaterChoicesFollowTheHostRule) {
    for (bool spread : {false, true})
        for (double threshold : {0.3, 0.6, 0.0}) {
            SCOPED_TRACE(std::string(spread ? "spread" : "neighbours") + ", threshold " + std::to_string(threshold));
            const FloatImage first = level_picture(83, 67, 7);
            std::vector<std::uint32_t> host_list;
            int step = 0;
            HostAdaptivePicture host([&](const Scene&, const ProgressFn&) { return first; },
                                     [&](const Scene&, const std::vector<std::uint32_t>& pixels, bool, const ProgressFn&) {
                                         host_list = pixels;
                                         std::vector<ListedPixel> out;
                                         for (std::uint32_t p : pixels) out.push_back(traced(p, step));
                                         return out;
                                     });
            DeviceSelection device;
            host.render_first(Scene{}, {});
            device.selection.start(first, device.resources);
            int by_spread_alone = 0;
            for (step = 1; step <= 3; ++step) {
                SCOPED_TRACE("step " + std::to_string(step));
                const bool by_spread = spread && step > 1;
                if (by_spread) {
                    // How many the neighbour test alone leaves out, for the check below.
                    const FloatImage picture = host.picture();
                    std::vector<char> candidates(picture.pixels.size(), 0);
                    for (std::uint32_t p : host_list) candidates[p] = 1;
                    by_spread_alone -= int(pixels_to_refine(picture, threshold, candidates).size());
                }
                const std::size_t count = host.choose(threshold, by_spread);
                by_spread_alone += by_spread ? int(count) : 0;
                ASSERT_EQ(device.selection.choose(threshold, by_spread, device.resources, {}, 0.0), count);
                if (count == 0) break;
                host.refine(Scene{}, spread, {});
                ASSERT_EQ(device.selection.list(device.resources), host_list);
                // The refining trace's output, in three bands of uneven size.
                const std::uint32_t n = std::uint32_t(count), bounds[] = {0, n / 5, n / 2, n};
                for (int b = 0; b < 3; ++b) {
                    const std::uint32_t from = bounds[b], entries = bounds[b + 1] - from;
                    if (entries == 0) continue;
                    const gpu::Buffer& out = device.resources.output(std::size_t(entries) * 3 * sizeof(glm::vec4));
                    auto* band = static_cast<glm::vec4*>(out.data());
                    for (std::uint32_t i = 0; i < entries; ++i) {
                        const ListedPixel t = traced(host_list[from + i], step);
                        band[i] = t.colour;
                        band[entries + i] = glm::vec4(t.lo, 0.0f);
                        band[2 * entries + i] = glm::vec4(t.hi, 0.0f);
                    }
                    device.selection.merge(from, entries, spread, device.resources, {}, 0.0);
                }
                const FloatImage on_device = device.selection.picture(device.resources), on_host = host.picture();
                ASSERT_EQ(std::memcmp(on_device.pixels.data(), on_host.pixels.data(), on_host.pixels.size() * sizeof(glm::vec4)), 0);
            }
            if (spread && threshold > 0.0) {
                EXPECT_GT(by_spread_alone, 0) << "no pixel went on by its spread alone";
            }
        }
}

}  // namespace
}  // namespace lancer
