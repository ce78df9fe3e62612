// Image textures on the CPU (the reference): texel placement, sRGB decoding before filtering,
// bilinear and nearest filtering, and each placement option as docs/scene-format.md states it.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "cpu/texture.hpp"
#include "image/image.hpp"

namespace lancer::cpu {
namespace {

// An image whose texel (x, y) (row 0 at the top) has the sRGB bytes (r, g, b) = fn(x, y).
template <typename Fn>
ImageTexture image_texture(int w, int h, Fn fn) {
    auto image = std::make_shared<TextureImage>();
    image->width = w;
    image->height = h;
    image->rgba.resize(std::size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::array<int, 3> c = fn(x, y);
            std::uint8_t* texel = &image->rgba[(std::size_t(y) * w + x) * 4];
            for (int k = 0; k < 3; ++k) texel[k] = static_cast<std::uint8_t>(c[k]);
            texel[3] = 255;
        }
    ImageTexture t;
    t.image = image;
    return t;
}

double srgb_to_linear(int byte) {
    double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// 4 x 2 texels with distinct red bytes 10 * (index + 1), row 0 on top; nearest filtering.
ImageTexture labelled(TextureWrap wrap = TextureWrap::Repeat) {
    ImageTexture t = image_texture(4, 2, [](int x, int y) { return std::array<int, 3>{10 * (y * 4 + x + 1), 0, 0}; });
    t.filter = TextureFilter::Nearest;
    t.wrap_u = t.wrap_v = wrap;
    return t;
}

// The red byte `labelled` shows at (u, v).
int label_at(const ImageTexture& t, glm::dvec2 uv) {
    double r = texture_color(t, uv).r;
    for (int byte = 10; byte <= 80; byte += 10)
        if (std::abs(srgb_to_linear(byte) - r) < 1e-12) return byte;
    return -1;
}

TEST(Texture, TexelsLieWhereTheConventionPutsThem) {
    ImageTexture t = labelled();
    // u across from the left, v up from the bottom: (0, 0) is the bottom-left texel, row 1.
    EXPECT_EQ(label_at(t, {0.1, 0.1}), 50);
    EXPECT_EQ(label_at(t, {0.9, 0.1}), 80);
    EXPECT_EQ(label_at(t, {0.1, 0.9}), 10);
    EXPECT_EQ(label_at(t, {0.6, 0.7}), 30);
}

TEST(Texture, DecodesSrgbExactly) {
    ImageTexture t = image_texture(1, 1, [](int, int) { return std::array<int, 3>{128, 0, 255}; });
    dvec3 c = texture_color(t, {0.3, 0.6});
    EXPECT_NEAR(c.r, std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4), 1e-15);  // 0.2158605...
    EXPECT_NEAR(c.r, 0.21586050011389926, 1e-15);
    EXPECT_EQ(c.g, 0.0);
    EXPECT_EQ(c.b, 1.0);
}

TEST(Texture, BilinearHalfWayBetweenTwoTexelsIsTheMeanOfTheirLinearValues) {
    // Black and white: half way between their centres is 0.5 in linear light (decoding after
    // filtering would give decode(127.5) = 0.21 instead).
    ImageTexture t = image_texture(2, 1, [](int x, int) { return std::array<int, 3>{x * 255, x * 255, x * 255}; });
    EXPECT_NEAR(texture_color(t, {0.5, 0.5}).g, 0.5, 1e-12);
    EXPECT_NEAR(texture_color(t, {0.25, 0.5}).g, 0.0, 1e-12);  // at the black texel's centre
    EXPECT_NEAR(texture_color(t, {0.375, 0.5}).g, 0.25, 1e-12);
    // Repeat: left of the first centre blends with the last texel across the edge.
    EXPECT_NEAR(texture_color(t, {0.0, 0.5}).g, 0.5, 1e-12);
    t.wrap_u = TextureWrap::Clamp;
    EXPECT_NEAR(texture_color(t, {0.0, 0.5}).g, 0.0, 1e-12);
}

TEST(Texture, RepeatTilesAndClampHoldsTheEdge) {
    ImageTexture repeat = labelled(TextureWrap::Repeat);
    EXPECT_EQ(label_at(repeat, {2.1, -0.9}), 50);
    EXPECT_EQ(label_at(repeat, {-0.1, 0.1}), 80);
    ImageTexture clamp = labelled(TextureWrap::Clamp);
    EXPECT_EQ(label_at(clamp, {2.1, -0.9}), 80);
    EXPECT_EQ(label_at(clamp, {-3.0, 5.0}), 10);
}

TEST(Texture, ScaleOffsetAndRotatePlaceTheImage) {
    ImageTexture t = labelled();
    t.scale = {0.5, 2.0};  // one copy covers u in [0, 0.5], v in [0, 2]
    EXPECT_EQ(label_at(t, {0.45, 0.2}), 80);
    EXPECT_EQ(label_at(t, {0.55, 0.2}), 50);  // the next copy
    EXPECT_EQ(label_at(t, {0.05, 1.9}), 10);
    t.scale = {1.0, 1.0};
    t.offset = {0.25, 0.5};  // the image's corner moves to (0.25, 0.5)
    EXPECT_EQ(label_at(t, {0.3, 0.6}), 50);
    EXPECT_EQ(label_at(t, {0.2, 0.6}), 80);  // the copy to the left ends here
    t.offset = {0.0, 0.0};
    t.rotate_deg = 90.0;  // turned anticlockwise: the image's u axis now points along +v
    EXPECT_EQ(label_at(t, {-0.1, 0.1}), 50);   // image (0.1, 0.1)
    EXPECT_EQ(label_at(t, {-0.1, 0.9}), 80);   // image (0.9, 0.1)
}

}  // namespace
}  // namespace lancer::cpu
