#include "gpu/spirv_cache.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "core/error.hpp"
#include "gpu/spirv_specialize.hpp"
#include "image/image.hpp"

namespace lancer::gpu {
namespace {

// An entry: this header, then the specialised module's words.
struct EntryHeader {
    char magic[8];                 // kMagic: also versions the entry format
    std::uint64_t input_hash;      // of the unspecialised module
    std::uint64_t features;        // one bit per LANCER_FEATURES flag, in table order
    std::uint64_t cleanup;         // the SpirvCleanup
    std::uint64_t words;           // the module's length
    std::uint64_t output_hash;     // of the module's words: a torn or damaged file does not match
};
constexpr char kMagic[8] = {'l', 'a', 'n', 'c', 's', 'p', 'v', '2'};

// Entries kept: editing shaders (lancer watch, view) makes a new one per edit, and each is
// 50-200 KiB; the least recently written go first.
constexpr std::size_t kMaxEntries = 256;

// FNV-1a over 64 bits: enough to tell modules apart, cheap next to the optimizer it saves.
std::uint64_t hash_words(const std::vector<std::uint32_t>& words) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::uint32_t w : words) {
        for (int b = 0; b < 4; ++b) {
            h ^= (w >> (8 * b)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    return h;
}

std::uint64_t feature_bits(const ShaderFeatures& features) {
    static_assert(std::size(kFeatures) <= 64);
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < std::size(kFeatures); ++i)
        if (features.*kFeatures[i].member) bits |= std::uint64_t{1} << i;
    return bits;
}

bool is_set(const char* name) {
    const char* v = std::getenv(name);
    return v && (std::strcmp(v, "1") == 0 || std::strcmp(v, "true") == 0);
}

std::optional<std::vector<std::uint32_t>> read_entry(const std::string& path, const EntryHeader& wanted) {
    std::ifstream in(path, std::ios::binary);
    EntryHeader header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return std::nullopt;
    if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.input_hash != wanted.input_hash ||
        header.features != wanted.features || header.cleanup != wanted.cleanup || header.words == 0 || header.words > (std::uint64_t{1} << 24))
        return std::nullopt;
    std::vector<std::uint32_t> words(header.words);
    if (!in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * sizeof(std::uint32_t))))
        return std::nullopt;
    if (hash_words(words) != header.output_hash) return std::nullopt;
    return words;
}

void evict_oldest(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::pair<fs::file_time_type, fs::path>> entries;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".spv") entries.emplace_back(e.last_write_time(ec), e.path());
    if (entries.size() <= kMaxEntries) return;
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i + kMaxEntries < entries.size(); ++i) fs::remove(entries[i].second, ec);
}

void write_entry(const std::string& path, EntryHeader header, const std::vector<std::uint32_t>& words) {
    header.words = words.size();
    header.output_hash = hash_words(words);
    std::vector<char> bytes(sizeof header + words.size() * sizeof(std::uint32_t));
    std::memcpy(bytes.data(), &header, sizeof header);
    std::memcpy(bytes.data() + sizeof header, words.data(), words.size() * sizeof(std::uint32_t));
    try {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        write_file_atomically(path, bytes.data(), bytes.size());
    } catch (const std::exception&) {
        // A read-only home or a full disk: the next run specialises again, nothing worse.
        return;
    }
    evict_oldest(std::filesystem::path(path).parent_path());
}

}  // namespace

std::optional<std::string> spirv_cache_directory() {
    if (is_set("LANCER_CACHE_DISABLE")) return std::nullopt;
    if (const char* dir = std::getenv("LANCER_CACHE_DIR"); dir && *dir) return std::string(dir);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/lancer";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/lancer";
    return std::nullopt;
}

std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup) {
    const std::optional<std::string> dir = spirv_cache_directory();
    if (!dir) return specialize_spirv(spirv, features, cleanup);
    EntryHeader key{};
    std::memcpy(key.magic, kMagic, sizeof kMagic);
    key.input_hash = hash_words(spirv);
    key.features = feature_bits(features);
    key.cleanup = static_cast<std::uint64_t>(cleanup);
    const std::string path =
        fmt::format("{}/tracer-{:016x}-{:016x}-{}.spv", *dir, key.input_hash, key.features, key.cleanup);
    if (std::optional<std::vector<std::uint32_t>> hit = read_entry(path, key)) return std::move(*hit);
    std::vector<std::uint32_t> specialized = specialize_spirv(spirv, features, cleanup);
    write_entry(path, key, specialized);
    return specialized;
}

}  // namespace lancer::gpu
