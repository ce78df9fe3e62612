#include <algorithm>
#include <array>
#include <cmath>

#include "image/image.hpp"

namespace lancer {

std::uint8_t encode_srgb8(float linear) {
    float c = std::clamp(linear, 0.0f, 1.0f);
    if (std::isnan(linear)) c = 0.0f;
    float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

float decode_srgb8(std::uint8_t encoded) {
    float c = encoded / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

Rgb8Image to_srgb8(const FloatImage& image, const ToneMapping& mapping) {
    Rgb8Image out{image.width, image.height, {}};
    out.bytes.resize(image.pixels.size() * 3);
    const bool identity = mapping.exposure == 0.0 && mapping.tone == Tone::Clamp;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            float v = image.pixels[i][c];
            out.bytes[i * 3 + c] = encode_srgb8(identity ? v : tone_map(v, mapping));
        }
    return out;
}

double FloatImage::total_rays() const {
    double sum = 0.0;
    for (const auto& p : pixels) sum += p.a;
    return sum;
}

}  // namespace lancer
