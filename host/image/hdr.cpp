// Linear HDR output (OpenEXR and PFM) and the choice of format by file name (image.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfDoubleAttribute.h>
#include <ImfIntAttribute.h>
#include <ImfStringAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfVersion.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/escape.hpp"
#include "core/file_reading.hpp"
#include "image/image.hpp"

namespace lancer {
namespace {

constexpr const char* kFirstPassAttribute = "lancerFirstPass";
constexpr const char* kPassesAttribute = "lancerPasses";
constexpr const char* kTotalPassesAttribute = "lancerTotalPasses";
constexpr const char* kExposureAttribute = "lancerExposure";
constexpr const char* kToneAttribute = "lancerTone";
constexpr const char* kAssumedGammaAttribute = "lancerAssumedGamma";
constexpr const char* kSceneHashAttribute = "lancerSceneHash";
constexpr const char* kSettingsAttribute = "lancerSettings";
const char* const kToneNames[] = {"clamp", "reinhard", "aces"};

// Interleaved RGB floats, row-major from the top (what OpenEXR's frame buffer points into).
std::vector<float> rgb_of(const FloatImage& image) {
    std::vector<float> rgb(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i][c];
    return rgb;
}

}  // namespace

void write_exr(const std::string& path, const FloatImage& image, const ExrInfo& info) {
    std::vector<float> rgb = rgb_of(image);
    std::ostringstream bytes;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        if (info.passes > 0) {
            header.insert(kFirstPassAttribute, Imf::IntAttribute(info.first_pass));
            header.insert(kPassesAttribute, Imf::IntAttribute(info.passes));
            header.insert(kTotalPassesAttribute, Imf::IntAttribute(info.total_passes));
        }
        header.insert(kExposureAttribute, Imf::DoubleAttribute(info.tone.exposure));
        header.insert(kToneAttribute, Imf::StringAttribute(kToneNames[static_cast<int>(info.tone.tone)]));
        if (info.tone.assumed_gamma != 1.0) header.insert(kAssumedGammaAttribute, Imf::DoubleAttribute(info.tone.assumed_gamma));
        if (!info.scene_hash.empty()) header.insert(kSceneHashAttribute, Imf::StringAttribute(info.scene_hash));
        if (!info.settings.empty()) header.insert(kSettingsAttribute, Imf::StringAttribute(info.settings));
        Imf::StdOSStream stream;
        Imf::FrameBuffer frame;
        const std::size_t x_stride = 3 * sizeof(float), y_stride = x_stride * static_cast<std::size_t>(image.width);
        for (int c = 0; c < 3; ++c)
            frame.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgb.data() + c), x_stride, y_stride));
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(image.height);
        }
        std::string data = stream.str();
        write_file_atomically(path, data.data(), data.size());
    } catch (const UserError&) {
        throw;
    } catch (const std::exception& e) {
        throw UserError("cannot write OpenEXR '" + path + "': " + e.what());
    }
}

namespace {

// The bytes of a file as OpenEXR's input stream: the size is known before OpenEXR reads a thing,
// and reading past the end is an error, never a wait.
class MemoryStream : public Imf::IStream {
public:
    MemoryStream(const std::string& name, const std::string& bytes) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos_ > bytes_.size() || static_cast<std::size_t>(n) > bytes_.size() - pos_)
            throw std::runtime_error("the file ends too early");
        std::memcpy(c, bytes_.data() + pos_, static_cast<std::size_t>(n));
        pos_ += static_cast<std::size_t>(n);
        return pos_ < bytes_.size();
    }
    std::uint64_t tellg() override { return pos_; }
    void seekg(std::uint64_t pos) override { pos_ = pos; }
    void clear() override {}

private:
    const std::string& bytes_;
    std::uint64_t pos_ = 0;
};

// How many times smaller than the pixels a chunk's compressed data can be: deflate (ZIP, ZIPS)
// at best stores 258 bytes in about 2 bits (1032 : 1, plus zlib's few bytes); OpenEXR's RLE a run
// of up to 128 bytes in 2. lancer reads no other compression (it writes ZIP).
double max_compression_ratio(Imf::Compression c) {
    switch (c) {
        case Imf::NO_COMPRESSION: return 1.0;
        case Imf::RLE_COMPRESSION: return 64.0;
        case Imf::ZIPS_COMPRESSION:
        case Imf::ZIP_COMPRESSION: return 1032.0;
        default: return 0.0;
    }
}

struct ExrRejected : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What the header must say before anything is allocated for the pixels: one scanline image of
// R, G and B within lancer's limits, in a file large enough for them.
constexpr const char* kScanlineOnly = "lancer reads single-part scanline images (it writes them), not tiled, multi-part or deep ones";

void check_exr_header(const Imf::Header& h, std::size_t file_size) {
    if (h.hasTileDescription()) throw ExrRejected(kScanlineOnly);
    const Imath::Box2i w = h.dataWindow();
    const long long width = static_cast<long long>(w.max.x) - w.min.x + 1, height = static_cast<long long>(w.max.y) - w.min.y + 1;
    if (width < 1 || height < 1) throw ExrRejected("its data window is empty");
    if (width > kMaxReadSide || height > kMaxReadSide || width * height > kMaxReadPixels)
        throw ExrRejected(fmt::format("its data window is {}x{}, beyond the limit of {} pixels a side and {} in all", width,
                                      height, kMaxReadSide, kMaxReadPixels));
    std::vector<std::string> names;
    long long bytes_per_pixel = 0;
    for (auto c = h.channels().begin(); c != h.channels().end(); ++c) {
        names.push_back(c.name());
        if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
            throw ExrRejected(fmt::format("channel {} is subsampled", c.name()));
        bytes_per_pixel += c.channel().type == Imf::HALF ? 2 : 4;
    }
    if (names != std::vector<std::string>{"B", "G", "R"})  // the channel list is sorted by name
        throw ExrRejected(fmt::format("it has the channels {}, not R, G and B", names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "))));
    const double ratio = max_compression_ratio(h.compression());
    if (ratio == 0.0) throw ExrRejected("lancer reads uncompressed, RLE and ZIP compressed OpenEXR (it writes ZIP)");
    const double least = double(width) * double(height) * double(bytes_per_pixel) / ratio;
    if (double(file_size) < least)
        throw ExrRejected(fmt::format("its {} bytes cannot hold the {}x{} pixels its header claims (at least {:.0f} bytes)",
                                      file_size, width, height, least));
}

// The attribute types read_exr accepts, with their values' sizes (0: as the size field says).
// OpenEXR reads a value by its type's structure, not by the size field before it, and allocates
// what a string's size, a preview image's or a string vector's own fields claim: a value whose
// size field disagrees with its structure would make OpenEXR read the rest of the header out of
// step (a 600-byte file then claimed a string of 2 GB: fuzz_exr_part). So every value must have
// its type's size; chlist is walked; other types (preview, stringvector, idmanifest, ...) are
// refused: lancer writes none.
std::size_t attribute_size(const std::string& type) {
    static const std::pair<const char*, std::size_t> kTypes[] = {
        {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"lineOrder", 1}, {"envmap", 1}, {"deepImageState", 1},
        {"int", 4}, {"float", 4}, {"double", 8}, {"rational", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12},
        {"v3f", 12}, {"v3d", 24}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"chromaticities", 32},
        {"keycode", 28}, {"timecode", 8}, {"tiledesc", 9}, {"string", 0}, {"chlist", 0}};
    for (const auto& [name, size] : kTypes)
        if (type == name) return size == 0 ? std::string::npos - 1 : size;
    return std::string::npos;
}

// Walks the header's attributes (name, type, size, value; an empty name ends it) before OpenEXR
// reads them, as OpenEXR will (attribute_size above).
void check_attribute_sizes(const std::string& bytes, int version) {
    const std::size_t max_name = (version & Imf::LONG_NAMES_FLAG) ? 255 : 31;
    std::size_t pos = 8;  // after the magic number and the version field
    auto c_string = [&](std::size_t max) {
        const std::size_t end = bytes.find('\0', pos);
        if (end == std::string::npos || end - pos > max) throw ExrRejected("its header is malformed");
        std::string text = bytes.substr(pos, end - pos);
        pos = end + 1;
        return text;
    };
    for (;;) {
        if (pos >= bytes.size()) throw ExrRejected("its header ends too early");
        if (bytes[pos] == '\0') return;
        const std::string name = c_string(max_name), type = c_string(max_name);
        const std::size_t fixed = attribute_size(type);
        if (fixed == std::string::npos)
            throw ExrRejected(fmt::format("lancer does not read its {} attribute {}", escape_control_characters(type),
                                          escape_control_characters(name)));
        std::int32_t size = 0;
        if (bytes.size() - pos < sizeof size) throw ExrRejected("its header ends too early");
        std::memcpy(&size, bytes.data() + pos, sizeof size);
        pos += sizeof size;
        if (size < 0 || static_cast<std::size_t>(size) > bytes.size() - pos)
            throw ExrRejected(fmt::format("its attribute {} claims {} bytes, more than the file holds",
                                          escape_control_characters(name), size));
        const std::size_t value_end = pos + static_cast<std::size_t>(size);
        if (type == "chlist") {  // entries of a name and 16 bytes, then an empty name, exactly
            while (pos < value_end && bytes[pos] != '\0') {
                c_string(max_name);
                pos += 16;
            }
            if (pos + 1 != value_end) throw ExrRejected(fmt::format("its channel list {} is malformed", escape_control_characters(name)));
        } else if (type != "string" && static_cast<std::size_t>(size) != fixed) {
            throw ExrRejected(fmt::format("its {} attribute {} has {} bytes, not {}", type, escape_control_characters(name), size, fixed));
        }
        pos = value_end;
    }
}

// Reads one of lancer's attributes: absent is fine, another type is not.
template <typename Attribute>
const Attribute* lancer_attribute(const Imf::Header& h, const char* name) {
    const Imf::Attribute* a = h.find(name) == h.end() ? nullptr : &h[name];
    if (!a) return nullptr;
    const auto* typed = dynamic_cast<const Attribute*>(a);
    if (!typed) throw ExrRejected(fmt::format("its attribute {} has the type {}", name, a->typeName()));
    return typed;
}

ExrInfo read_lancer_attributes(const Imf::Header& h) {
    ExrInfo info;
    if (const auto* a = lancer_attribute<Imf::IntAttribute>(h, kFirstPassAttribute)) info.first_pass = a->value();
    if (const auto* a = lancer_attribute<Imf::IntAttribute>(h, kPassesAttribute)) info.passes = a->value();
    if (const auto* a = lancer_attribute<Imf::IntAttribute>(h, kTotalPassesAttribute)) info.total_passes = a->value();
    if (const auto* a = lancer_attribute<Imf::DoubleAttribute>(h, kExposureAttribute)) {
        const double e = a->value();
        if (!(std::isfinite(e) && std::abs(e) <= kMaxExposureStops))
            throw ExrRejected(fmt::format("its {} attribute is {}, not a finite number of stops in [-{}, {}]", kExposureAttribute, e,
                                          kMaxExposureStops, kMaxExposureStops));
        info.tone.exposure = e;
    }
    if (const auto* a = lancer_attribute<Imf::StringAttribute>(h, kToneAttribute)) {
        const auto* name = std::find(std::begin(kToneNames), std::end(kToneNames), a->value());
        if (name == std::end(kToneNames))
            throw ExrRejected(fmt::format("its {} attribute is '{}', not clamp, reinhard or aces", kToneAttribute,
                                          escape_control_characters(a->value())));
        info.tone.tone = static_cast<Tone>(name - std::begin(kToneNames));
    }
    if (const auto* a = lancer_attribute<Imf::DoubleAttribute>(h, kAssumedGammaAttribute)) {
        const double g = a->value();
        if (!(g >= kMinAssumedGamma && g <= kMaxAssumedGamma))
            throw ExrRejected(fmt::format("its {} attribute is {}, not a gamma in [{}, {}]", kAssumedGammaAttribute, g,
                                          kMinAssumedGamma, kMaxAssumedGamma));
        info.tone.assumed_gamma = g;
    }
    if (const auto* a = lancer_attribute<Imf::StringAttribute>(h, kSceneHashAttribute)) info.scene_hash = a->value();
    if (const auto* a = lancer_attribute<Imf::StringAttribute>(h, kSettingsAttribute)) info.settings = a->value();
    return info;
}

}  // namespace

FloatImage read_exr_bytes(const std::string& path, const std::string& bytes, ExrInfo* info) {
    try {
        MemoryStream stream(path, bytes);
        int magic = 0, version = 0;
        stream.read(reinterpret_cast<char*>(&magic), sizeof magic);  // little-endian, as lancer's hosts
        stream.read(reinterpret_cast<char*>(&version), sizeof version);
        if (magic != Imf::MAGIC) throw ExrRejected("not an OpenEXR file");
        if (Imf::getVersion(version) != Imf::EXR_VERSION || !Imf::supportsFlags(Imf::getFlags(version)))
            throw ExrRejected(fmt::format("OpenEXR version field {:#x} is not one lancer reads", version));
        if (Imf::isTiled(version) || Imf::isMultiPart(version) || Imf::isNonImage(version)) throw ExrRejected(kScanlineOnly);
        check_attribute_sizes(bytes, version);
        Imf::Header header;
        header.readFrom(stream, version);
        check_exr_header(header, bytes.size());
        ExrInfo attributes = read_lancer_attributes(header);

        stream.seekg(0);
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        FloatImage image(width, height);
        // Straight into the image's vec4 pixels (a stays 0): no second copy of the picture.
        Imf::FrameBuffer frame;
        const std::size_t x_stride = sizeof(glm::vec4), y_stride = x_stride * static_cast<std::size_t>(width);
        for (int c = 0; c < 3; ++c)
            frame.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
                         Imf::Slice::Make(Imf::FLOAT, reinterpret_cast<char*>(image.pixels.data()) + c * sizeof(float), window,
                                          x_stride, y_stride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (info) *info = attributes;
        return image;
    } catch (const UserError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        throw UserError("cannot read OpenEXR '" + path + "': " + escape_control_characters(e.what()));
    }
}

FloatImage read_exr(const std::string& path, ExrInfo* info) {
    // Read whole and bounded (a FIFO too; an interrupt stops a read that blocks): no part lancer
    // writes is larger than its pixels uncompressed, 12 bytes each, plus its header.
    const std::size_t limit = static_cast<std::size_t>(kMaxReadPixels) * 12 + (std::size_t(64) << 20);
    FileText file;
    try {
        file = read_file(path, limit);
    } catch (const UserError& e) {
        throw UserError("cannot read OpenEXR '" + path + "': " + e.what());
    }
    if (!file.complete) throw UserError(fmt::format("cannot read OpenEXR '{}': it is larger than {} bytes", path, limit));
    return read_exr_bytes(path, file.text, info);
}

void write_pfm(const std::string& path, const FloatImage& image) {
    // "PF" (colour), the size, and a negative scale for little-endian floats; rows bottom to top.
    std::string data = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    const std::size_t header = data.size();
    data.resize(header + image.pixels.size() * 3 * sizeof(float));
    char* out = data.data() + header;
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = image.at(x, y)[c];
                std::memcpy(out, &v, sizeof v);  // x86 and ARM Linux: little-endian
                out += sizeof v;
            }
    write_file_atomically(path, data.data(), data.size());
}

FloatImage read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int width = 0, height = 0;
    double scale = 0.0;
    if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 || height <= 0 || scale >= 0.0)
        throw UserError("cannot read PFM '" + path + "': not a little-endian colour PFM");
    in.get();  // the single whitespace character after the scale
    FloatImage image(width, height);
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v;
                if (!in.read(reinterpret_cast<char*>(&v), sizeof v)) throw UserError("cannot read PFM '" + path + "': truncated");
                image.at(x, y)[c] = v;
            }
    return image;
}

std::optional<ImageFormat> image_format_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".pfm") return ImageFormat::Pfm;
    return std::nullopt;
}

void write_image(const std::string& path, const FloatImage& image, const ExrInfo& info) {
    switch (image_format_of(path).value_or(ImageFormat::Png)) {
        case ImageFormat::Png: write_png(path, to_srgb8(image, info.tone)); break;
        case ImageFormat::Exr: write_exr(path, image, info); break;
        case ImageFormat::Pfm: write_pfm(path, image); break;
    }
}

}  // namespace lancer
