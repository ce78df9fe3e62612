// Writes the seed corpus of the EXR part fuzz target (tests/fuzz/corpus/exr_part/): tiny
// scanline OpenEXR files as lancer writes its parts and as other tools might, in every
// compression lancer reads, float and half, with and without lancer's attributes, and a data
// window away from the origin. Not built with the project:
//
//   g++ -std=c++17 tests/fuzz/make_exr_corpus.cpp $(pkg-config --cflags --libs OpenEXR) -o make_exr_corpus
//   ./make_exr_corpus tests/fuzz/corpus/exr_part
#include <cstdio>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

namespace {

void write(const std::string& path, int width, int height, Imf::Compression compression, Imf::PixelType type,
           bool lancer_attributes, int x0 = 0, int y0 = 0) {
    Imath::Box2i window({x0, y0}, {x0 + width - 1, y0 + height - 1});
    Imf::Header header(window, window);
    header.compression() = compression;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(type));
    if (lancer_attributes) {
        header.insert("lancerFirstPass", Imf::IntAttribute(0));
        header.insert("lancerPasses", Imf::IntAttribute(2));
        header.insert("lancerTotalPasses", Imf::IntAttribute(4));
        header.insert("lancerExposure", Imf::DoubleAttribute(0.5));
        header.insert("lancerTone", Imf::StringAttribute("aces"));
        header.insert("lancerSceneHash", Imf::StringAttribute("0123456789abcdef"));
        header.insert("lancerSettings", Imf::StringAttribute("lancer 0.1.0\nbackend cpu\nsize 4x2\nsamples 2\n"));
    }
    // Values of every kind a render gives: 0, small, large, a gradient.
    std::vector<float> rgb(std::size_t(width) * height * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = i % 7 == 0 ? 0.0f : float(i) * 0.37f;
    std::vector<unsigned short> half_bits(rgb.size(), 0x3c00);  // 1.0 in half
    const bool is_float = type == Imf::FLOAT;
    const std::size_t size = is_float ? sizeof(float) : sizeof(unsigned short);
    char* base = is_float ? reinterpret_cast<char*>(rgb.data()) : reinterpret_cast<char*>(half_bits.data());
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c)
        frame.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
                     Imf::Slice::Make(type, base + c * size, window, 3 * size, 3 * size * std::size_t(width)));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s DIRECTORY\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    const std::pair<Imf::Compression, const char*> compressions[] = {
        {Imf::NO_COMPRESSION, "none"}, {Imf::RLE_COMPRESSION, "rle"}, {Imf::ZIPS_COMPRESSION, "zips"}, {Imf::ZIP_COMPRESSION, "zip"}};
    const std::pair<int, int> sizes[] = {{1, 1}, {4, 2}, {3, 17}};
    int n = 0;
    for (const auto& [compression, name] : compressions)
        for (const auto& [w, h] : sizes) {
            const std::string stem = dir + "/" + name + "-" + std::to_string(w) + "x" + std::to_string(h);
            write(stem + "-part.exr", w, h, compression, Imf::FLOAT, true);
            write(stem + "-half.exr", w, h, compression, Imf::HALF, false);
            n += 2;
        }
    write(dir + "/zip-window-offset.exr", 3, 2, Imf::ZIP_COMPRESSION, Imf::FLOAT, true, -5, 7);
    std::printf("%d files in %s\n", n + 1, dir.c_str());
    return 0;
}
