#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <vector>

#include "image/image.hpp"

namespace lancer {

std::uint8_t encode_srgb8_by_formula(float linear) {
    float c = std::clamp(linear, 0.0f, 1.0f);
    if (std::isnan(linear)) c = 0.0f;
    float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

namespace {

// The formula's codes as tables. The formula is non-decreasing on [0, 1] (checked float by float
// once; tests/unit/difference_tables_test.cpp checks the floats around every level start), so a
// float's code is the highest level whose least float it reaches. Non-negative floats order as
// their bit patterns do: the levels' starts are found by bisecting patterns, and the code where
// each run of 2^16 consecutive patterns begins is a table entry. A run spans at most a level or
// two of the curve, so one or two comparisons with the level starts finish a code: a 720p
// picture's 2.8 M codes in a few milliseconds instead of 2.8 M powf (about 5% of `seed`'s wall time).
constexpr int kRunBits = 16;

struct Srgb8Tables {
    std::array<float, 256> starts{};
    std::vector<std::uint8_t> run_code;

    Srgb8Tables() {
        const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
        for (int k = 1; k < 256; ++k) {
            std::uint32_t lo = 0, hi = one;  // formula(lo) < k <= formula(hi)
            while (hi - lo > 1) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                (encode_srgb8_by_formula(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
            }
            starts[k] = std::bit_cast<float>(hi);
        }
        run_code.resize((one >> kRunBits) + 1);
        unsigned reached = 0;  // the previous run's code: runs come in increasing order
        for (std::uint32_t run = 0; run < run_code.size(); ++run)
            run_code[run] = reached = code(std::bit_cast<float>(run << kRunBits), reached);
    }

    // The code of `linear`, counting level starts from `first`, a code it is known to reach.
    std::uint8_t code(float linear, unsigned first) const {
        unsigned k = first;
        while (k < 255 && linear >= starts[k + 1]) ++k;
        return static_cast<std::uint8_t>(k);
    }

    std::uint8_t encode(float linear) const {
        if (!(linear > 0.0f)) return 0;  // negative, zero, NaN
        if (linear >= 1.0f) return 255;
        return code(linear, run_code[std::bit_cast<std::uint32_t>(linear) >> kRunBits]);
    }
};

const Srgb8Tables& srgb8_tables() {
    static const Srgb8Tables tables;
    return tables;
}

}  // namespace

const std::array<float, 256>& srgb8_level_starts() { return srgb8_tables().starts; }

std::uint8_t encode_srgb8(float linear) { return srgb8_tables().encode(linear); }

float decode_srgb8(std::uint8_t encoded) {
    float c = encoded / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

Rgb8Image to_srgb8(const FloatImage& image, const ToneMapping& mapping, float scale) {
    Rgb8Image out{image.width, image.height, {}};
    out.bytes.resize(image.pixels.size() * 3);
    const bool identity = mapping.exposure == 0.0 && mapping.tone == Tone::Clamp && mapping.assumed_gamma == 1.0;
    const Srgb8Tables& tables = srgb8_tables();
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            float v = scale == 1.0f ? image.pixels[i][c] : image.pixels[i][c] * scale;
            out.bytes[i * 3 + c] = tables.encode(identity ? v : tone_map(v, mapping));
        }
    return out;
}

double FloatImage::total_rays() const {
    double sum = 0.0;
    for (const auto& p : pixels) sum += p.a;
    return sum;
}

}  // namespace lancer
