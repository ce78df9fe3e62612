#pragma once
// Compiled and specialised tracer modules kept on disk between runs. Specialising the tracer
// with SPIRV-Tools (gpu/shaders/spirv_specialize) is most of lancer's start-up once Mesa's shader cache
// holds the driver's compile, and compiling it with glslang is most of the rest for a scene with
// expression surfaces (their generated code), yet both depend only on their inputs: a scene
// rendered again reuses them, as Mesa reuses its compile.
//
// The directory is $LANCER_CACHE_DIR, else $XDG_CACHE_HOME/lancer, else $HOME/.cache/lancer;
// LANCER_CACHE_DISABLE=1 (or true) turns the cache off. A missing, unwritable, damaged or
// foreign entry is never an error: it is specialised again (and written back if possible).
//
// The cache may be shared, and its files are not the user's input: an entry is named by the
// SHA-256 of all its inputs (a crafted scene cannot collide with another's entry), carries a
// SHA-256 checksum over its key and contents (another entry's module copied under this name is a
// miss), and is opened without waiting and read only when it is a regular file of bounded size
// (a FIFO or a link there is a miss, replaced by the fresh entry). The checksum is no signature:
// whoever may write the directory can write a matching entry, as with Mesa's shader cache.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/sha256.hpp"
#include "gpu/layout.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/shaders/spirv_specialize.hpp"

namespace lancer::gpu {

// Where entries go; nullopt when the cache is off or no directory can be named.
std::optional<std::string> spirv_cache_directory();

// compile_compute(with_files(base, generated), entry, defines, display_root), from the cache
// when an entry of the same compiler, generated files, entry point text and defines was compiled
// from files that all read the same today (every name the compile looked up: included files,
// and files it did not find). A compile that fails is not kept.
std::vector<std::uint32_t> cached_compile(const ShaderTree& base, const ShaderFiles& generated,
                                          const std::string& entry, const std::vector<ShaderDefine>& defines = {},
                                          const std::string& display_root = "");

// specialize_spirv(spirv, features, cleanup), from the cache when an entry matches all three exactly.
std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup = SpirvCleanup::dead_code);

// The entries' format, for the tests and the fuzz target fuzz_cache_entry. A parse returns the
// module of a well-formed entry for `key` whose checksum holds (and, for a compile, whose
// manifest's files read as they did); nullopt for anything else. A read opens `path` as
// read_regular_file_nonblocking does, then parses.
namespace cache_entry {
constexpr std::uint64_t kMaxEntryWords = std::uint64_t{1} << 24;   // 64 MiB of module
constexpr std::uint64_t kMaxManifestBytes = std::uint64_t{1} << 20;
constexpr std::size_t kMaxManifestLines = 4096;                       // far more names than a compile looks up
constexpr std::size_t kMaxManifestContentBytes = std::size_t{64} << 20;  // read to check a manifest
constexpr std::size_t kMaxEntryBytes = 128 + kMaxManifestBytes + kMaxEntryWords * 4;

Sha256Digest specialization_key(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                SpirvCleanup cleanup);
std::string encode_specialization(const Sha256Digest& key, const std::vector<std::uint32_t>& words);
std::optional<std::vector<std::uint32_t>> parse_specialization(std::string_view bytes, const Sha256Digest& key);
std::optional<std::vector<std::uint32_t>> read_specialization(const std::string& path, const Sha256Digest& key);

// The key reads the entry point's text from `tree` (generated files included).
Sha256Digest compile_key(const ShaderTree& tree, const ShaderFiles& generated, const std::string& entry,
                         const std::vector<ShaderDefine>& defines);
// `manifest`: a line "HASH NAME" per file the compile looked up, HASH the SHA-256 of its contents
// in hex, or "-" for a file not found.
std::string encode_compiled(const Sha256Digest& key, const std::string& manifest, const std::vector<std::uint32_t>& words);
std::optional<std::vector<std::uint32_t>> parse_compiled(std::string_view bytes, const Sha256Digest& key,
                                                         const ShaderTree& tree);
std::optional<std::vector<std::uint32_t>> read_compiled(const std::string& path, const Sha256Digest& key,
                                                        const ShaderTree& tree);
}  // namespace cache_entry

}  // namespace lancer::gpu
