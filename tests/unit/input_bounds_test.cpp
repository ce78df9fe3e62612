// Bounds on what untrusted input can make lancer do before it allocates: image files
// whose data is far more than their header says (decompression bombs), shader trees whose
// includes never end, output names at the file system's limit, names with control characters.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/escape.hpp"
#include "core/temporary_name.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "image/image.hpp"
#include "image/image_file.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

std::string be32(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
    return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc32(type + data));
}

// A zlib stream of about `bytes` bytes that inflates to 258 bytes for every 13 bits (about 160
// times its size): one fixed-Huffman block, a literal 0, then copies of 258 bytes at distance 1.
std::string zlib_bomb(std::size_t bytes) {
    std::string out = "\x78\x01";
    std::uint64_t bits = 0;
    int count = 0;
    auto put = [&](std::uint32_t value, int n) {  // LSB first
        bits |= std::uint64_t(value) << count;
        count += n;
        while (count >= 8) {
            out += char(bits & 0xff);
            bits >>= 8;
            count -= 8;
        }
    };
    // Huffman codes are sent most significant bit first: reverse them into the LSB-first stream.
    auto code = [&](std::uint32_t c, int n) {
        std::uint32_t r = 0;
        for (int i = 0; i < n; ++i) r |= ((c >> i) & 1u) << (n - 1 - i);
        put(r, n);
    };
    put(0, 1);           // BFINAL = 0: the stream never says it ends
    put(1, 2);           // fixed Huffman
    code(0x30, 8);       // literal 0
    while (out.size() < bytes) {
        code(0xc5, 8);   // length 258 (symbol 285)
        code(0, 5);      // distance 1
    }
    return out;
}

std::string png(int width, int height, const std::string& idat) {
    std::string ihdr = be32(width) + be32(height) + std::string("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) + chunk("IEND", "");
}

std::string write(const std::string& name, const std::string& bytes) {
    std::string path = test::fresh_dir("input-bounds") + "/" + name;
    test::write_file(path, bytes);
    return path;
}

// A 3 MB PNG whose header says 1x1 would inflate to ~500 MB: refused from its compressed size
// before anything is decoded.
TEST(ImageBounds, ADecompressionBombIsRefusedByItsCompressedSize) {
    std::string path = write("bomb.png", png(1, 1, zlib_bomb(3'000'000)));
    try {
        read_png(path);
        FAIL() << "the bomb was read";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("more than a 1x1 PNG can need"), std::string::npos) << e.what();
    }
}

// Within the compressed size a 64x64 image can need, a bomb still inflates to far more than
// the image: the decoder's memory is capped, and it stops with a message.
TEST(ImageBounds, DecodingIsCappedByTheHeadersSize) {
    std::uint64_t need = png_max_compressed_bytes(png(64, 64, ""));
    std::string path = write("small-bomb.png", png(64, 64, zlib_bomb(need - 64)));
    try {
        read_png(path);
        FAIL() << "the bomb was decoded";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("decodes to more than a 64x64 image holds"), std::string::npos) << e.what();
    }
}

TEST(ImageBounds, AnImageAboveTheLimitsIsRefusedFromItsHeader) {
    std::string path = write("huge.png", png(20000, 10, zlib_bomb(100)));
    try {
        read_png(path);
        FAIL();
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("20000x10 pixels; the limit is 16384 on each side"), std::string::npos)
            << e.what();
    }
}

gpu::ShaderTree tree(std::map<std::string, std::string> files) {
    return [files](const std::string& name) -> std::optional<std::string> {
        auto it = files.find(name);
        if (it == files.end()) return std::nullopt;
        return it->second;
    };
}

TEST(ShaderIncludes, ACycleIsAnErrorNamingTheChain) {
    auto files = tree({{"main.comp", "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"a.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n"},
                       {"a.glsl", "#include \"b.glsl\"\n"},
                       {"b.glsl", "#include \"a.glsl\"\n"}});
    try {
        gpu::compile_compute(files, "main.comp");
        FAIL() << "compiled";
    } catch (const gpu::ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("#include cycle: main.comp -> a.glsl -> b.glsl -> a.glsl"), std::string::npos)
            << e.what();
    }
}

TEST(ShaderIncludes, AFileIncludingItselfIsACycle) {
    auto files = tree({{"main.comp", "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"main.comp\"\nvoid main() {}\n"}});
    try {
        gpu::compile_compute(files, "main.comp");
        FAIL() << "compiled";
    } catch (const gpu::ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("#include cycle: main.comp -> main.comp"), std::string::npos) << e.what();
    }
}

TEST(ShaderIncludes, NestingIsLimited) {
    std::map<std::string, std::string> files = {
        {"main.comp", "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"f0.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n"}};
    for (int i = 0; i < 40; ++i) files["f" + std::to_string(i) + ".glsl"] = "#include \"f" + std::to_string(i + 1) + ".glsl\"\n";
    files["f40.glsl"] = "\n";
    try {
        gpu::compile_compute(tree(files), "main.comp");
        FAIL() << "compiled";
    } catch (const gpu::ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("#include nested more than 32 deep: main.comp -> f0.glsl"), std::string::npos)
            << e.what();
    }
}

// A guarded header included twice (not a cycle) still compiles.
TEST(ShaderIncludes, TheSameFileTwiceIsNoCycle) {
    auto files = tree({{"main.comp", "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"a.glsl\"\n#include \"a.glsl\"\nlayout(local_size_x = 1) in;\n"
                                     "void main() {}\n"},
                       {"a.glsl", "#ifndef A\n#define A\n#endif\n"}});
    EXPECT_FALSE(gpu::compile_compute(files, "main.comp").empty());
}

TEST(TemporaryNames, FitTheFileSystemsLimitForAnyLegalName) {
    std::string dir = test::fresh_dir("temporary-names");
    for (std::size_t length : {5u, 200u, 247u, 248u, 254u, 255u}) {
        std::string name(length - 4, 'n');
        name += ".png";
        std::string temp = temporary_template(dir + "/" + name);
        std::string file = std::filesystem::path(temp).filename().string();
        EXPECT_LE(file.size(), 255u) << length;
        EXPECT_EQ(file.substr(file.size() - 7), ".XXXXXX");
        EXPECT_EQ(file[0], '.');
    }
}

TEST(Escape, ControlCharactersAreWrittenAsEscapes) {
    EXPECT_EQ(escape_control_characters(std::string("a\x1b[2Jb\r\n\t\0z\x7f", 12)), "a\\x1b[2Jb\\r\\n\\t\\0z\\x7f");
    EXPECT_EQ(escape_control_characters("line 1\nline 2", true), "line 1\nline 2");
    EXPECT_EQ(escape_control_characters("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 is kept
}

}  // namespace
}  // namespace lancer
