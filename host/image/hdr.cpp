// Linear HDR output (OpenEXR and PFM) and the choice of format by file name (image.hpp).
#include <algorithm>
#include <cctype>
#include <cstring>
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

#include "core/error.hpp"
#include "image/image.hpp"

namespace lancer {
namespace {

constexpr const char* kFirstPassAttribute = "lancerFirstPass";
constexpr const char* kPassesAttribute = "lancerPasses";
constexpr const char* kTotalPassesAttribute = "lancerTotalPasses";
constexpr const char* kExposureAttribute = "lancerExposure";
constexpr const char* kToneAttribute = "lancerTone";
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

FloatImage read_exr(const std::string& path, ExrInfo* info) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        FloatImage image(width, height);
        std::vector<float> rgb(std::size_t(width) * height * 3, 0.0f);
        Imf::FrameBuffer frame;
        const std::size_t x_stride = 3 * sizeof(float), y_stride = x_stride * static_cast<std::size_t>(width);
        char* origin = reinterpret_cast<char*>(rgb.data()) -
                       (static_cast<std::ptrdiff_t>(window.min.x) * x_stride + static_cast<std::ptrdiff_t>(window.min.y) * y_stride);
        for (int c = 0; c < 3; ++c)
            frame.insert(c == 0 ? "R" : c == 1 ? "G" : "B", Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), x_stride, y_stride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = glm::vec4(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2], 0.0f);
        if (info) {
            *info = {};
            const Imf::Header& h = file.header();
            if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>(kFirstPassAttribute)) info->first_pass = a->value();
            if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>(kPassesAttribute)) info->passes = a->value();
            if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>(kTotalPassesAttribute)) info->total_passes = a->value();
            if (const auto* a = h.findTypedAttribute<Imf::DoubleAttribute>(kExposureAttribute)) info->tone.exposure = a->value();
            if (const auto* a = h.findTypedAttribute<Imf::StringAttribute>(kToneAttribute))
                for (int t = 0; t < 3; ++t)
                    if (a->value() == kToneNames[t]) info->tone.tone = static_cast<Tone>(t);
        }
        return image;
    } catch (const std::exception& e) {
        throw UserError("cannot read OpenEXR '" + path + "': " + e.what());
    }
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
