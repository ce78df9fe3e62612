// Reading patch files (host/surface/patch_file): the pinned teapot in both formats, the format
// details, and every error with its exact file:line:col.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "unit/bezier_test_support.hpp"

namespace lancer::surface {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::uint64_t fnv1a64(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
    return h;
}

// scenes/teapot.bpt is data that tests depend on: any change to it must be deliberate.
// (FNV-1a 64 of the bytes; sha256 2e1418b2420722fb2175adba3b1587c3472d4e39f87eb1ba931e11c65ab6c807.)
TEST(PatchFile, TeapotFileIsPinned) {
    EXPECT_EQ(fnv1a64(slurp(test::source_path("scenes/teapot.bpt"))), 0xdf75b21b86889a21ull);
}

TEST(PatchFile, TeapotHasNewellsShape) {
    const auto& t = test::teapot();
    ASSERT_EQ(t.size(), 32u);
    PatchBounds all = bounds(t[0]);
    for (const BezierPatch& p : t) {
        EXPECT_FALSE(is_rational(p));
        PatchBounds b = bounds(p);
        all.min = glm::min(all.min, b.min);
        all.max = glm::max(all.max, b.max);
    }
    EXPECT_EQ(all.min, dvec3(-3.0, -2.0, 0.0));
    EXPECT_EQ(all.max, dvec3(3.525, 2.0, 3.15));
    for (int j = 0; j < 4; ++j) {
        EXPECT_EQ(control_point(t[0], 0, j).z, 2.4);               // the rim
        EXPECT_EQ(control_point(t[20], 0, j), dvec3(0, 0, 3.15));  // the lid apex
        EXPECT_EQ(control_point(t[28], 0, j), dvec3(0, 0, 0));     // the bottom centre
    }
    EXPECT_EQ(evaluate(t[0], 0, 0), dvec3(1.4, 0, 2.4));
}

TEST(PatchFile, BothFormatsReadTheSameTeapot) {
    auto newell = read_patch_file(test::source_path("tests/data/teapot.newell"));
    const auto& bpt = test::teapot();
    ASSERT_EQ(newell.size(), bpt.size());
    for (std::size_t k = 0; k < bpt.size(); ++k) {
        EXPECT_EQ(newell[k].points, bpt[k].points) << "patch " << k + 1;
        EXPECT_EQ(newell[k].weights, bpt[k].weights);
    }
}

std::string bpt_patch(const std::string& fourth = "") {
    std::string s = "3 3\n";
    for (int k = 0; k < 16; ++k) s += std::to_string(k / 4) + " " + std::to_string(k % 4) + " 0" + fourth + "\n";
    return s;
}

TEST(PatchFile, ReadsWeightsCommentsCrLfAndSigns) {
    std::string text = "# a comment line\r\n  1   # one patch\r\n3 3\r\n";
    for (int k = 0; k < 16; ++k)
        text +=
            "+" + std::to_string(k / 4) + "\t" + std::to_string(k % 4) + " -0.5e0 " + (k == 5 ? "2.5" : "1") + "\r\n";
    text += "\r\n# trailing comment\r\n";
    auto patches = parse_patch_text(text, "inline.bpt");
    ASSERT_EQ(patches.size(), 1u);
    EXPECT_EQ(patches[0].points[6], dvec3(1, 2, -0.5));
    EXPECT_EQ(patches[0].weights[5], 2.5);
    EXPECT_EQ(patches[0].weights[4], 1.0);
    EXPECT_TRUE(is_rational(patches[0]));
}

TEST(PatchFile, MissingWeightsMeanPolynomial) {
    auto patches = parse_patch_text("1\n" + bpt_patch(), "inline.bpt");
    ASSERT_EQ(patches.size(), 1u);
    EXPECT_FALSE(is_rational(patches[0]));
    EXPECT_EQ(patches[0].points[15], dvec3(3, 3, 0));
}

TEST(PatchFile, UnreadableFilesAreSceneErrorsNamingTheFile) {
    // The reason alone: the scene loader puts it after "cannot read patch file 'NAME'".
    for (auto [path, reason] : {std::pair{std::string("/nonexistent/teapot.bpt"), std::string("No such file or directory")},
                                std::pair{test::source_path("scenes"), std::string("it is a directory")}}) {
        try {
            read_patch_file(path);
            FAIL() << path << " was read";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().file.str(), path);
            EXPECT_EQ(format_error(e), path + ": error: " + reason);
        }
    }
}

// Each file in tests/data/bad_patches/ starts with "# expect: LINE:COL: error: MESSAGE"; reading
// it must fail with exactly that location and message.
class BadPatchFile : public testing::TestWithParam<std::string> {};

TEST_P(BadPatchFile, FailsWithTheExpectedLocationAndMessage) {
    const std::string path = GetParam();
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    const std::string tag = "# expect: ";
    ASSERT_EQ(first.rfind(tag, 0), 0u) << path << " lacks an expect line";
    const std::string expected = path + ":" + first.substr(tag.size());
    try {
        read_patch_file(path);
        FAIL() << path << " was read without error";
    } catch (const SceneError& e) {
        EXPECT_EQ(format_error(e), expected);
    }
}

std::vector<std::string> bad_patch_files() {
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(test::source_path("tests/data/bad_patches")))
        paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

INSTANTIATE_TEST_SUITE_P(Data, BadPatchFile, testing::ValuesIn(bad_patch_files()), [](const auto& info) {
    std::string name = std::filesystem::path(info.param).filename().string();
    std::replace(name.begin(), name.end(), '.', '_');
    return name;
});

}  // namespace
}  // namespace lancer::surface
