#include "gpu/shaders/spirv_cache.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <glslang/build_info.h>
#include <spirv-tools/libspirv.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_reading.hpp"
#include "gpu/shaders/spirv_specialize.hpp"
#include "image/image.hpp"

namespace lancer::gpu {
namespace cache_entry {
namespace {

// A specialisation's entry (all integers little-endian):
//   magic[8] | key[32] | words (u64) | checksum[32] | the module's words
// A compile's entry:
//   magic[8] | key[32] | manifest bytes (u64) | words (u64) | checksum[32] | manifest | words
// The key is the SHA-256 of every input (specialization_key, compile_key) and names the file;
// the checksum is the SHA-256 of every other byte of the entry, the key included, so an entry
// copied under another entry's name or key, torn or damaged, does not match. The magic versions
// the format: "lancspv2"/"lancgls1" (FNV-1a keys of 64 bits) are read as misses.
constexpr char kMagic[8] = {'l', 'a', 'n', 'c', 's', 'p', 'v', '3'};
constexpr char kCompiledMagic[8] = {'l', 'a', 'n', 'c', 'g', 'l', 's', '2'};
constexpr std::size_t kKeyAt = 8, kDigestBytes = 32;
constexpr std::size_t kWordsAt = kKeyAt + kDigestBytes, kChecksumAt = kWordsAt + 8, kPayloadAt = kChecksumAt + kDigestBytes;
constexpr std::size_t kCompiledManifestBytesAt = kKeyAt + kDigestBytes, kCompiledWordsAt = kCompiledManifestBytesAt + 8,
                      kCompiledChecksumAt = kCompiledWordsAt + 8, kCompiledPayloadAt = kCompiledChecksumAt + kDigestBytes;

void put_u64(std::string& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out += static_cast<char>(static_cast<unsigned char>(v >> (8 * i)));
}

std::uint64_t get_u64(std::string_view bytes, std::size_t at) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
    return v;
}

std::string_view digest_view(const Sha256Digest& d) { return {reinterpret_cast<const char*>(d.data()), d.size()}; }

// SHA-256 of the entry but for its checksum's own bytes.
Sha256Digest checksum_of(std::string_view bytes, std::size_t checksum_at) {
    Sha256 h;
    h.add(bytes.substr(0, checksum_at));
    h.add(bytes.substr(checksum_at + kDigestBytes));
    return h.finish();
}

bool checksum_holds(std::string_view bytes, std::size_t checksum_at) {
    return digest_view(checksum_of(bytes, checksum_at)) == bytes.substr(checksum_at, kDigestBytes);
}

std::vector<std::uint32_t> words_at(std::string_view bytes, std::size_t at, std::size_t count) {
    std::vector<std::uint32_t> words(count);
    std::memcpy(words.data(), bytes.data() + at, count * sizeof(std::uint32_t));
    return words;
}

std::string_view word_bytes(const std::vector<std::uint32_t>& words) {
    return {reinterpret_cast<const char*>(words.data()), words.size() * sizeof(std::uint32_t)};
}

// A manifest line's hash of a file's contents: SHA-256 in hex, "-" for a file not found.
std::string contents_hash(const std::optional<std::string>& contents) {
    return contents ? to_hex(sha256(*contents)) : "-";
}

}  // namespace

Sha256Digest specialization_key(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                SpirvCleanup cleanup) {
    Sha256 h;
    h.add_field("lancer tracer specialisation");
    h.add_field(spvSoftwareVersionDetailsString());
    h.add_field(word_bytes(spirv));
    h.add_u64(kFeatureCount);
    for (std::size_t i = 0; i < kFeatureCount; ++i) h.add_u64(feature_value(features, i));
    h.add_field(spirv_recipe(cleanup));
    h.add_u64(static_cast<std::uint64_t>(cleanup));
    return h.finish();
}

std::string encode_specialization(const Sha256Digest& key, const std::vector<std::uint32_t>& words) {
    std::string bytes(kMagic, sizeof kMagic);
    bytes += digest_view(key);
    put_u64(bytes, words.size());
    bytes.append(kDigestBytes, '\0');
    bytes += word_bytes(words);
    const Sha256Digest checksum = checksum_of(bytes, kChecksumAt);
    bytes.replace(kChecksumAt, kDigestBytes, digest_view(checksum));
    return bytes;
}

std::optional<std::vector<std::uint32_t>> parse_specialization(std::string_view bytes, const Sha256Digest& key) {
    if (bytes.size() < kPayloadAt || bytes.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic) ||
        bytes.substr(kKeyAt, kDigestBytes) != digest_view(key))
        return std::nullopt;
    const std::uint64_t words = get_u64(bytes, kWordsAt);
    if (words == 0 || words > kMaxEntryWords || bytes.size() != kPayloadAt + words * sizeof(std::uint32_t) ||
        !checksum_holds(bytes, kChecksumAt))
        return std::nullopt;
    return words_at(bytes, kPayloadAt, words);
}

Sha256Digest compile_key(const ShaderTree& tree, const ShaderFiles& generated, const std::string& entry,
                         const std::vector<ShaderDefine>& defines) {
    Sha256 h;
    h.add_field("lancer glslang compile");
    h.add_field(fmt::format("glslang {}.{}.{}{}", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH,
                            GLSLANG_VERSION_FLAVOR));
    h.add_field(entry);
    h.add_u64(defines.size());
    for (const ShaderDefine& d : defines) h.add_field(d.name).add_field(d.value);
    h.add_u64(generated.size());
    for (const auto& [name, contents] : generated) h.add_field(name).add_field(contents);
    const std::optional<std::string> text = tree(entry);
    h.add_u64(text.has_value());
    if (text) h.add_field(*text);
    return h.finish();
}

std::string encode_compiled(const Sha256Digest& key, const std::string& manifest, const std::vector<std::uint32_t>& words) {
    std::string bytes(kCompiledMagic, sizeof kCompiledMagic);
    bytes += digest_view(key);
    put_u64(bytes, manifest.size());
    put_u64(bytes, words.size());
    bytes.append(kDigestBytes, '\0');
    bytes += manifest;
    bytes += word_bytes(words);
    const Sha256Digest checksum = checksum_of(bytes, kCompiledChecksumAt);
    bytes.replace(kCompiledChecksumAt, kDigestBytes, digest_view(checksum));
    return bytes;
}

std::optional<std::vector<std::uint32_t>> parse_compiled(std::string_view bytes, const Sha256Digest& key,
                                                         const ShaderTree& tree) {
    if (bytes.size() < kCompiledPayloadAt ||
        bytes.substr(0, sizeof kCompiledMagic) != std::string_view(kCompiledMagic, sizeof kCompiledMagic) ||
        bytes.substr(kKeyAt, kDigestBytes) != digest_view(key))
        return std::nullopt;
    const std::uint64_t manifest_bytes = get_u64(bytes, kCompiledManifestBytesAt), words = get_u64(bytes, kCompiledWordsAt);
    if (manifest_bytes > kMaxManifestBytes || words == 0 || words > kMaxEntryWords ||
        bytes.size() != kCompiledPayloadAt + manifest_bytes + words * sizeof(std::uint32_t) ||
        !checksum_holds(bytes, kCompiledChecksumAt))
        return std::nullopt;
    // Every file the compile looked up must read as it did then. The names are the entry's, so
    // what they may cost is bounded: so many lines, each name once, so many bytes read in all.
    std::istringstream lines{std::string(bytes.substr(kCompiledPayloadAt, manifest_bytes))};
    std::set<std::string> names;
    std::size_t read = 0;
    for (std::string line; std::getline(lines, line);) {
        const std::size_t space = line.find(' ');
        if (space == std::string::npos || space + 1 == line.size() || names.size() == kMaxManifestLines ||
            !names.insert(line.substr(space + 1)).second)
            return std::nullopt;
        const std::optional<std::string> contents = tree(line.substr(space + 1));
        read += contents ? contents->size() : 0;
        if (read > kMaxManifestContentBytes || contents_hash(contents) != line.substr(0, space)) return std::nullopt;
    }
    return words_at(bytes, kCompiledPayloadAt + manifest_bytes, words);
}

std::optional<std::vector<std::uint32_t>> read_specialization(const std::string& path, const Sha256Digest& key) {
    const std::optional<std::string> bytes = read_regular_file_nonblocking(path, kMaxEntryBytes);
    return bytes ? parse_specialization(*bytes, key) : std::nullopt;
}

std::optional<std::vector<std::uint32_t>> read_compiled(const std::string& path, const Sha256Digest& key,
                                                        const ShaderTree& tree) {
    const std::optional<std::string> bytes = read_regular_file_nonblocking(path, kMaxEntryBytes);
    return bytes ? parse_compiled(*bytes, key, tree) : std::nullopt;
}

}  // namespace cache_entry

namespace {

// Entries kept: editing shaders (lancer watch, view) makes a new one per edit, and each is
// 50-200 KiB; the least recently written go first.
constexpr std::size_t kMaxEntries = 256;

bool is_set(const char* name) {
    const char* v = std::getenv(name);
    return v && (std::strcmp(v, "1") == 0 || std::strcmp(v, "true") == 0);
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

// Written to a temporary file and renamed into place: a reader sees the old entry or the new one,
// and whatever was at the path (a FIFO, a symbolic link: the link, not what it names) is replaced.
// A directory there is not: the entry is then a miss every time, nothing worse.
void write_bytes(const std::string& path, const std::string& bytes) {
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

std::vector<std::uint32_t> cached_compile(const ShaderTree& base, const ShaderFiles& generated,
                                          const std::string& entry, const std::vector<ShaderDefine>& defines,
                                          const std::string& display_root) {
    const ShaderTree tree = with_files(base, generated);
    const std::optional<std::string> dir = spirv_cache_directory();
    if (!dir) return compile_compute(tree, entry, defines, display_root);
    // The generated files and the entry point's text are in the key, so that each scene's code
    // and each edit of the entry point gets an entry of its own rather than replacing another's;
    // the files it includes are checked against the entry's manifest.
    const Sha256Digest key = cache_entry::compile_key(tree, generated, entry, defines);
    const std::string path = fmt::format("{}/glsl-{}.spv", *dir, to_hex(key));
    if (std::optional<std::vector<std::uint32_t>> hit = cache_entry::read_compiled(path, key, tree))
        return std::move(*hit);

    std::map<std::string, std::string> looked_up;
    const ShaderTree recording = [&tree, &looked_up](const std::string& name) {
        std::optional<std::string> contents = tree(name);
        looked_up[name] = cache_entry::contents_hash(contents);
        return contents;
    };
    std::vector<std::uint32_t> spirv = compile_compute(recording, entry, defines, display_root);
    std::string manifest;
    bool recordable = true;
    for (const auto& [name, hash] : looked_up) {
        recordable = recordable && !name.empty() && name.find('\n') == std::string::npos;
        manifest += hash + " " + name + "\n";
    }
    if (recordable && looked_up.size() <= cache_entry::kMaxManifestLines && manifest.size() <= cache_entry::kMaxManifestBytes)
        write_bytes(path, cache_entry::encode_compiled(key, manifest, spirv));
    return spirv;
}

std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup) {
    const std::optional<std::string> dir = spirv_cache_directory();
    if (!dir) return specialize_spirv(spirv, features, cleanup);
    const Sha256Digest key = cache_entry::specialization_key(spirv, features, cleanup);
    const std::string path = fmt::format("{}/tracer-{}.spv", *dir, to_hex(key));
    if (std::optional<std::vector<std::uint32_t>> hit = cache_entry::read_specialization(path, key))
        return std::move(*hit);
    std::vector<std::uint32_t> specialized = specialize_spirv(spirv, features, cleanup);
    write_bytes(path, cache_entry::encode_specialization(key, specialized));
    return specialized;
}

}  // namespace lancer::gpu
