#pragma once
// Images as the renderers produce them (linear float RGB plus a per-pixel ray count) and as
// they are written (8-bit sRGB).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "image/tone.hpp"

namespace lancer {

// rgb = linear colour, a = rays traced for the pixel (so rays/s needs no atomic counters).
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> pixels;  // row-major, row 0 at the top
    // Adaptive anti-aliasing (render/adaptive_render.hpp): the pixels refined at least once,
    // and the camera rays traced in all (the first ray of every pixel and every refinement's
    // grids); -1 when the render was not adaptive (every pixel got the full grid).
    long long refined_pixels = -1;
    long long camera_rays = -1;

    FloatImage() = default;
    FloatImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, glm::vec4(0.0f)) {}
    glm::vec4& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const glm::vec4& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
    double total_rays() const;
};

struct Rgb8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> bytes;  // RGB, row-major
    const std::uint8_t* at(int x, int y) const { return &bytes[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

// sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1], to 0..255, as
// evaluated in float with powf and rounded: the definition of every 8-bit code lancer writes.
std::uint8_t encode_srgb8_by_formula(float linear);
// The same codes, bit for bit, from tables: what pictures are encoded with.
std::uint8_t encode_srgb8(float linear);
// For each code k (1..255), the least float that encode_srgb8() maps to k or above (entry 0 is
// 0). encode_srgb8 is non-decreasing, so the code of a float f is the largest k with f >=
// entry k, and 0 when there is none (negative, NaN).
const std::array<float, 256>& srgb8_level_starts();
float decode_srgb8(std::uint8_t encoded);

// Each channel times `scale` (a sum of samples over their count), tone-mapped (image/tone.hpp),
// clamped to [0, 1] and sRGB-encoded.
Rgb8Image to_srgb8(const FloatImage& image, const ToneMapping& mapping = {}, float scale = 1.0f);

// Writes a PNG atomically: to a temporary file in the same directory, then rename(), so the
// destination is either the old file or the complete new one. Throws UserError on I/O failure.
void write_png(const std::string& path, const Rgb8Image& image);

// The largest image read_png() accepts: the largest lancer writes (scene/limits.hpp checks that
// they agree). Larger files, and files whose data is more than their header's size needs, are
// refused before they are decoded (image/image_file.hpp).
constexpr int kMaxReadSide = 16384;
constexpr long long kMaxReadPixels = 64LL * 1024 * 1024;

// A PNG (or JPEG, BMP) as 8-bit RGB. Throws UserError "cannot read PNG 'path': why".
Rgb8Image read_png(const std::string& path);

// What an OpenEXR file of lancer's says besides its pixels (as attributes): which photon passes
// its pixels average ("lancerFirstPass", "lancerPasses" of "lancerTotalPasses"; absent without
// photon mapping), for combining the parts of a farm render, and the scene's tone mapping
// ("lancerExposure", "lancerTone"), for the PNG made of them.
// A part of a farm render also carries a stamp of what determined its pixels
// ("lancerSceneHash": the scene's files; "lancerSettings": the render's settings, one "name
// value" per line; app/render_options.hpp), so that parts of different renders are not mixed.
struct ExrInfo {
    int first_pass = 0;
    int passes = 0;  // 0: not a photon render
    int total_passes = 0;
    ToneMapping tone;
    std::string scene_hash;  // empty: not stamped
    std::string settings;
};

// HDR output: the linear colours as they are (no exposure, no tone curve), 32-bit float:
// OpenEXR (RGB, ZIP-compressed) and the Portable Float Map (little-endian, rows bottom to top).
// Both atomic, as write_png.
void write_exr(const std::string& path, const FloatImage& image, const ExrInfo& info = {});
void write_pfm(const std::string& path, const FloatImage& image);
// Reads them back (rgb; a = 0). read_exr reads files as lancer writes them and refuses, before
// allocating for the pixels, anything larger than kMaxReadSide / kMaxReadPixels, channels other
// than R, G and B, tiled, deep or multi-part files, compressions other than NONE, RLE, ZIPS and
// ZIP, and a file too small for the pixels its header claims (even compressed); and lancer's
// attributes when they are of the wrong type or out of range (an exposure that is not finite or
// beyond kMaxExposureStops, an unknown tone curve). Throws UserError "cannot read OpenEXR
// 'path': why".
FloatImage read_exr(const std::string& path, ExrInfo* info = nullptr);
// The same from the bytes of a file (the fuzz target's entry); `name` is for the messages.
FloatImage read_exr_bytes(const std::string& name, const std::string& bytes, ExrInfo* info = nullptr);
FloatImage read_pfm(const std::string& path);

enum class ImageFormat { Png, Exr, Pfm };
// By the file name's extension (case-insensitive); nullopt for any other.
std::optional<ImageFormat> image_format_of(const std::string& path);
// Writes `image` in the format its name says: PNG through info's tone mapping, EXR (with info)
// and PFM linear.
void write_image(const std::string& path, const FloatImage& image, const ExrInfo& info);

// Writes `size` bytes atomically to `path` (a temporary file beside it, fsync, rename).
void write_file_atomically(const std::string& path, const void* data, std::size_t size);

}  // namespace lancer
