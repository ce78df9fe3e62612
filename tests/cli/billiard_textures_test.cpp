// The billiard-ball textures in scenes/textures/ are what scenes/tools/make_billiard_textures
// draws, byte for byte: the committed images can always be made again from the source.
#include <filesystem>

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

TEST(BilliardTextures, TheGeneratorRecreatesTheCommittedImages) {
    fs::path dir = fs::path(test::output_dir()) / "billiard-textures";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string command = std::string(LANCER_BILLIARD_TOOL) + " " + dir.string() + " >/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    int compared = 0;
    for (const auto& entry : fs::directory_iterator(test::source_path("scenes/textures"))) {
        if (entry.path().extension() != ".png") continue;
        fs::path made = dir / entry.path().filename();
        ASSERT_TRUE(fs::exists(made)) << entry.path().filename() << " is not made by the generator";
        EXPECT_TRUE(test::read_file(made.string()) == test::read_file(entry.path().string()))
            << entry.path().filename() << " differs from the generator's output";
        ++compared;
    }
    int made = 0;
    for (const auto& entry : fs::directory_iterator(dir)) made += entry.path().extension() == ".png";
    EXPECT_EQ(compared, made) << "the generator makes images that are not committed";
    EXPECT_GE(compared, 4);
}

}  // namespace
}  // namespace lancer
