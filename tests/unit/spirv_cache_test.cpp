// The disk cache of specialised tracer modules: a hit is used as it is, anything else (no entry,
// a damaged or foreign one, an unwritable directory, the cache switched off) gives exactly what
// specialising gives.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/shaders/spirv_cache.hpp"
#include "gpu/shaders/spirv_specialize.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

class SpirvCache : public ::testing::Test {
protected:
    void SetUp() override {
        // ctest runs each test in its own process, in parallel: one directory per test.
        const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ = test::fresh_dir("spirv-cache-" + name);
        ::setenv("LANCER_CACHE_DIR", dir_.c_str(), 1);
        ::unsetenv("LANCER_CACHE_DISABLE");
        features_.add_shape(SHAPE_SPHERE);
        features_.add_shape(SHAPE_PLANE);
    }
    void TearDown() override { ::unsetenv("LANCER_CACHE_DIR"); }

    std::vector<fs::path> entries() const {
        std::vector<fs::path> found;
        for (const auto& e : fs::directory_iterator(dir_)) found.push_back(e.path());
        return found;
    }

    std::string dir_;
    gpu::ShaderFeatures features_;
    const std::vector<std::uint32_t> spirv_ = gpu::embedded_trace_spirv();
};

TEST_F(SpirvCache, AMissIsSpecialisedAndStoredAHitIsReadBack) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    ASSERT_EQ(entries().size(), 1u);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_EQ(entries().size(), 1u);
    gpu::ShaderFeatures other = features_;
    other.add_shape(SHAPE_BOX);
    EXPECT_EQ(gpu::cached_specialization(spirv_, other), gpu::specialize_spirv(spirv_, other));
    EXPECT_EQ(entries().size(), 2u) << "one entry per feature set";
}

TEST_F(SpirvCache, EachCleanupHasItsOwnEntry) {
    using gpu::SpirvCleanup;
    const std::vector<std::uint32_t> dead_code = gpu::specialize_spirv(spirv_, features_, SpirvCleanup::dead_code);
    const std::vector<std::uint32_t> local = gpu::specialize_spirv(spirv_, features_, SpirvCleanup::local_variables);
    // What the cleanup is for: a module lavapipe's NIR passes go through faster.
    EXPECT_LT(local.size(), dead_code.size() * 3 / 4) << "the local-variable passes did not shrink the module";
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_, SpirvCleanup::dead_code), dead_code);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_, SpirvCleanup::local_variables), local);
    EXPECT_EQ(entries().size(), 2u);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_, SpirvCleanup::dead_code), dead_code);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_, SpirvCleanup::local_variables), local);
}

TEST(SpirvCleanupChoice, BezierAndParametricSurfacesKeepTheDeadCodeCleanup) {
    using gpu::SpirvCleanup;
    gpu::ShaderFeatures spheres;
    spheres.add_shape(SHAPE_SPHERE);
    EXPECT_EQ(gpu::spirv_cleanup_for(spheres), SpirvCleanup::local_variables);
    for (std::uint32_t type : {SHAPE_BEZIER, SHAPE_PARAMETRIC}) {
        gpu::ShaderFeatures with = spheres;
        with.add_shape(type);
        EXPECT_EQ(gpu::spirv_cleanup_for(with), SpirvCleanup::dead_code) << shape_name(type);
    }
    gpu::ShaderFeatures implicit = spheres;
    implicit.add_shape(SHAPE_IMPLICIT);
    EXPECT_EQ(gpu::spirv_cleanup_for(implicit), SpirvCleanup::local_variables);
}

// Specialisation leaves no constant unfolded: every condition on the features (shape flags
// derived from the sets, CHEAP_SHAPES, SHADOW_HINTS) becomes a plain constant, so the dead-branch
// passes remove what the scene lacks. An OpSpecConstantOp left behind (SPIRV-Tools cannot fold
// every form) would keep that code in lavapipe's pipeline, or leave an invalid module.
std::size_t spec_constants_left(const std::vector<std::uint32_t>& spirv) {
    std::size_t left = 0;
    for (std::size_t i = 5; i < spirv.size();) {
        const std::uint32_t opcode = spirv[i] & 0xffffu, words = spirv[i] >> 16;
        left += opcode >= 48 && opcode <= 52;  // OpSpecConstantTrue ... OpSpecConstantOp
        i += words ? words : 1;
    }
    return left;
}

TEST(SpirvSpecialisation, FoldsEveryConstantForEachCleanup) {
    const std::vector<std::uint32_t> spirv = gpu::embedded_trace_spirv();
    ASSERT_GT(spec_constants_left(spirv), 0u);
    gpu::ShaderFeatures spheres;
    spheres.add_shape(SHAPE_SPHERE);
    spheres.add_shape(SHAPE_PLANE);
    spheres.has_bvh = true;
    spheres.boxed_families = 1u << SHAPE_SPHERE;
    gpu::ShaderFeatures patches = spheres;
    patches.add_shape(SHAPE_BEZIER);
    for (const gpu::ShaderFeatures& f : {spheres, patches})
        for (gpu::SpirvCleanup cleanup : {gpu::SpirvCleanup::dead_code, gpu::SpirvCleanup::local_variables})
            EXPECT_EQ(spec_constants_left(gpu::specialize_spirv(spirv, f, cleanup)), 0u)
                << "shapes " << f.scene_shapes << ", cleanup " << int(cleanup);
}

// A module built with its locals as SSA values (the smaller tracers) needs only what the constants
// decide, and has no code for the shapes that keep their locals.
TEST(SpirvCleanupChoice, AModuleWithItsLocalsAsSsaValuesTakesTheConstantsCleanup) {
    using gpu::SpirvCleanup;
    gpu::ShaderFeatures spheres;
    spheres.add_shape(SHAPE_SPHERE);
    EXPECT_EQ(gpu::spirv_cleanup_for(spheres, true), SpirvCleanup::constants);
    gpu::ShaderFeatures patches = spheres;
    patches.add_shape(SHAPE_BEZIER);
    EXPECT_THROW(gpu::spirv_cleanup_for(patches, true), std::logic_error);
    const gpu::EmbeddedModule cheap = gpu::embedded_module(gpu::kTraceShader, spheres);
    ASSERT_TRUE(cheap.locals_in_ssa);
    const std::vector<std::uint32_t> constants = gpu::specialize_spirv(cheap.spirv, spheres, SpirvCleanup::constants);
    const std::vector<std::uint32_t> dead_code = gpu::specialize_spirv(cheap.spirv, spheres, SpirvCleanup::dead_code);
    EXPECT_EQ(spec_constants_left(constants), 0u);
    // What the constants decide once frozen: 20% fewer words for `seed` (17,660 against 21,919).
    EXPECT_LT(constants.size(), dead_code.size() * 9 / 10) << "the constant passes did not shrink the module";
}

// A hit is not specialised again: a well-formed entry for this key (right name, key and checksum)
// holding other valid words is what comes back. So the checksum is no signature: whoever can
// write the directory can make entries (docs/robustness.md).
TEST_F(SpirvCache, AWellFormedEntryIsUsedAsItIs) {
    gpu::ShaderFeatures other = features_;
    other.add_shape(SHAPE_BOX);
    const std::vector<std::uint32_t> stand_in = gpu::specialize_spirv(spirv_, other);
    ASSERT_NE(stand_in, gpu::specialize_spirv(spirv_, features_));
    const Sha256Digest key = gpu::cache_entry::specialization_key(spirv_, features_, gpu::SpirvCleanup::dead_code);
    const std::string bytes = gpu::cache_entry::encode_specialization(key, stand_in);
    std::ofstream(dir_ + "/tracer-" + to_hex(key) + ".spv", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), stand_in);
    EXPECT_EQ(entries().size(), 1u);
}

// Two feature sets whose 64-bit FNV-1a keys (the cache's key before issue 42) collide: a scene
// crafted to collide with another's must not get, or leave for it, the other's tracer.
TEST_F(SpirvCache, InputsWhoseWeakKeysCollideKeepTheirOwnEntries) {
    gpu::ShaderFeatures a = features_, b = features_;
    a.boxed_families = 0xecbe1c6au;  // found by Pollard's rho over (boxed_families, split_families)
    a.split_families = 0x71cc1a12u;
    b.boxed_families = 0xd0054817u;
    b.split_families = 0x40aa8249u;
    const std::vector<std::uint32_t> fresh_a = gpu::specialize_spirv(spirv_, a), fresh_b = gpu::specialize_spirv(spirv_, b);
    ASSERT_NE(fresh_a, fresh_b) << "spheres boxed in one, not in the other";
    EXPECT_EQ(gpu::cached_specialization(spirv_, a), fresh_a);
    EXPECT_EQ(gpu::cached_specialization(spirv_, b), fresh_b);
    EXPECT_EQ(gpu::cached_specialization(spirv_, a), fresh_a);
    EXPECT_EQ(entries().size(), 2u);
}

// A forged entry: another scene's entry (words, length, checksum) under this entry's name, with
// this entry's key written into its header. Before issue 42 the same splice of format 2's header
// (magic, input hash, features) was used as it was: a scene drew with another's tracer. The
// checksum covers the key, so it is specialised again.
TEST_F(SpirvCache, AnotherEntrysWordsUnderThisKeyAreSpecialisedAgain) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    gpu::cached_specialization(spirv_, features_);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    gpu::ShaderFeatures other = features_;
    other.add_shape(SHAPE_BOX);
    ASSERT_NE(gpu::specialize_spirv(spirv_, other), fresh);
    gpu::cached_specialization(spirv_, other);
    ASSERT_EQ(entries().size(), 2u);
    const fs::path other_entry = entries()[0] == entry ? entries()[1] : entries()[0];
    std::ifstream a(entry, std::ios::binary), b(other_entry, std::ios::binary);
    std::vector<char> mine((std::istreambuf_iterator<char>(a)), {}), theirs((std::istreambuf_iterator<char>(b)), {});
    std::copy(mine.begin() + 8, mine.begin() + 40, theirs.begin() + 8);  // the key, after the magic
    std::ofstream(entry, std::ios::binary | std::ios::trunc).write(theirs.data(), std::streamsize(theirs.size()));
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_EQ(fs::file_size(entry), mine.size()) << "written back";
}

// Where an entry would be read: a FIFO (opening it would wait for a writer), a symbolic link
// (here to a FIFO) or a directory. Each is a miss at once: the lookup returning shows it.
TEST_F(SpirvCache, AFifoLinkOrDirectoryAtAnEntrysPathIsAMiss) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    gpu::cached_specialization(spirv_, features_);
    const fs::path entry = entries().at(0);
    fs::remove(entry);
    ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(entry))) << "written back in the FIFO's place";

    const std::string pipe = dir_ + "/pipe";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    fs::remove(entry);
    fs::create_symlink(pipe, entry);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(entry))) << "the link replaced";
    EXPECT_EQ(fs::status(pipe).type(), fs::file_type::fifo) << "not what it pointed to";

    fs::remove(entry);
    fs::create_directory(entry);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
}

TEST_F(SpirvCache, DamagedOrTruncatedEntriesAreSpecialisedAgain) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    gpu::cached_specialization(spirv_, features_);
    const fs::path entry = entries().at(0);
    const auto size = fs::file_size(entry);
    {
        std::fstream f(entry, std::ios::binary | std::ios::in | std::ios::out);
        f.seekp(std::streamoff(size - 7));
        f.put('\x5a');  // one byte of the module
    }
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    fs::resize_file(entry, size / 2);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    fs::resize_file(entry, 3);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_EQ(fs::file_size(entry), size) << "written back whole";
}

// Editing shaders makes an entry per edit: the oldest go once there are 256.
TEST_F(SpirvCache, KeepsAtMost256EntriesTheNewestOnes) {
    const auto long_ago = fs::file_time_type::clock::now() - std::chrono::hours(24);
    for (int i = 0; i < 300; ++i) {
        const std::string old = dir_ + "/tracer-old-" + std::to_string(i) + ".spv";
        std::ofstream(old) << "an entry of another module";
        fs::last_write_time(old, long_ago + std::chrono::seconds(i));
    }
    gpu::cached_specialization(spirv_, features_);
    const std::vector<fs::path> kept = entries();
    EXPECT_EQ(kept.size(), 256u);
    EXPECT_FALSE(fs::exists(dir_ + "/tracer-old-44.spv"));
    EXPECT_TRUE(fs::exists(dir_ + "/tracer-old-45.spv"));
    EXPECT_EQ(std::count_if(kept.begin(), kept.end(), [](const fs::path& p) { return p.filename().string().rfind("tracer-old-", 0) != 0; }), 1);
}

TEST_F(SpirvCache, SwitchedOffOrUnwritableItStillSpecialises) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    ::setenv("LANCER_CACHE_DISABLE", "1", 1);
    EXPECT_FALSE(gpu::spirv_cache_directory());
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    EXPECT_TRUE(entries().empty());
    ::unsetenv("LANCER_CACHE_DISABLE");
    const std::string file = dir_ + "/a-file";
    std::ofstream(file) << "not a directory";
    ::setenv("LANCER_CACHE_DIR", (file + "/cache").c_str(), 1);
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
}

// A tree of two files: main.comp includes value.glsl, whose constant `value` the test edits.
struct TwoFileTree {
    std::string value = "1.0";
    int lookups = 0;
    gpu::ShaderTree tree() {
        return [this](const std::string& name) -> std::optional<std::string> {
            ++lookups;
            if (name == "main.comp")
                return "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"value.glsl\"\n"
                       "layout(local_size_x = 1) in;\nlayout(set = 0, binding = 0) buffer Out { float x; };\n"
                       "void main() { x = VALUE; }\n";
            if (name == "value.glsl") return "#define VALUE " + value + "\n";
            return std::nullopt;
        };
    }
};

TEST_F(SpirvCache, ACompileIsReusedWhileItsIncludedFilesAreUnchanged) {
    TwoFileTree files;
    const std::vector<std::uint32_t> one = gpu::compile_compute(files.tree(), "main.comp");
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), one);
    ASSERT_EQ(entries().size(), 1u);
    files.lookups = 0;
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), one);
    // The entry point for the key and for the manifest, its include for the manifest; a compile
    // would read both once more.
    EXPECT_EQ(files.lookups, 3) << "a hit reads the files, and compiles nothing";

    files.value = "2.0";  // an included file changed: compiled again, the new module kept
    const std::vector<std::uint32_t> two = gpu::compile_compute(files.tree(), "main.comp");
    ASSERT_NE(two, one);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), two);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), two);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp", {{"UNUSED", "1"}}),
              gpu::compile_compute(files.tree(), "main.comp", {{"UNUSED", "1"}}))
        << "defines are part of the key";
}

TEST_F(SpirvCache, EachSetOfGeneratedFilesKeepsItsOwnEntry) {
    // Two scenes' generated code standing in for the same included file, rendered in turn: each
    // compile is kept, neither replaces the other.
    TwoFileTree files;
    const gpu::ShaderFiles scene_a{{"value.glsl", "#define VALUE 4.0\n"}}, scene_b{{"value.glsl", "#define VALUE 5.0\n"}};
    const std::vector<std::uint32_t> a = gpu::compile_compute(gpu::with_files(files.tree(), scene_a), "main.comp");
    const std::vector<std::uint32_t> b = gpu::compile_compute(gpu::with_files(files.tree(), scene_b), "main.comp");
    ASSERT_NE(a, b);
    EXPECT_EQ(gpu::cached_compile(files.tree(), scene_a, "main.comp"), a);
    EXPECT_EQ(gpu::cached_compile(files.tree(), scene_b, "main.comp"), b);
    EXPECT_EQ(entries().size(), 2u);
    files.lookups = 0;
    EXPECT_EQ(gpu::cached_compile(files.tree(), scene_a, "main.comp"), a);
    EXPECT_EQ(gpu::cached_compile(files.tree(), scene_b, "main.comp"), b);
    EXPECT_EQ(files.lookups, 4) << "both were hits: the entry point twice each, the generated file not from the tree";
}

TEST_F(SpirvCache, AFailedCompileIsNotKeptAndADamagedEntryIsCompiledAgain) {
    TwoFileTree files;
    files.value = "not_declared";
    EXPECT_THROW(gpu::cached_compile(files.tree(), {}, "main.comp"), gpu::ShaderCompileError);
    EXPECT_TRUE(entries().empty());

    files.value = "3.0";
    const std::vector<std::uint32_t> fresh = gpu::compile_compute(files.tree(), "main.comp");
    gpu::cached_compile(files.tree(), {}, "main.comp");
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries().front();
    fs::resize_file(entry, fs::file_size(entry) - 4);  // torn
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), fresh);
    {
        std::fstream damaged(entry, std::ios::in | std::ios::out | std::ios::binary);
        damaged.seekp(std::streamoff(fs::file_size(entry) - 4));
        damaged.write("\x7f\x7f\x7f\x7f", 4);  // a word flipped
    }
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), fresh);
}

// A forged compile: another scene's compiled entry (manifest, words, checksum) under this one's
// name, with this one's key written into its header, is compiled again.
TEST_F(SpirvCache, AnotherCompilesEntryUnderThisKeyIsCompiledAgain) {
    TwoFileTree files;
    const gpu::ShaderFiles scene_a{{"value.glsl", "#define VALUE 4.0\n"}}, scene_b{{"value.glsl", "#define VALUE 5.0\n"}};
    const std::vector<std::uint32_t> a = gpu::compile_compute(gpu::with_files(files.tree(), scene_a), "main.comp");
    ASSERT_EQ(gpu::cached_compile(files.tree(), scene_a, "main.comp"), a);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    gpu::cached_compile(files.tree(), scene_b, "main.comp");
    ASSERT_EQ(entries().size(), 2u);
    const fs::path other_entry = entries()[0] == entry ? entries()[1] : entries()[0];
    std::ifstream in_a(entry, std::ios::binary), in_b(other_entry, std::ios::binary);
    std::vector<char> mine((std::istreambuf_iterator<char>(in_a)), {}), theirs((std::istreambuf_iterator<char>(in_b)), {});
    std::copy(mine.begin() + 8, mine.begin() + 40, theirs.begin() + 8);  // the key, after the magic
    std::ofstream(entry, std::ios::binary | std::ios::trunc).write(theirs.data(), std::streamsize(theirs.size()));
    EXPECT_EQ(gpu::cached_compile(files.tree(), scene_a, "main.comp"), a);
}

// An entry of an earlier format (FNV-1a keys) left in the directory is a miss, not an error.
TEST_F(SpirvCache, AnEntryOfTheEarlierFormatIsAMiss) {
    const std::vector<std::uint32_t> fresh = gpu::specialize_spirv(spirv_, features_);
    gpu::cached_specialization(spirv_, features_);
    const fs::path entry = entries().at(0);
    {
        std::fstream f(entry, std::ios::binary | std::ios::in | std::ios::out);
        f.write("lancspv2", 8);
    }
    EXPECT_EQ(gpu::cached_specialization(spirv_, features_), fresh);
    std::ifstream in(entry, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    EXPECT_EQ(std::string(magic, 8), "lancspv3") << "written back in the current format";
}

// The same for the entry of a compile: a FIFO or a link to one is a miss, not a wait.
TEST_F(SpirvCache, AFifoOrLinkAtACompilesEntryPathIsAMiss) {
    TwoFileTree files;
    const std::vector<std::uint32_t> fresh = gpu::compile_compute(files.tree(), "main.comp");
    gpu::cached_compile(files.tree(), {}, "main.comp");
    const fs::path entry = entries().at(0);
    fs::remove(entry);
    ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), fresh);
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(entry)));
    const std::string pipe = dir_ + "/pipe";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    fs::remove(entry);
    fs::create_symlink(pipe, entry);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), fresh);
}

TEST_F(SpirvCache, SwitchedOffItStillCompiles) {
    TwoFileTree files;
    ::setenv("LANCER_CACHE_DISABLE", "1", 1);
    EXPECT_EQ(gpu::cached_compile(files.tree(), {}, "main.comp"), gpu::compile_compute(files.tree(), "main.comp"));
    EXPECT_TRUE(entries().empty());
    ::unsetenv("LANCER_CACHE_DISABLE");
}

}  // namespace
}  // namespace lancer
