// What lancer's caches read their files with (read_regular_file_nonblocking) and key and check
// their entries by (SHA-256 through OpenSSL), and the shader directory's reads, which a cache
// entry's manifest drives.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "core/file_reading.hpp"
#include "core/sha256.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// FIPS 180-2's examples.
TEST(Sha256, KnownAnswers) {
    EXPECT_EQ(to_hex(sha256("")), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(to_hex(sha256("abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    Sha256 pieces;
    pieces.add("abcdbcdecdefdefgefghfghighijhijk").add("ijkljklmklmnlmnomnopnopq");
    EXPECT_EQ(to_hex(pieces.finish()), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, FieldsAreFramedByTheirLength) {
    Sha256 ab_c, a_bc;
    ab_c.add_field("ab").add_field("c");
    a_bc.add_field("a").add_field("bc");
    EXPECT_NE(ab_c.finish(), a_bc.finish());
}

class CacheFileReading : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::fresh_dir("cache-file-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::ofstream(dir_ + "/file", std::ios::binary) << "twelve bytes";
    }
    std::string dir_;
};

TEST_F(CacheFileReading, ARegularFileWithinTheBoundIsRead) {
    EXPECT_EQ(read_regular_file_nonblocking(dir_ + "/file", 12), "twelve bytes");
    EXPECT_EQ(read_regular_file_nonblocking(dir_ + "/file", 1 << 20), "twelve bytes");
    std::ofstream(dir_ + "/empty");
    EXPECT_EQ(read_regular_file_nonblocking(dir_ + "/empty", 0), "");
}

TEST_F(CacheFileReading, AnythingElseIsNothingAtOnce) {
    EXPECT_FALSE(read_regular_file_nonblocking(dir_ + "/file", 11)) << "larger than the bound";
    EXPECT_FALSE(read_regular_file_nonblocking(dir_ + "/missing", 100));
    EXPECT_FALSE(read_regular_file_nonblocking(dir_, 100)) << "a directory";
    ASSERT_EQ(::mkfifo((dir_ + "/fifo").c_str(), 0600), 0);
    EXPECT_FALSE(read_regular_file_nonblocking(dir_ + "/fifo", 100)) << "a FIFO (without a writer: no wait)";
    EXPECT_FALSE(read_regular_file_nonblocking("/dev/zero", 100)) << "a device";
    std::filesystem::create_symlink(dir_ + "/file", dir_ + "/link");
    EXPECT_FALSE(read_regular_file_nonblocking(dir_ + "/link", 100)) << "a symbolic link";
    EXPECT_EQ(read_regular_file_nonblocking(dir_ + "/link", 100, Links::follow), "twelve bytes");
    std::filesystem::create_symlink(dir_ + "/fifo", dir_ + "/link-to-fifo");
    EXPECT_FALSE(read_regular_file_nonblocking(dir_ + "/link-to-fifo", 100, Links::follow));
}

// A shader directory's tree reads the names a cache entry's manifest lists: a FIFO or device
// there is a file not found, not a wait.
TEST_F(CacheFileReading, AShaderDirectoryTreeReadsOnlyRegularFiles) {
    const gpu::ShaderTree tree = gpu::directory_tree(dir_);
    EXPECT_EQ(tree("file"), "twelve bytes");
    ASSERT_EQ(::mkfifo((dir_ + "/fifo.glsl").c_str(), 0600), 0);
    EXPECT_FALSE(tree("fifo.glsl"));
    EXPECT_FALSE(tree("../../../../../../../../../dev/zero"));
    std::filesystem::create_directory(dir_ + "/sub");
    EXPECT_FALSE(tree("sub"));
}

}  // namespace
}  // namespace lancer
