// Every file of the fuzz corpora (tests/fuzz/corpus/TARGET/) and every reproducer of a bug the
// fuzzers found (tests/fuzz/regressions/TARGET/) goes through the fuzz targets' own entry
// points in the normal suite, so a regression fails here without a fuzzer, and under the
// sanitizer build with ASan and UBSan watching.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/fuzz_entries.hpp"
#include "gpu/shaders/spirv_cache.hpp"
#include "scene/scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

using Entry = void (*)(const std::uint8_t*, std::size_t);

struct Target {
    std::string name;
    Entry entry;
};

void PrintTo(const Target& t, std::ostream* os) { *os << t.name; }

std::vector<std::string> files_under(const fs::path& dir) {
    std::vector<std::string> files;
    if (!fs::is_directory(dir)) return files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && e.path().filename().string().front() != '.') files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::uint8_t> bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs every file; returns how many there were.
std::size_t replay(const Target& t, const fs::path& dir) {
    std::vector<std::string> files = files_under(dir);
    for (const std::string& file : files) {
        std::vector<std::uint8_t> data = bytes_of(file);
        try {
            t.entry(data.data(), data.size());
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << ": " << e.what();
        }
    }
    return files.size();
}

const fs::path kFuzzDir = fs::path(LANCER_SOURCE_DIR) / "tests" / "fuzz";

class FuzzReplay : public testing::TestWithParam<Target> {};

TEST_P(FuzzReplay, EveryCorpusFileIsAcceptedOrRejectedCleanly) {
    // The corpora are seeded from scenes/ and the tests' bad inputs, then minimised: never empty.
    EXPECT_GE(replay(GetParam(), kFuzzDir / "corpus" / GetParam().name), 20u) << "the corpus is missing or tiny";
}

TEST_P(FuzzReplay, EveryReproducerOfAFixedBugStaysFixed) {
    replay(GetParam(), kFuzzDir / "regressions" / GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         testing::Values(Target{"scene", fuzz::scene_entry}, Target{"expression", fuzz::expression_entry},
                                         Target{"patch", fuzz::patch_entry},
                                         Target{"cache_entry", fuzz::cache_file_entry},
                                         Target{"exr_part", fuzz::exr_part_entry}, Target{"obj", fuzz::obj_entry},
                                         Target{"ply", fuzz::ply_entry}),
                         [](const auto& info) { return info.param.name; });

// The invariants the scene target checks can fail: a scene the loader would never accept.
TEST(FuzzInvariants, BreakOnANonFiniteOrDegenerateScene) {
    Scene scene = test::scene_from_text("[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n"
                                        "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n");
    EXPECT_NO_THROW(fuzz::check_scene_invariants(scene, "as loaded"));
    Scene nan_radius = scene;
    std::get<Sphere>(nan_radius.objects[0].shape).radius = std::nan("");
    EXPECT_THROW(fuzz::check_scene_invariants(nan_radius, "NaN radius"), fuzz::InvariantBroken);
    Scene nan_center = scene;
    std::get<Sphere>(nan_center.objects[0].shape).center.y = std::nan("");
    try {  // the message is put together only on failure: it still says where and what
        fuzz::check_scene_invariants(nan_center, "frame 7");
        ADD_FAILURE() << "a NaN centre passed";
    } catch (const fuzz::InvariantBroken& broken) {
        EXPECT_STREQ(broken.what(), "frame 7: sphere is not finite");
    }
    Scene blind = scene;
    blind.camera.look_at = blind.camera.eye;
    EXPECT_THROW(fuzz::check_scene_invariants(blind, "no view direction"), UserError);
    Scene dangling = scene;
    dangling.objects[0].material = 99;
    EXPECT_THROW(fuzz::check_scene_invariants(dangling, "material index"), fuzz::InvariantBroken);
}

// The seeds of the cache entry target (tests/fuzz/cache_entry_seeds.py writes them in the cache's
// format): the well-formed ones are hits, so the fuzzer starts past the checksum.
TEST(FuzzCacheEntrySeeds, TheWellFormedSeedsAreHits) {
    const Sha256Digest key = sha256("lancer fuzz: the key looked up");
    const std::string dir = test::fresh_dir("fuzz-cache-entry-seeds");
    auto entry = [&](const std::string& seed) {
        const std::vector<std::uint8_t> data = bytes_of((kFuzzDir / "corpus" / "cache_entry" / seed).string());
        const std::string path = dir + "/" + seed;
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data.data()) + 1, std::streamsize(data.size() - 1));
        return path;
    };
    const gpu::ShaderTree tree = [](const std::string& name) -> std::optional<std::string> {
        if (name == "main.comp") return "#version 450\n#include \"a.glsl\"\nvoid main() {}\n";
        if (name == "a.glsl") return "float a() { return 1.0; }\n";
        return std::nullopt;
    };
    const auto spv = gpu::cache_entry::read_specialization(entry("spv-good"), key);
    ASSERT_TRUE(spv);
    EXPECT_EQ(spv->size(), 5u);
    EXPECT_FALSE(gpu::cache_entry::read_specialization(entry("spv-bad-checksum"), key));
    const auto compiled = gpu::cache_entry::read_compiled(entry("gls-good"), key, tree);
    ASSERT_TRUE(compiled);
    EXPECT_EQ(compiled->size(), 4u);
    EXPECT_FALSE(gpu::cache_entry::read_compiled(entry("gls-stale-file"), key, tree));
}

}  // namespace
}  // namespace lancer
