// `lancer combine` against hostile parts (issue 42): forged OpenEXR headers and attributes, parts
// of different renders, and outputs that would overwrite a part. Each is one message, exit
// code 2, and no output file.
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>
#include <unistd.h>

#include "image/image.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

std::string forged_dir() {
    std::string dir = test::output_dir() + "/combine-forged";
    fs::create_directories(dir);
    return dir;
}

// A valid stamp: what lancer render writes for a part, as far as combine compares it.
ExrInfo part_info(int first, int passes, int total = 6) {
    ExrInfo info{first, passes, total, {}};
    info.scene_hash = "0123456789abcdef";
    info.settings = "lancer 0.1.0\nbackend cpu\nsize 4x2\nsamples 2\n";
    return info;
}

// Writes a 4x2 part (pixels 1) and returns its path; made while the cases are listed.
std::string part(const std::string& name, const ExrInfo& info) {
    std::string path = forged_dir() + "/" + name + ".exr";
    FloatImage image(4, 2);
    for (auto& p : image.pixels) p = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
    write_exr(path, image, info);
    return path;
}

ExrInfo with_exposure(ExrInfo info, double exposure) {
    info.tone.exposure = exposure;
    return info;
}

// A valid part with some bytes of its header replaced: `at` (a string in the header) found,
// then `offset` bytes after its start overwritten by `bytes`. Every test process makes the
// files as it starts (ctest -j runs several at once): the valid part goes to a name of this
// process's own, and the patched one into place atomically, so no process ever reads a file
// half written or not yet patched.
std::string patched_part(const std::string& name, const std::string& at, std::size_t offset, const std::string& bytes) {
    std::string valid = part(name + "-valid-" + std::to_string(::getpid()), part_info(0, 3));
    std::string data = test::read_file(valid);
    fs::remove(valid);
    std::size_t where = data.find(at);
    if (where == std::string::npos) throw std::runtime_error(at + " not in the header");
    data.replace(where + offset, bytes.size(), bytes);
    std::string path = forged_dir() + "/" + name + ".exr";
    write_file_atomically(path, data.data(), data.size());
    return path;
}

std::string le32(std::int32_t v) {
    std::string s(4, '\0');
    std::memcpy(s.data(), &v, 4);
    return s;
}

// The data window (box2i: min x, min y, max x, max y after the attribute's name, type and size).
std::string window_part(const std::string& name, int width, int height) {
    const std::string at = std::string("dataWindow\0box2i\0", 17);
    return patched_part(name, at, at.size() + 4 + 8, le32(width - 1) + le32(height - 1));
}

const std::string kSecond = part("second", part_info(3, 3));

using Case = test::RejectedCommand;

class CombineRejects : public testing::TestWithParam<Case> {};

TEST_P(CombineRejects, WithExitCode2AndOneMessageAndNoOutput) {
    const Case& c = GetParam();
    const std::string out = test::output_dir() + "/combine-rejected-" + c.name + ".png";
    fs::remove(out);
    test::expect_refused(c.args, c.env, c.message, out);
}

Case combine(const std::string& name, const std::string& first, const std::string& message, const std::string& more = "") {
    return Case{name, "combine " + first + " " + kSecond + more + " -o OUT", "", message};
}

std::string cannot_read(const std::string& path) { return "lancer: error: cannot read OpenEXR '" + path + "': "; }

const std::string kNan = part("exposure-nan", with_exposure(part_info(0, 3), std::nan("")));
const std::string kInf = part("exposure-inf", with_exposure(part_info(0, 3), INFINITY));
const std::string kThousand = part("exposure-1000", with_exposure(part_info(0, 3), 1000.0));
const std::string kBright = part("exposure-1", with_exposure(part_info(0, 3), 1.0));
const std::string kOverflow = part("passes-overflow", part_info(INT_MAX - 1, 3));
const std::string kNegative = part("passes-negative", part_info(-2147483647, 3));
const std::string kHugeTotal = part("passes-huge-total", part_info(0, 3, INT_MAX));
const std::string kBeyondTotal = part("passes-beyond-total", part_info(4, 3));
ExrInfo unstamped() {
    ExrInfo info = part_info(0, 3);
    info.scene_hash.clear();
    info.settings.clear();
    return info;
}
const std::string kUnstamped = part("unstamped", unstamped());
ExrInfo other_samples() {
    ExrInfo info = part_info(0, 3);
    info.settings = "lancer 0.1.0\nbackend cpu\nsize 4x2\nsamples 1\n";
    return info;
}
const std::string kOtherSamples = part("other-samples", other_samples());
ExrInfo other_scene() {
    ExrInfo info = part_info(0, 3);
    info.scene_hash = "fedcba9876543210";
    return info;
}
const std::string kOtherScene = part("other-scene", other_scene());
const std::string kHugeWindow = window_part("window-9000", 9000, 9000);
const std::string kLargestSide = window_part("window-16384", 16384, 16384);
const std::string kClaims16Mpx = window_part("window-4096", 4096, 4096);
// The channel list B, G, R with R renamed Y (still sorted): entries are a name and 16 bytes.
const std::string kChannelY = patched_part("channels-bgy", std::string("channels\0chlist\0", 16), 16 + 4 + 2 * 18, "Y");
const std::string kPiz = patched_part("compression-piz", std::string("compression\0compression\0", 24), 24 + 4, std::string(1, '\4'));
// The version field's flags (after the magic number): tiled (0x200), multi-part (0x1000).
const std::string kTiled = patched_part("tiled", "\x76\x2f\x31\x01", 5, "\x02");
const std::string kMultiPart = patched_part("multi-part", "\x76\x2f\x31\x01", 5, "\x10");
const std::string kAttributeTooLarge = patched_part("attribute-size", std::string("lancerTone\0string\0", 18), 18, le32(1 << 30));

INSTANTIATE_TEST_SUITE_P(
    Cases, CombineRejects,
    testing::Values(
        combine("exposure_nan", kNan,
                cannot_read(kNan) + "its lancerExposure attribute is nan, not a finite number of stops in [-64, 64]"),
        combine("exposure_inf", kInf, cannot_read(kInf) + "its lancerExposure attribute is inf, not a finite number"),
        combine("exposure_1000", kThousand, cannot_read(kThousand) + "its lancerExposure attribute is 1000, not a finite number"),
        combine("exposures_disagree", kBright,
                "lancer: error: '" + kSecond + "' (exposure 0, tone clamp, assumed gamma 1) and '" + kBright +
                    "' (exposure 1, tone clamp, assumed gamma 1) disagree on the picture's exposure, tone curve or gamma"),
        combine("exposure_option_nan", kBright, "lancer: error: --exposure: the exposure must be a finite number of stops",
                " --exposure nan"),
        combine("exposure_option_inf", kBright, "lancer: error: --exposure: the exposure must be a finite number of stops",
                " --exposure -inf"),
        combine("passes_overflow", kOverflow, "lancer: error: '" + kOverflow + "' claims passes 2147483646 to 2147483648 of 6"),
        combine("passes_negative", kNegative, "lancer: error: '" + kNegative + "' claims passes -2147483647 to -2147483645 of 6"),
        combine("passes_huge_total", kHugeTotal,
                "lancer: error: '" + kHugeTotal + "' claims passes 0 to 2 of 2147483647: a part holds 1 or more of the passes "
                "0 to K - 1, K at most 1048576"),
        combine("passes_beyond_total", kBeyondTotal, "lancer: error: '" + kBeyondTotal + "' claims passes 4 to 6 of 6"),
        combine("unstamped", kUnstamped,
                "lancer: error: '" + kUnstamped + "' has no stamp of its render (lancerSceneHash, lancerSettings)"),
        combine("other_samples", kOtherSamples,
                "lancer: error: '" + kSecond + "' and '" + kOtherSamples + "' are parts of different renders: samples 2 against 1"),
        combine("other_scene", kOtherScene,
                "lancer: error: '" + kSecond + "' and '" + kOtherScene +
                    "' are parts of different renders: the scene or a file it reads differs (hash 0123456789abcdef against "
                    "fedcba9876543210)"),
        combine("window_9000", kHugeWindow,
                cannot_read(kHugeWindow) +
                    "its data window is 9000x9000, beyond the limit of 16384 pixels a side and 67108864 in all"),
        combine("window_16384", kLargestSide, cannot_read(kLargestSide) + "its data window is 16384x16384, beyond the limit"),
        combine("window_4096_in_a_small_file", kClaims16Mpx,
                cannot_read(kClaims16Mpx) + "its " + std::to_string(fs::file_size(kClaims16Mpx)) +
                    " bytes cannot hold the 4096x4096 pixels its header claims (at least 195084 bytes)"),
        combine("channels", kChannelY, cannot_read(kChannelY) + "it has the channels B, G, Y, not R, G and B"),
        combine("compression", kPiz, cannot_read(kPiz) + "lancer reads uncompressed, RLE and ZIP compressed OpenEXR"),
        combine("attribute_size", kAttributeTooLarge,
                cannot_read(kAttributeTooLarge) + "its attribute lancerTone claims 1073741824 bytes, more than the file holds"),
        combine("tiled", kTiled, cannot_read(kTiled) + "lancer reads single-part scanline images"),
        combine("multi_part", kMultiPart, cannot_read(kMultiPart) + "lancer reads single-part scanline images"),
        Case{"not_exr", "combine " + test::source_path("scenes/seed.toml") + " " + kSecond + " -o OUT", "",
             cannot_read(test::source_path("scenes/seed.toml")) + "not an OpenEXR file"},
        Case{"part_missing", "combine /nonexistent/part.exr " + kSecond + " -o OUT", "",
             cannot_read("/nonexistent/part.exr") + "No such file or directory"}),
    [](const auto& info) { return info.param.name; });

// `combine A B C -o A` would replace a part with the picture: refused, the part unchanged.
TEST(Combine, RefusesToWriteOverAPart) {
    std::string dir = test::fresh_dir("over-a-part");
    std::string a = dir + "/a.exr", b = dir + "/b.exr";
    fs::copy_file(part("over-a", part_info(0, 3)), a);
    fs::copy_file(kSecond, b);
    const std::string before = test::read_file(a);
    auto ok = test::run_lancer("combine " + a + " " + b + " -o " + dir + "/whole.exr");
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    for (const std::string& output : {a, b, dir + "/./a.exr"}) {
        auto r = test::run_lancer("combine " + a + " " + b + " -o " + output);
        EXPECT_EQ(r.exit_code, 2) << output;
        EXPECT_NE(r.err.find("lancer: error: cannot write '" + output + "': it is "), std::string::npos) << r.err;
    }
    fs::create_hard_link(a, dir + "/link.exr");
    auto linked = test::run_lancer("combine " + a + " " + b + " -o " + dir + "/link.exr");
    EXPECT_EQ(linked.exit_code, 2);
    EXPECT_NE(linked.err.find("it is the input '" + a + "'"), std::string::npos) << linked.err;
    EXPECT_EQ(test::read_file(a), before);
}

// Real parts of small.toml (6 passes): parts of the same render combine, wherever the scene's
// copy lies; a part of another render (other photons, backend, or an edited scene: what the farm
// recipe, which skips parts that exist, would otherwise mix) is refused, naming both parts and
// what differs.
TEST(Combine, RefusesPartsOfDifferentRenders) {
    std::string dir = test::fresh_dir("different-renders");
    const std::string text = test::read_file(test::source_path("tests/data/photons/small.toml"));
    test::write_file(dir + "/scene.toml", text);
    fs::create_directories(dir + "/elsewhere");
    test::write_file(dir + "/elsewhere/scene.toml", text);
    std::string edited = text;
    ASSERT_NE(edited.find("power = 30"), std::string::npos);
    edited.replace(edited.find("power = 30"), 10, "power = 31");
    test::write_file(dir + "/edited.toml", edited);
    auto render = [&](const std::string& scene, const std::string& range, const std::string& out, const std::string& more) {
        auto r = test::run_lancer("render " + dir + "/" + scene + " -q --pass-range " + range + more + " -o " + dir + "/" + out);
        EXPECT_EQ(r.exit_code, 0) << r.err;
    };
    render("scene.toml", "0-2", "a.exr", " --backend cpu");
    render("elsewhere/scene.toml", "3-5", "b.exr", " --backend cpu");
    render("scene.toml", "3-5", "photons.exr", " --backend cpu --photons 2000");
    render("edited.toml", "3-5", "edited.exr", " --backend cpu");
    render("scene.toml", "3-5", "gpu.exr", "");
    auto same = test::run_lancer("combine " + dir + "/a.exr " + dir + "/b.exr -o " + dir + "/whole.png");
    EXPECT_EQ(same.exit_code, 0) << same.err;
    const std::pair<const char*, std::string> cases[] = {
        {"photons.exr", "photons 2000 per pass, 6 passes"},
        {"edited.exr", "the scene or a file it reads differs"},
        {"gpu.exr", "backend gpu against cpu"},
    };
    for (const auto& [other, why] : cases) {
        std::string out = dir + "/mixed.png";
        auto r = test::run_lancer("combine " + dir + "/a.exr " + dir + "/" + other + " -o " + out);
        EXPECT_EQ(r.exit_code, 2) << other;
        EXPECT_EQ(r.err.rfind("lancer: error: '" + dir + "/" + other + "' and '" + dir + "/a.exr' are parts of different renders: ", 0), 0u)
            << r.err;
        EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
        EXPECT_FALSE(test::file_exists(out));
    }
}

}  // namespace
}  // namespace lancer
